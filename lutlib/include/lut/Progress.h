// SPDX-License-Identifier: Apache-2.0
#pragma once
// Progress and cancellation of long library calls that a program runs on a worker thread (the
// editor reading a large picture, writing its preview, comparing a LUT over a picture). The caller
// owns a Progress and passes its address with the call (a null pointer everywhere means none: the
// call runs as it always did); it may cancel it from any thread. The call reports the fraction
// done through the callback and checks for cancellation between pieces of work (a chunk of rows,
// a few thousand colours): once cancelled it throws CancelledError at its next check. Writes go
// through lut::AtomicFile, so a cancelled write leaves the old file as it was.
//
// A part of a longer task is a child Progress: its fractions 0..1 are [from, to] of its parent's,
// and it is cancelled when its parent is. report() and check() may be called from several
// threads at once (parallel loops); the callback must allow that.
#include "lut/Error.h"

#include <atomic>
#include <functional>
#include <string>

namespace lut {

// A call stopped because its Progress was cancelled. The program decides what that means (the
// editor: nothing to report; the work's partial results are dropped).
class CancelledError : public Error {
public:
    using Error::Error;
};

class Progress {
public:
    using Callback = std::function<void(double fraction)>;

    Progress() = default;
    explicit Progress(Callback callback) : m_callback(std::move(callback)) {}
    // A part of `parent`: fraction f here is from + f * (to - from) there.
    Progress(const Progress& parent, double from, double to)
        : m_parent(&parent), m_from(from), m_to(to) {}
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void cancel() noexcept { m_cancelled.store(true, std::memory_order_relaxed); }
    bool cancelled() const noexcept {
        return m_cancelled.load(std::memory_order_relaxed) || (m_parent && m_parent->cancelled());
    }
    // Reports the fraction done (clamped to [0, 1]; NaN is ignored).
    void report(double fraction) const;
    // Throws CancelledError("WHAT: cancelled") once cancelled.
    void check(const std::string& what) const;

private:
    const Progress* m_parent = nullptr;
    double m_from = 0.0, m_to = 1.0;
    Callback m_callback;
    std::atomic<bool> m_cancelled{false};
};

// The same for an optional Progress (null = none).
inline void reportProgress(const Progress* progress, double fraction) {
    if (progress)
        progress->report(fraction);
}
inline void checkCancelled(const Progress* progress, const std::string& what) {
    if (progress)
        progress->check(what);
}

} // namespace lut
