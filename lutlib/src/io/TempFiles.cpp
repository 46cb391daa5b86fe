// SPDX-License-Identifier: Apache-2.0
#include "lut/io/TempFiles.h"

#include "lut/os/Files.h"

#include <atomic>
#include <cstdint>
#include <cstring>

namespace lut {

namespace {

// Fixed slots of atomic pointers: registering, unregistering and the handler's walk never lock
// or allocate. A slot holds a heap copy of its path after one kind byte ('f' file, 'd' folder),
// so both are published by one atomic store; the handler only reads it.
struct Registry {
    static constexpr std::uint32_t kMagic = 0x6c75746bu; // "lutk": a matching layout
    static constexpr int kSlots = 512;
    std::uint32_t magic = kMagic;
    std::atomic<char*> paths[kSlots] = {};
    std::atomic<int> signal{0};
    // Walks in progress (the handler counts itself in before it reads any slot, out when done):
    // meanwhile unregistering leaks the path instead of freeing it, since the handler may hold
    // it. Afterwards paths are freed again (an interrupted batch goes on to finish its jobs).
    std::atomic<int> walking{0};
};

Registry g_own;
std::atomic<Registry*> g_registry{&g_own};

Registry& registry() noexcept {
    return *g_registry.load();
}

} // namespace

void removeTempFilesInFlight() noexcept {
    Registry& r = registry();
    r.walking.fetch_add(1);
    for (int pass = 0; pass < 2; ++pass) // files first, then the (now empty) folders
        for (int i = 0; i < Registry::kSlots; ++i) {
            const char* p = r.paths[i].load();
            if (!p || p[0] != (pass == 0 ? 'f' : 'd'))
                continue;
            if (pass == 0)
                os::removeFile(p + 1);
            else
                os::removeFolder(p + 1);
        }
    r.walking.fetch_sub(1);
}

void markInterrupted(int sig) noexcept {
    registry().signal.store(sig > 0 ? sig : 1);
}

bool interrupted() noexcept {
    return registry().signal.load() != 0;
}

int interruptSignal() noexcept {
    return registry().signal.load();
}

void throwIfInterrupted(const std::string& what) {
    if (interrupted())
        throw InterruptedError(what + ": interrupted");
}

TempPathRegistration::TempPathRegistration(const std::string& path, bool isFolder) {
    Registry& r = registry();
    char* copy = new char[path.size() + 2];
    copy[0] = isFolder ? 'd' : 'f';
    std::memcpy(copy + 1, path.c_str(), path.size() + 1);
    for (int i = 0; i < Registry::kSlots; ++i) {
        char* expected = nullptr;
        if (r.paths[i].load() == nullptr && r.paths[i].compare_exchange_strong(expected, copy)) {
            m_registry = &r;
            m_slot = i;
            return;
        }
    }
    // Every slot taken (hundreds of writes at once): the owner still removes its file; only a
    // signal would miss it.
    delete[] copy;
}

TempPathRegistration::~TempPathRegistration() {
    release();
}

TempPathRegistration::TempPathRegistration(TempPathRegistration&& other) noexcept
    : m_registry(other.m_registry), m_slot(other.m_slot) {
    other.m_slot = -1;
}

TempPathRegistration& TempPathRegistration::operator=(TempPathRegistration&& other) noexcept {
    if (this != &other) {
        release();
        m_registry = other.m_registry;
        m_slot = other.m_slot;
        other.m_slot = -1;
    }
    return *this;
}

void TempPathRegistration::release() noexcept {
    if (m_slot < 0)
        return;
    Registry& r = *static_cast<Registry*>(m_registry); // the one it was registered in
    char* p = r.paths[m_slot].exchange(nullptr);
    m_slot = -1;
    // Sequentially consistent: if a walk began before the exchange and may still hold the path,
    // we see `walking` and leave the path alive for it (a few bytes, only then).
    if (r.walking.load() == 0)
        delete[] p;
}

void* tempFileRegistry() noexcept {
    return g_registry.load();
}

void useTempFileRegistry(void* registry) noexcept {
    auto* r = static_cast<Registry*>(registry);
    if (r && r->magic == Registry::kMagic)
        g_registry.store(r);
}

} // namespace lut
