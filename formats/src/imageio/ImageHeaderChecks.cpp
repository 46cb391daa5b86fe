#include "imageio/ImageHeaderChecks.h"

#include "lut/Error.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lut::formats {

namespace {

constexpr std::size_t kHeaderWindow = std::size_t(1) << 20; // header bytes looked at

std::uint32_t u32(const unsigned char* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

// OpenEXR (openexr.com, "OpenEXR File Layout"): magic 76 2f 31 01, a version word (bit 12 =
// multi-part), then headers of attributes "name\0type\0" + int32 size + value, each header ended
// by an empty name (multi-part: the list of headers ended by one more).
void checkExr(const std::string& path, const std::vector<unsigned char>& b,
              std::uint64_t fileSize) {
    const bool multiPart = (u32(b.data() + 4) & 0x1000u) != 0;
    std::size_t at = 8;
    auto cString = [&](std::size_t& pos) -> bool { // false when it runs past what was read
        while (pos < b.size() && b[pos] != 0)
            ++pos;
        if (pos >= b.size())
            return false;
        ++pos;
        return true;
    };
    for (int header = 0; header < 1024; ++header) {
        if (at >= b.size())
            return;
        if (b[at] == 0) // an empty header name: end of the headers
            return;
        for (;;) {
            if (at >= b.size())
                return;
            if (b[at] == 0) { // end of this header
                ++at;
                break;
            }
            const std::size_t nameAt = at;
            if (!cString(at))
                return;
            const std::string name(reinterpret_cast<const char*>(b.data() + nameAt),
                                   at - nameAt - 1);
            if (!cString(at) || at + 4 > b.size())
                return;
            const auto size = static_cast<std::int32_t>(u32(b.data() + at));
            at += 4;
            const std::uint64_t left = fileSize > at ? fileSize - at : 0;
            if (size < 0 || static_cast<std::uint64_t>(size) > left)
                throw Error(path + ": OpenEXR header attribute '" + name + "' declares " +
                            std::to_string(size) + " bytes, but only " + std::to_string(left) +
                            " bytes follow in the file (truncated or corrupt)");
            at += static_cast<std::size_t>(size);
        }
        if (!multiPart)
            return;
    }
}

} // namespace

// DPX (SMPTE 268M): "SDPX" big-endian or "XPDS" little-endian; pixels per line at byte 772, lines
// per element at 776. OpenImageIO allocates the frame from them when it opens the file (a 2 KB
// file claiming 32704x32704 asked for 4.3 GB: found by fuzz_image_apply). No DPX stores less than
// one bit per pixel.
void checkDpx(const std::string& path, const std::vector<unsigned char>& b, std::uint64_t size) {
    if (b.size() < 780)
        return;
    const bool big = b[0] == 'S';
    auto u32 = [&](std::size_t at) {
        return big ? (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) |
                         (std::uint32_t(b[at + 2]) << 8) | b[at + 3]
                   : (std::uint32_t(b[at + 3]) << 24) | (std::uint32_t(b[at + 2]) << 16) |
                         (std::uint32_t(b[at + 1]) << 8) | b[at];
    };
    const std::uint64_t w = u32(772), h = u32(776);
    if (w * h > 8 * size)
        throw Error(path + ": DPX header declares " + std::to_string(w) + "x" + std::to_string(h) +
                    " pixels, more than the file's " + std::to_string(size) +
                    " bytes can hold (truncated or corrupt)");
}

void checkImageHeader(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0)
        return; // the reader says why it cannot open it
    struct stat st {};
    std::vector<unsigned char> b;
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
        b.resize(static_cast<std::size_t>(
            std::min<std::uint64_t>(static_cast<std::uint64_t>(st.st_size), kHeaderWindow)));
        std::size_t got = 0;
        while (got < b.size()) {
            const ssize_t n = ::pread(fd, b.data() + got, b.size() - got, static_cast<off_t>(got));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            got += static_cast<std::size_t>(n);
        }
        b.resize(got);
    }
    ::close(fd);
    static const unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
    if (b.size() >= 8 && std::memcmp(b.data(), kExrMagic, 4) == 0)
        checkExr(path, b, static_cast<std::uint64_t>(st.st_size));
    if (b.size() >= 4 &&
        (std::memcmp(b.data(), "SDPX", 4) == 0 || std::memcmp(b.data(), "XPDS", 4) == 0))
        checkDpx(path, b, static_cast<std::uint64_t>(st.st_size));
}

} // namespace lut::formats
