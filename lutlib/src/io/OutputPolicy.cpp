// SPDX-License-Identifier: Apache-2.0
#include "lut/io/OutputPolicy.h"

#include "lut/io/AtomicFile.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>

namespace fs = std::filesystem;

namespace lut {

OutputExistsError::OutputExistsError(const std::string& path)
    : Error(path + ": already exists (not replaced)"), m_path(path) {}

namespace {

bool underDevOrProc(const std::string& path) {
    std::error_code ec;
    const std::string abs = os::fromPath(fs::absolute(os::toPath(path), ec).lexically_normal());
    return abs.rfind("/dev/", 0) == 0 || abs.rfind("/proc/", 0) == 0;
}

std::string folderOf(const std::string& path) {
    const fs::path parent = os::toPath(path).parent_path();
    return parent.empty() ? std::string(".") : os::fromPath(parent);
}

std::string keyOf(const std::string& path) {
    std::error_code ec;
    return os::fromPath(fs::absolute(os::toPath(path), ec).lexically_normal());
}

std::mutex& exclusiveMutex() {
    static std::mutex m;
    return m;
}

std::set<std::string>& exclusiveOutputs() {
    static std::set<std::string> s;
    return s;
}

} // namespace

bool isExclusiveOutput(const std::string& path) {
    std::lock_guard<std::mutex> lock(exclusiveMutex());
    return exclusiveOutputs().count(keyOf(path)) > 0;
}

void forgetExclusiveOutput(const std::string& path) {
    std::lock_guard<std::mutex> lock(exclusiveMutex());
    exclusiveOutputs().erase(keyOf(path));
}

OutputTarget checkOutput(const std::string& path, ExistingOutput rule,
                         const std::vector<std::string>& inputs) {
    OutputTarget t;
    t.path = path;
    t.writePath = path;
    if (path.empty())
        throw Error("no output file named");
    if (isStdStream(path)) {
        t.kind = OutputKind::Stdout;
        return t;
    }
    if (os::isPathSeparator(path.back()))
        throw Error(path + ": is a folder name, not a file");
    for (const auto& in : inputs)
        if (!in.empty() && !isStdStream(in))
            checkNotSameFile(in, path);
    os::FileInfo st;
    if (const int err = os::fileInfo(path, st); err != 0) {
        if (err != ENOENT)
            throw Error(path + ": cannot write: " + std::strerror(err));
        os::FileInfo lst;
        if (os::linkInfo(path, lst) == 0) // a dangling symbolic link: never write through it
            throw Error(path + ": is a symbolic link to a missing file; not written");
        if (underDevOrProc(path))
            throw Error(path + ": no such device");
        const std::string dir = folderOf(path);
        if (!os::isDirectory(dir))
            throw Error(path + ": folder " + dir + " does not exist");
        t.kind = OutputKind::NewFile;
        if (rule != ExistingOutput::Replace) {
            std::lock_guard<std::mutex> lock(exclusiveMutex());
            exclusiveOutputs().insert(keyOf(path));
        }
        return t;
    }
    if (st.type == os::FileType::Directory)
        throw Error(path + ": is a folder, not a file");
    if (st.type != os::FileType::Regular || underDevOrProc(path)) {
        t.kind = OutputKind::Special;
        return t;
    }
    if (rule == ExistingOutput::Refuse)
        throw OutputExistsError(path);
    t.kind = OutputKind::ExistingFile;
    t.skip = rule == ExistingOutput::Skip;
    os::FileInfo lst;
    if (os::linkInfo(path, lst) == 0 && lst.type == os::FileType::SymbolicLink) {
        if (std::string real = os::realPath(path); !real.empty())
            t.writePath = real; // replace the file the link names; the link stays
    }
    return t;
}

OutputTarget memoryOutput(const std::string& name, std::string& bytes) {
    OutputTarget t;
    t.path = name;
    t.writePath = name;
    t.kind = OutputKind::Memory;
    t.memory = &bytes;
    return t;
}

} // namespace lut
