// SPDX-License-Identifier: Apache-2.0
#include "FullDisk.h"

#include "TestPaths.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sched.h>
#include <sys/mount.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lut::robust {

namespace {

constexpr const char* kFiller = ".filler";

bool writeAll(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    return static_cast<bool>(out);
}

// Enters a private mount namespace once per process: a mount made there is invisible to the
// rest of the system and goes away with the process. Returns "" or why it is impossible.
const std::string& enterPrivateMounts() {
    static const std::string why = []() -> std::string {
        const uid_t uid = ::getuid();
        const gid_t gid = ::getgid();
        if (::unshare(CLONE_NEWNS) != 0) {
            const std::string asRoot = std::strerror(errno);
            // Not allowed to mount here: a user namespace of our own (single-threaded only).
            if (::unshare(CLONE_NEWUSER | CLONE_NEWNS) != 0)
                return "unshare(CLONE_NEWNS): " + asRoot +
                       "; unshare(CLONE_NEWUSER): " + std::strerror(errno);
            writeAll("/proc/self/setgroups", "deny");
            writeAll("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1");
            writeAll("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1");
        }
        if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
            return std::string("making / private: ") + std::strerror(errno);
        return {};
    }();
    return why;
}

} // namespace

FullDisk::FullDisk(std::string dir) : m_dir(std::move(dir)) {
    fs::create_directories(m_dir);
    const char* force = std::getenv("LUTKIT_TEST_FULL_DISK");
    const bool shimOnly = force && std::string(force) == "shim";
    if (!shimOnly) {
        m_why = enterPrivateMounts();
        if (m_why.empty()) {
            if (::mount("tmpfs", m_dir.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=1m") == 0) {
                m_kind = Kind::Tmpfs;
                return;
            }
            m_why = std::string("mount -t tmpfs: ") + std::strerror(errno);
        }
    }
#ifdef LUTKIT_FAULT_SHIM
    if (fs::exists(LUTKIT_FAULT_SHIM)) {
        m_kind = Kind::Shim;
        return;
    }
    m_why += (m_why.empty() ? "" : "; ") + std::string("no shim at ") + LUTKIT_FAULT_SHIM;
#else
    m_why += (m_why.empty() ? "" : "; ") + std::string("the fault shim was not built");
#endif
}

FullDisk::~FullDisk() {
    if (m_kind == Kind::Tmpfs)
        ::umount2(m_dir.c_str(), MNT_DETACH);
}

const char* FullDisk::kindName() const {
    return m_kind == Kind::Tmpfs ? "tmpfs" : m_kind == Kind::Shim ? "LD_PRELOAD shim" : "none";
}

void FullDisk::fill(int freeKiB) {
    if (m_kind == Kind::Shim) {
        m_shimBytes = static_cast<long long>(freeKiB) * 1024;
        return;
    }
    if (m_kind != Kind::Tmpfs)
        return;
    // A pad keeps freeKiB free while the filler takes everything else; then the pad goes.
    const std::string pad = m_dir + "/.pad";
    writeBytes(pad, std::string(static_cast<std::size_t>(freeKiB) * 1024, 'p'));
    const int fd = ::open((m_dir + "/" + kFiller).c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const std::string chunk(4096, 'f');
    while (::write(fd, chunk.data(), chunk.size()) > 0) {
    }
    ::close(fd);
    fs::remove(pad);
}

lut::test::RunResult FullDisk::run(const std::string& args) const {
    if (m_kind != Kind::Shim)
        return lut::test::runCli(args);
#ifdef LUTKIT_FAULT_SHIM
    ::setenv("LD_PRELOAD", LUTKIT_FAULT_SHIM, 1);
    ::setenv("LUTKIT_ENOSPC_DIR", fs::canonical(m_dir).c_str(), 1);
    ::setenv("LUTKIT_ENOSPC_BYTES", std::to_string(m_shimBytes).c_str(), 1);
    // A sanitizer build of lutkit accepts a library preloaded before its runtime.
    const char* asan = std::getenv("ASAN_OPTIONS");
    const std::string asanBefore = asan ? asan : "";
    ::setenv("ASAN_OPTIONS", (asanBefore + ":verify_asan_link_order=0").c_str(), 1);
#endif
    auto r = lut::test::runCli(args);
#ifdef LUTKIT_FAULT_SHIM
    if (asanBefore.empty())
        ::unsetenv("ASAN_OPTIONS");
    else
        ::setenv("ASAN_OPTIONS", asanBefore.c_str(), 1);
#endif
    ::unsetenv("LD_PRELOAD");
    ::unsetenv("LUTKIT_ENOSPC_DIR");
    ::unsetenv("LUTKIT_ENOSPC_BYTES");
    return r;
}

std::vector<std::string> FullDisk::listing() const {
    auto names = listDir(m_dir);
    names.erase(std::remove(names.begin(), names.end(), kFiller), names.end());
    return names;
}

} // namespace lut::robust
