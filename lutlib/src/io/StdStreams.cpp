// SPDX-License-Identifier: Apache-2.0
#include "lut/io/StdStreams.h"

#include "lut/io/MemoryLimit.h"
#include "lut/os/Files.h"

#include <algorithm>

#include <cerrno>
#include <cstring>

namespace lut {

std::string readStandardInput(std::size_t maxBytes) {
    return readStandardInput(maxBytes, {});
}

std::string readStandardInput(std::size_t maxBytes,
                              const std::function<StreamBound(const std::string& head)>& bound) {
    std::string bytes;
    char buf[1 << 16];
    // The memory limit (--max-memory) holds standard input too.
    const std::uint64_t memory = memoryLimit();
    std::uint64_t limit = std::min<std::uint64_t>(maxBytes, memory);
    std::string why = limit < maxBytes ? "of the memory limit (--max-memory)" : "";
    bool judged = !bound;
    auto over = [&] {
        throw LimitError(
            why.empty()
                ? "-: standard input is over the limit of " + std::to_string(limit) + " bytes"
                : "-: standard input is over the " + std::to_string(limit) + " bytes " + why);
    };
    auto judge = [&] {
        judged = true;
        const StreamBound b = bound(bytes);
        if (b.bytes > 0 && b.bytes < limit) {
            limit = b.bytes;
            why = b.what;
        }
    };
    for (;;) {
        const std::ptrdiff_t n = os::readBytes(0, buf, sizeof buf); // standard input
        if (n < 0) {
            if (errno == EINTR)
                continue;
            throw IoError(std::string("-: cannot read standard input: ") + std::strerror(errno));
        }
        if (n == 0)
            break;
        if (bytes.size() + static_cast<std::size_t>(n) > limit)
            over();
        bytes.append(buf, static_cast<std::size_t>(n));
        if (!judged && bytes.size() >= kStreamHeadBytes)
            judge();
    }
    if (bytes.empty())
        throw Error("-: standard input is empty");
    if (!judged)
        judge();
    if (bytes.size() > limit)
        over();
    return bytes;
}

} // namespace lut
