// SPDX-License-Identifier: Apache-2.0
#pragma once
// A full disk for the "nothing lost" tests (issue 17): a small tmpfs mounted in a private mount
// namespace of the test process (as root, or through a user namespace), so lutkit writes into a
// real file system that runs out of space. Where no mount is possible, writes under the folder
// fail with ENOSPC through an LD_PRELOAD shim (tests/robust/shim) instead; set
// LUTKIT_TEST_FULL_DISK=shim to force the shim.
#include "RobustSupport.h"

#include <string>
#include <vector>

namespace lut::robust {

class FullDisk {
public:
    enum class Kind { Tmpfs, Shim, None };

    // Makes dir (created if missing) a small empty file system.
    explicit FullDisk(std::string dir);
    ~FullDisk();
    FullDisk(const FullDisk&) = delete;
    FullDisk& operator=(const FullDisk&) = delete;

    Kind kind() const { return m_kind; }
    const char* kindName() const;
    const std::string& whyNone() const { return m_why; } // for the skip message
    const std::string& dir() const { return m_dir; }

    // Fills the disk so that only freeKiB KiB can still be written (call after placing the files
    // that must be there).
    void fill(int freeKiB);
    // Runs lutkit (the shim preloaded when kind() is Shim).
    lut::test::RunResult run(const std::string& args) const;
    // The folder's names, hidden ones included, without the filler.
    std::vector<std::string> listing() const;

private:
    std::string m_dir;
    Kind m_kind = Kind::None;
    std::string m_why;
    long long m_shimBytes = 0;
};

} // namespace lut::robust
