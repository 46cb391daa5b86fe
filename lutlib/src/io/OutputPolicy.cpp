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
            throw IoError(path + ": cannot write: " + std::strerror(err));
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

namespace {

// What sameFile compares, taken once per output: the path made canonical, and the file's device
// and inode when it exists (standard output's for "-"). Comparing these keeps the claim of many
// outputs free of system calls (atlas split of 8192 rows made 33 million of them).
struct ClaimKey {
    std::string path, inode;
};
ClaimKey claimKey(const std::string& path) {
    ClaimKey k;
    os::FileInfo st;
    if ((path == "-" ? os::openFileInfo(1, st) : os::fileInfo(path, st)) == 0)
        k.inode = std::to_string(st.device) + ":" + std::to_string(st.inode);
    std::error_code ec;
    const std::filesystem::path p = path == "-"
                                        ? std::filesystem::path()
                                        : std::filesystem::weakly_canonical(os::toPath(path), ec);
    k.path = path == "-" || ec ? "=" + path : os::fromPath(p);
    return k;
}

} // namespace

OutputTarget CommandOutputs::claim(const std::string& path, ExistingOutput rule,
                                   const std::vector<std::string>& inputs) {
    // Each entry: the canonical path, the inode key, the path as named, NUL between them.
    const ClaimKey key = claimKey(path);
    for (const std::string& entry : m_claimed) {
        const std::size_t a = entry.find('\0'), b = entry.find('\0', a + 1);
        const bool same = entry.compare(0, a, key.path) == 0 && a == key.path.size();
        const bool sameInode = !key.inode.empty() && b - a - 1 == key.inode.size() &&
                               entry.compare(a + 1, b - a - 1, key.inode) == 0;
        if (same || sameInode) {
            const std::string other = entry.substr(b + 1);
            throw Error(path + ": is also another output of this command" +
                        (other == path ? std::string() : " (" + other + ")") +
                        "; name another file");
        }
    }
    OutputTarget t = checkOutput(path, rule, inputs);
    m_claimed.push_back(key.path + '\0' + key.inode + '\0' + path);
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
