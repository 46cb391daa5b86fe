// SPDX-License-Identifier: Apache-2.0
#include "lut/io/OutputPolicy.h"

#include "lut/io/AtomicFile.h"
#include "lut/io/ProtectInputs.h"
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
        // The shell may have pointed standard output at an input (`-o - 1<> lut.png`): a
        // regular file that is an input is refused like any output that is an input.
        os::FileInfo out;
        if (os::openFileInfo(1, out) == 0 && out.type == os::FileType::Regular)
            for (const auto& in : inputs) {
                os::FileInfo st;
                if (!in.empty() && !isStdStream(in) && os::fileInfo(in, st) == 0 &&
                    st.device == out.device && st.inode == out.inode)
                    throw Error("-: standard output is the same file as input " + in +
                                "; refusing to overwrite it");
            }
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

OutputTarget CommandOutputs::claim(const std::string& path, ExistingOutput rule,
                                   const std::vector<std::string>& inputs) {
    for (const std::string& other : m_claimed)
        if (sameFile(path, other))
            throw Error(path + ": is also another output of this command" +
                        (other == path ? std::string() : " (" + other + ")") +
                        "; name another file");
    OutputTarget t = checkOutput(path, rule, inputs);
    m_claimed.push_back(path);
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
