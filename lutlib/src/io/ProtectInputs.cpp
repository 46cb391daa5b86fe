// SPDX-License-Identifier: Apache-2.0
#include "lut/io/ProtectInputs.h"

#include "lut/Error.h"
#include "lut/os/Files.h"
#include "lut/os/Paths.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace lut {

void checkNotOverwritingInputs(const std::string& output, const std::vector<std::string>& inputs) {
    os::FileInfo out;
    const bool outExists = !output.empty() && os::fileInfo(output, out) == 0;
    for (const std::string& input : inputs) {
        if (input.empty() || input == "-")
            continue;
        os::FileInfo in;
        if (outExists && os::fileInfo(input, in) == 0) {
            // One file whatever the names: same device and inode (hard links, symbolic links,
            // linked folders, any spelling of the path).
            if (in.device == out.device && in.inode == out.inode)
                throw Error(output + ": output is the same file as input " + input +
                            " (same path or a link to it); refusing to overwrite it");
            continue;
        }
        // One of them does not exist yet: only the same path spelled differently can match.
        std::error_code e1, e2;
        const fs::path a = fs::weakly_canonical(os::toPath(input), e1),
                       b = fs::weakly_canonical(os::toPath(output), e2);
        if (!e1 && !e2 && a == b)
            throw Error(output + ": output is the same file as input " + input +
                        "; refusing to overwrite it");
    }
}

void checkNotSameFile(const std::string& input, const std::string& output) {
    checkNotOverwritingInputs(output, {input});
}

namespace {

bool statOf(const std::string& path, os::FileInfo& st) {
    return path == "-" ? os::openFileInfo(1, st) == 0 : os::fileInfo(path, st) == 0;
}

} // namespace

bool sameFile(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty())
        return false;
    if (a == b)
        return true;
    os::FileInfo sa, sb;
    if (statOf(a, sa) && statOf(b, sb))
        return sa.device == sb.device && sa.inode == sb.inode;
    if (a == "-" || b == "-")
        return false;
    std::error_code e1, e2;
    const fs::path pa = fs::weakly_canonical(os::toPath(a), e1),
                   pb = fs::weakly_canonical(os::toPath(b), e2);
    return !e1 && !e2 && pa == pb;
}

} // namespace lut
