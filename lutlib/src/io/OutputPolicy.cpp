// SPDX-License-Identifier: Apache-2.0
#include "lut/io/OutputPolicy.h"

#include "lut/io/AtomicFile.h"
#include "lut/io/ProtectInputs.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lut {

OutputExistsError::OutputExistsError(const std::string& path)
    : Error(path + ": already exists (not replaced)"), m_path(path) {}

namespace {

bool underDevOrProc(const std::string& path) {
    std::error_code ec;
    const std::string abs = fs::absolute(path, ec).lexically_normal().string();
    return abs.rfind("/dev/", 0) == 0 || abs.rfind("/proc/", 0) == 0;
}

std::string folderOf(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

std::string keyOf(const std::string& path) {
    std::error_code ec;
    return fs::absolute(path, ec).lexically_normal().string();
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
        struct stat out {};
        if (::fstat(STDOUT_FILENO, &out) == 0 && S_ISREG(out.st_mode))
            for (const auto& in : inputs) {
                struct stat st {};
                if (!in.empty() && !isStdStream(in) && ::stat(in.c_str(), &st) == 0 &&
                    st.st_dev == out.st_dev && st.st_ino == out.st_ino)
                    throw Error("-: standard output is the same file as input " + in +
                                "; refusing to overwrite it");
            }
        t.kind = OutputKind::Stdout;
        return t;
    }
    if (path.back() == '/')
        throw Error(path + ": is a folder name, not a file");
    for (const auto& in : inputs)
        if (!in.empty() && !isStdStream(in))
            checkNotSameFile(in, path);
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        const int err = errno;
        if (err != ENOENT)
            throw Error(path + ": cannot write: " + std::strerror(err));
        struct stat lst {};
        if (::lstat(path.c_str(), &lst) == 0) // a dangling symbolic link: never write through it
            throw Error(path + ": is a symbolic link to a missing file; not written");
        if (underDevOrProc(path))
            throw Error(path + ": no such device");
        const std::string dir = folderOf(path);
        struct stat dst {};
        if (::stat(dir.c_str(), &dst) != 0 || !S_ISDIR(dst.st_mode))
            throw Error(path + ": folder " + dir + " does not exist");
        t.kind = OutputKind::NewFile;
        if (rule != ExistingOutput::Replace) {
            std::lock_guard<std::mutex> lock(exclusiveMutex());
            exclusiveOutputs().insert(keyOf(path));
        }
        return t;
    }
    if (S_ISDIR(st.st_mode))
        throw Error(path + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode) || underDevOrProc(path)) {
        t.kind = OutputKind::Special;
        return t;
    }
    if (rule == ExistingOutput::Refuse)
        throw OutputExistsError(path);
    t.kind = OutputKind::ExistingFile;
    t.skip = rule == ExistingOutput::Skip;
    struct stat lst {};
    if (::lstat(path.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode)) {
        char buf[PATH_MAX];
        if (::realpath(path.c_str(), buf))
            t.writePath = buf; // replace the file the link names; the link stays
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
