// SPDX-License-Identifier: Apache-2.0
// lutkit: the command-line front end. Everything lives in the lutkit_cli library
// (CommandLine.h: the subcommands of commands/, help, errors and exit codes).
#include "CommandLine.h"
#include "OutOfMemory.h"

#include "lut/os/Memory.h"

#include <cstdlib>
#include <new>

int main(int argc, char** argv) {
    return lut::cli::CommandLine().run(argc, argv);
}

// lutkit's operator new: malloc, and on failure the size asked for is noted (OutOfMemory.h) so
// "out of memory" can say how much. Sanitizer builds keep their runtime's own.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LUTKIT_OWN_OPERATOR_NEW 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
#define LUTKIT_OWN_OPERATOR_NEW 0
#endif
#endif
#ifndef LUTKIT_OWN_OPERATOR_NEW
#define LUTKIT_OWN_OPERATOR_NEW 1
#endif

#if LUTKIT_OWN_OPERATOR_NEW
namespace {

void* allocate(std::size_t n, std::size_t align) {
    if (n == 0)
        n = 1;
    for (;;) {
        void* p = nullptr;
        if (align <= alignof(std::max_align_t))
            p = std::malloc(n);
        else
            p = lut::os::allocateAligned(n, align);
        if (p)
            return p;
        if (std::new_handler handler = std::get_new_handler()) {
            handler();
            continue;
        }
        lut::cli::noteFailedAllocation(n);
        throw std::bad_alloc();
    }
}

void* allocateNoThrow(std::size_t n, std::size_t align) noexcept {
    try {
        return allocate(n, align);
    } catch (...) {
        return nullptr;
    }
}

constexpr std::size_t kPlain = alignof(std::max_align_t);

// What allocate() took from malloc goes back to free, the rest to its aligned allocator.
void deallocate(void* p, std::size_t align) noexcept {
    if (align <= kPlain)
        std::free(p);
    else
        lut::os::freeAligned(p);
}

} // namespace

// clang-format off
void* operator new(std::size_t n) { return allocate(n, kPlain); }
void* operator new[](std::size_t n) { return allocate(n, kPlain); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocateNoThrow(n, kPlain); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocateNoThrow(n, kPlain); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return allocateNoThrow(n, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept { return allocateNoThrow(n, static_cast<std::size_t>(a)); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete[](void* p, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete(void* p, std::size_t, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete[](void* p, std::size_t, std::align_val_t a) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t a, const std::nothrow_t&) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
void operator delete[](void* p, std::align_val_t a, const std::nothrow_t&) noexcept { deallocate(p, static_cast<std::size_t>(a)); }
// clang-format on
#endif
