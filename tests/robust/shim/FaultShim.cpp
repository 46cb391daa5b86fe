// SPDX-License-Identifier: Apache-2.0
// LD_PRELOAD shim that injects the faults the robustness tests need where the real thing cannot
// be arranged:
//  - a full disk (where no small file system can be mounted): writes to files under
//    $LUTKIT_ENOSPC_DIR fail with ENOSPC once $LUTKIT_ENOSPC_BYTES bytes (over the whole process)
//    went there. Covers the calls the writers use: write, pwrite, writev (our own writes,
//    libtiff, libstdc++ streams for OpenEXR) and fwrite, fputs, fputc (libpng, BMP, TGA, JPEG,
//    DPX through stdio);
//  - too little memory: malloc returns null for any request over $LUTKIT_FAIL_MALLOC_ABOVE bytes,
//    whatever the machine has.
// Everything else passes through untouched.
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

namespace {

std::atomic<long long> g_used{0};

template <class Fn> Fn real(const char* name) {
    return reinterpret_cast<Fn>(::dlsym(RTLD_NEXT, name));
}

// Whether fd is a file under the watched folder.
bool watched(int fd) {
    const char* dir = std::getenv("LUTKIT_ENOSPC_DIR");
    if (!dir || !*dir || fd < 0)
        return false;
    char link[64], target[PATH_MAX];
    std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t n = ::readlink(link, target, sizeof target - 1);
    if (n <= 0)
        return false;
    target[n] = '\0';
    const std::size_t len = std::strlen(dir);
    return std::strncmp(target, dir, len) == 0 && (target[len] == '/' || target[len] == '\0');
}

// How many of `want` bytes may still go to the watched folder (claims them).
std::size_t allowance(std::size_t want) {
    const char* limit = std::getenv("LUTKIT_ENOSPC_BYTES");
    const long long cap = limit ? std::atoll(limit) : 0;
    long long used = g_used.load();
    for (;;) {
        const long long left = cap > used ? cap - used : 0;
        const long long take =
            static_cast<long long>(want) < left ? static_cast<long long>(want) : left;
        if (g_used.compare_exchange_weak(used, used + take))
            return static_cast<std::size_t>(take);
    }
}

} // namespace

extern "C" {

void* __libc_malloc(size_t size); // glibc's own, so the shim needs no dlsym (which allocates)

void* malloc(size_t size) {
    static const long long cap = [] {
        const char* v = std::getenv("LUTKIT_FAIL_MALLOC_ABOVE");
        return v ? std::atoll(v) : 0LL;
    }();
    if (cap > 0 && static_cast<long long>(size) > cap) {
        errno = ENOMEM;
        return nullptr;
    }
    return __libc_malloc(size);
}

ssize_t write(int fd, const void* buf, size_t count) {
    static auto next = real<ssize_t (*)(int, const void*, size_t)>("write");
    if (count == 0 || !watched(fd))
        return next(fd, buf, count);
    const std::size_t ok = allowance(count);
    if (ok == 0) {
        errno = ENOSPC;
        return -1;
    }
    return next(fd, buf, ok);
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
    static auto next = real<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite");
    if (count == 0 || !watched(fd))
        return next(fd, buf, count, offset);
    const std::size_t ok = allowance(count);
    if (ok == 0) {
        errno = ENOSPC;
        return -1;
    }
    return next(fd, buf, ok, offset);
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off_t offset) {
    return pwrite(fd, buf, count, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int iovcnt) {
    static auto next = real<ssize_t (*)(int, const struct iovec*, int)>("writev");
    if (!watched(fd))
        return next(fd, iov, iovcnt);
    ssize_t total = 0;
    for (int i = 0; i < iovcnt; ++i) {
        const ssize_t n = write(fd, iov[i].iov_base, iov[i].iov_len);
        if (n < 0)
            return total > 0 ? total : -1;
        total += n;
        if (static_cast<size_t>(n) < iov[i].iov_len)
            break;
    }
    return total;
}

size_t fwrite(const void* ptr, size_t size, size_t nmemb, FILE* stream) {
    static auto next = real<size_t (*)(const void*, size_t, size_t, FILE*)>("fwrite");
    if (size == 0 || nmemb == 0 || !watched(::fileno(stream)))
        return next(ptr, size, nmemb, stream);
    const std::size_t items = allowance(size * nmemb) / size;
    const size_t done = items ? next(ptr, size, items, stream) : 0;
    if (done < nmemb)
        errno = ENOSPC;
    return done;
}

int fputs(const char* s, FILE* stream) {
    const size_t n = std::strlen(s);
    return fwrite(s, 1, n, stream) == n ? 1 : EOF;
}

int fputc(int c, FILE* stream) {
    const unsigned char ch = static_cast<unsigned char>(c);
    return fwrite(&ch, 1, 1, stream) == 1 ? c : EOF;
}

} // extern "C"
