// The running program's folder; see lut/io/FileNames.h (extensionOf is in Format.cpp).
#include "lut/io/FileNames.h"

#include <unistd.h>

#include <vector>

namespace lut {

std::string executableDir() {
    std::vector<char> buf(4096);
    const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0)
        return {};
    std::string p(buf.data(), static_cast<std::size_t>(n));
    const auto slash = p.find_last_of('/');
    return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

} // namespace lut
