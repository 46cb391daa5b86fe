// SPDX-License-Identifier: Apache-2.0
#include "lut/io/ProtectInputs.h"

#include "lut/Error.h"

#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace lut {

void checkNotOverwritingInputs(const std::string& output, const std::vector<std::string>& inputs) {
    struct stat out {};
    const bool outExists = !output.empty() && ::stat(output.c_str(), &out) == 0;
    for (const std::string& input : inputs) {
        if (input.empty() || input == "-")
            continue;
        struct stat in {};
        if (outExists && ::stat(input.c_str(), &in) == 0) {
            // One file whatever the names: same device and inode (hard links, symbolic links,
            // linked folders, any spelling of the path).
            if (in.st_dev == out.st_dev && in.st_ino == out.st_ino)
                throw Error(output + ": output is the same file as input " + input +
                            " (same path or a link to it); refusing to overwrite it");
            continue;
        }
        // One of them does not exist yet: only the same path spelled differently can match.
        std::error_code e1, e2;
        const fs::path a = fs::weakly_canonical(input, e1), b = fs::weakly_canonical(output, e2);
        if (!e1 && !e2 && a == b)
            throw Error(output + ": output is the same file as input " + input +
                        "; refusing to overwrite it");
    }
}

void checkNotSameFile(const std::string& input, const std::string& output) {
    checkNotOverwritingInputs(output, {input});
}

namespace {

bool statOf(const std::string& path, struct stat& st) {
    return path == "-" ? ::fstat(STDOUT_FILENO, &st) == 0 : ::stat(path.c_str(), &st) == 0;
}

} // namespace

bool sameFile(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty())
        return false;
    if (a == b)
        return true;
    struct stat sa {
    }, sb{};
    if (statOf(a, sa) && statOf(b, sb))
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (a == "-" || b == "-")
        return false;
    std::error_code e1, e2;
    const fs::path pa = fs::weakly_canonical(a, e1), pb = fs::weakly_canonical(b, e2);
    return !e1 && !e2 && pa == pb;
}

} // namespace lut
