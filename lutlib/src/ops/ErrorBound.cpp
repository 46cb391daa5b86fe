// SPDX-License-Identifier: Apache-2.0
// The held-out bound of a lattice approximation's error; see lut/ops/ErrorBound.h.
#include "lut/ops/ErrorBound.h"

#include "lut/Math.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

namespace lut {

namespace {

using Slopes = std::array<float, 9>; // [axis * 3 + channel], change per unit of input

// A box of the grid: the difference at its centre, the slopes around it and what they allow
// inside it. Boxes whose bound is above the largest difference seen are refined afterwards.
struct Box {
    glm::dvec3 centre{0.0}, half{0.0};
    glm::dvec3 e{0.0};
    Slopes slope{};
    double bound = 0.0; // max over channels of |e| + sum over axes of slope * half
};

double boxBound(const Box& b) {
    double bound = -INFINITY;
    for (int c = 0; c < 3; ++c) {
        if (std::isnan(b.e[c]))
            continue;
        double term = 0.0;
        for (int a = 0; a < 3; ++a)
            term += double(b.slope[static_cast<std::size_t>(3 * a + c)]) * b.half[a];
        bound = std::max(bound, std::fabs(b.e[c]) + term);
    }
    return bound;
}

// A total order (equal bounds ordered by the box's place): the heap then gives its boxes in one
// order whatever the standard library's heap algorithm (libstdc++ natively and on Windows, libc++
// in the browser edition took equal bounds in other orders, so the refinement's budget ran out
// on other boxes: convert --size 65 printed 3.58e-07 natively, 3.88e-07 in the browser).
struct ByBoundDescending {
    bool operator()(const Box& a, const Box& b) const {
        if (a.bound != b.bound)
            return a.bound < b.bound;
        for (int i = 0; i < 3; ++i) {
            if (a.centre[i] != b.centre[i])
                return a.centre[i] < b.centre[i];
            if (a.half[i] != b.half[i])
                return a.half[i] < b.half[i];
        }
        return false;
    }
};

// Within 1% of the largest difference seen a bound is tight enough (the refinement stops there).
constexpr double kRelativeTolerance = 0.01;
constexpr double kAbsoluteTolerance = 1e-9;
double tightEnough(double seen) {
    return seen * (1.0 + kRelativeTolerance) + kAbsoluteTolerance;
}

// At most this many boxes are refined (the largest bounds); the others count as they are.
constexpr std::size_t kKeptBoxes = 65536;

// What one thread gathers.
struct Tally {
    double seen = 0.0, sum = 0.0;
    std::size_t count = 0;
    std::vector<Box> boxes; // bounds above what was seen when they were measured
    double settled = 0.0;   // the largest bound of the boxes not kept

    void add(double e) {
        if (std::isnan(e))
            return;
        const double a = std::fabs(e);
        seen = std::max(seen, a);
        sum += a;
        ++count;
    }
    void keep(Box b) {
        b.bound = boxBound(b);
        double largest = 0.0;
        for (int c = 0; c < 3; ++c)
            if (!std::isnan(b.e[c]))
                largest = std::max(largest, std::fabs(b.e[c]));
        // a bound close enough to a difference that occurs needs no refining
        if (b.bound > largest && b.bound > tightEnough(seen))
            boxes.push_back(std::move(b));
        else
            settled = std::max(settled, b.bound);
    }
    void merge(Tally&& o) {
        seen = std::max(seen, o.seen);
        sum += o.sum;
        count += o.count;
        settled = std::max(settled, o.settled);
        boxes.insert(boxes.end(), std::make_move_iterator(o.boxes.begin()),
                     std::make_move_iterator(o.boxes.end()));
    }
};

// The slope between two neighbouring differences `distance` apart; a skipped value (NaN) says
// nothing, an infinite one makes the slope infinite.
double slope(double a, double b, double distance) {
    if (std::isnan(a) || std::isnan(b))
        return 0.0;
    if (std::isinf(a) || std::isinf(b))
        return INFINITY;
    return std::fabs(a - b) / distance;
}

// float storage of a slope, rounded so that it never understates the double.
float roundUp(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, INFINITY) : f;
}

// One axis of the grid: the boxes' centres and half widths.
struct Axis {
    std::vector<double> centre, half;
    int size() const { return static_cast<int>(centre.size()); }
};

Axis makeAxis(double lo, double hi, int intervals, const std::vector<double>& breaks) {
    std::vector<double> planes;
    planes.reserve(static_cast<std::size_t>(intervals) + 1 + breaks.size());
    for (int j = 0; j <= intervals; ++j)
        planes.push_back(j == intervals ? hi : lo + (hi - lo) * (double(j) / intervals));
    for (double b : breaks)
        if (b > lo && b < hi)
            planes.push_back(b);
    std::sort(planes.begin(), planes.end());
    const double tiny = 1e-9 * std::fabs(hi - lo);
    Axis a;
    for (std::size_t i = 0; i + 1 < planes.size(); ++i) {
        if (planes[i + 1] - planes[i] <= tiny)
            continue;
        a.centre.push_back(0.5 * (planes[i] + planes[i + 1]));
        a.half.push_back(0.5 * (planes[i + 1] - planes[i]));
    }
    if (a.centre.empty()) { // a degenerate box: one point
        a.centre.push_back(lo);
        a.half.push_back(0.0);
    }
    return a;
}

// The grid's intervals per axis: `perCell` per lattice cell when given; else as many per cell as
// the budget allows, at least one; a lattice finer than the budget allows gets a coarser grid
// (its boxes span several cells: a larger slope term, which the refinement then narrows).
int gridIntervals(const BoundOptions& o, int cells) {
    if (o.perCell > 0)
        return cells * o.perCell;
    if (o.greyOnly) // a curve: up to 64 points per entry interval, at most ~2^18 in all
        return cells * std::clamp(static_cast<int>(262144 / std::max(1, cells)), 1, 64);
    const int perAxis = std::max(1, static_cast<int>(lut::math::cbrt(
                                        static_cast<double>(std::max<std::size_t>(o.budget, 1)))));
    if (o.constantBetweenBreaks)
        return std::min(cells, perAxis);
    return cells >= perAxis ? perAxis : cells * std::max(1, perAxis / cells);
}

void maxInto(Slopes& a, const Slopes& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = std::max(a[i], b[i]);
}

Tally boundCurve(const DifferenceFn& fn, const BoundOptions& o, const Axis& t) {
    const int m = t.size();
    std::vector<glm::dvec3> in(static_cast<std::size_t>(m)), e(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i)
        in[static_cast<std::size_t>(i)] = glm::dvec3(t.centre[static_cast<std::size_t>(i)]);
    fn(in.data(), e.data(), e.size());
    // L(i): the steeper slope to either neighbour; S(i): the largest L of i and its neighbours.
    std::vector<glm::dvec3> l(e.size(), glm::dvec3(0.0));
    if (!o.constantBetweenBreaks)
        for (int i = 0; i < m; ++i)
            for (int c = 0; c < 3; ++c) {
                const auto at = [&](int k) { return e[static_cast<std::size_t>(k)][c]; };
                const auto x = [&](int k) { return t.centre[static_cast<std::size_t>(k)]; };
                double s = 0.0;
                if (i > 0)
                    s = std::max(s, slope(at(i), at(i - 1), x(i) - x(i - 1)));
                if (i + 1 < m)
                    s = std::max(s, slope(at(i), at(i + 1), x(i + 1) - x(i)));
                l[static_cast<std::size_t>(i)][c] = s;
            }
    Tally tally;
    for (int i = 0; i < m; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        Box box;
        box.centre = glm::dvec3(t.centre[u]);
        box.half = glm::dvec3(t.half[u], 0.0, 0.0);
        box.e = e[u];
        for (int c = 0; c < 3; ++c) {
            double s = l[u][c];
            if (i > 0)
                s = std::max(s, l[u - 1][c]);
            if (i + 1 < m)
                s = std::max(s, l[u + 1][c]);
            tally.add(e[u][c]);
            box.slope[static_cast<std::size_t>(c)] = roundUp(s);
        }
        if (!o.constantBetweenBreaks)
            tally.keep(std::move(box));
    }
    return tally;
}

// The 3D grid, worked through in slabs of planes (blue) with two planes of halo each side (the
// slopes need one, their neighbourhood maximum another).
class Grid3 {
public:
    Grid3(const DifferenceFn& fn, const BoundOptions& o, std::array<Axis, 3> axes)
        : m_fn(fn), m_o(o), m_ax(std::move(axes)) {}

    int planes() const { return m_ax[2].size(); }

    Tally slab(int z0, int z1) const {
        const int mx = m_ax[0].size(), my = m_ax[1].size(), mz = m_ax[2].size();
        const std::size_t plane = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
        const int ze0 = std::max(0, z0 - 2), ze1 = std::min(mz, z1 + 2);
        // the differences of planes ze0 .. ze1 - 1
        std::vector<glm::dvec3> e(plane * static_cast<std::size_t>(ze1 - ze0));
        std::vector<glm::dvec3> in(plane);
        for (int z = ze0; z < ze1; ++z) {
            std::size_t i = 0;
            for (int y = 0; y < my; ++y)
                for (int x = 0; x < mx; ++x)
                    in[i++] = glm::dvec3(c(0, x), c(1, y), c(2, z));
            m_fn(in.data(), e.data() + plane * static_cast<std::size_t>(z - ze0), plane);
        }
        auto eAt = [&](int x, int y, int z) -> const glm::dvec3& {
            return e[plane * static_cast<std::size_t>(z - ze0) +
                     static_cast<std::size_t>(y) * static_cast<std::size_t>(mx) +
                     static_cast<std::size_t>(x)];
        };
        Tally t;
        if (m_o.constantBetweenBreaks) {
            for (int z = z0; z < z1; ++z)
                for (int y = 0; y < my; ++y)
                    for (int x = 0; x < mx; ++x) {
                        for (int ch = 0; ch < 3; ++ch)
                            t.add(eAt(x, y, z)[ch]);
                        if (m_o.values)
                            record(x, y, z, eAt(x, y, z));
                    }
            return t;
        }
        // L: per point, axis and channel, the steeper slope to either neighbour along the axis;
        // planes zl0 .. zl1 - 1 (one beyond the slab each side).
        const int zl0 = std::max(0, z0 - 1), zl1 = std::min(mz, z1 + 1);
        std::vector<Slopes> l(plane * static_cast<std::size_t>(zl1 - zl0));
        auto lAt = [&](int x, int y, int z) -> Slopes& {
            return l[plane * static_cast<std::size_t>(z - zl0) +
                     static_cast<std::size_t>(y) * static_cast<std::size_t>(mx) +
                     static_cast<std::size_t>(x)];
        };
        const int size[3] = {mx, my, mz};
        for (int z = zl0; z < zl1; ++z)
            for (int y = 0; y < my; ++y)
                for (int x = 0; x < mx; ++x) {
                    const glm::dvec3& here = eAt(x, y, z);
                    Slopes& out = lAt(x, y, z);
                    const int q[3] = {x, y, z};
                    for (int a = 0; a < 3; ++a) {
                        double s[3] = {0.0, 0.0, 0.0};
                        for (int d = -1; d <= 1; d += 2) {
                            int p[3] = {q[0], q[1], q[2]};
                            p[a] += d;
                            if (p[a] < 0 || p[a] >= size[a])
                                continue;
                            const glm::dvec3& there = eAt(p[0], p[1], p[2]);
                            const double dist = std::fabs(c(a, p[a]) - c(a, q[a]));
                            for (int ch = 0; ch < 3; ++ch)
                                s[ch] = std::max(s[ch], slope(here[ch], there[ch], dist));
                        }
                        for (int ch = 0; ch < 3; ++ch)
                            out[static_cast<std::size_t>(3 * a + ch)] = roundUp(s[ch]);
                    }
                }
        // The neighbourhood maximum, separably: along x and y within each plane, then along z.
        std::vector<Slopes> row(static_cast<std::size_t>(std::max(mx, my)));
        for (int z = zl0; z < zl1; ++z) {
            for (int y = 0; y < my; ++y) {
                for (int x = 0; x < mx; ++x) {
                    Slopes v = lAt(x, y, z);
                    if (x > 0)
                        maxInto(v, lAt(x - 1, y, z));
                    if (x + 1 < mx)
                        maxInto(v, lAt(x + 1, y, z));
                    row[static_cast<std::size_t>(x)] = v;
                }
                for (int x = 0; x < mx; ++x)
                    lAt(x, y, z) = row[static_cast<std::size_t>(x)];
            }
            for (int x = 0; x < mx; ++x) {
                for (int y = 0; y < my; ++y) {
                    Slopes v = lAt(x, y, z);
                    if (y > 0)
                        maxInto(v, lAt(x, y - 1, z));
                    if (y + 1 < my)
                        maxInto(v, lAt(x, y + 1, z));
                    row[static_cast<std::size_t>(y)] = v;
                }
                for (int y = 0; y < my; ++y)
                    lAt(x, y, z) = row[static_cast<std::size_t>(y)];
            }
        }
        for (int z = z0; z < z1; ++z)
            for (int y = 0; y < my; ++y)
                for (int x = 0; x < mx; ++x) {
                    Slopes s = lAt(x, y, z);
                    if (z > zl0)
                        maxInto(s, lAt(x, y, z - 1));
                    if (z + 1 < zl1)
                        maxInto(s, lAt(x, y, z + 1));
                    const glm::dvec3& here = eAt(x, y, z);
                    for (int ch = 0; ch < 3; ++ch)
                        t.add(here[ch]);
                    if (m_o.values)
                        record(x, y, z, here);
                    Box box;
                    box.centre = glm::dvec3(c(0, x), c(1, y), c(2, z));
                    box.half = glm::dvec3(half(0, x), half(1, y), half(2, z));
                    box.e = here;
                    box.slope = s;
                    t.keep(std::move(box));
                }
        return t;
    }

private:
    void record(int x, int y, int z, const glm::dvec3& e) const {
        const std::size_t i =
            3 * (static_cast<std::size_t>(x) +
                 static_cast<std::size_t>(m_ax[0].size()) *
                     (static_cast<std::size_t>(y) +
                      static_cast<std::size_t>(m_ax[1].size()) * static_cast<std::size_t>(z)));
        for (int ch = 0; ch < 3; ++ch)
            (*m_o.values)[i + static_cast<std::size_t>(ch)] = static_cast<float>(std::fabs(e[ch]));
    }
    double c(int axis, int i) const {
        return m_ax[static_cast<std::size_t>(axis)].centre[static_cast<std::size_t>(i)];
    }
    double half(int axis, int i) const {
        return m_ax[static_cast<std::size_t>(axis)].half[static_cast<std::size_t>(i)];
    }

    const DifferenceFn& m_fn;
    const BoundOptions& m_o;
    std::array<Axis, 3> m_ax;
};

// Branch and bound: the box with the largest bound is split in two along each axis that varies
// (8 children, 2 for a curve), the children measured at their centres with the parent's slopes
// or, where steeper, the change between neighbouring children; until no box's bound is above the
// largest difference seen by more than 1% (the bound is then within 1% of a difference that
// occurs), or half the budget more is spent. Returns the bound over every box.
double refineBoxes(const DifferenceFn& fn, const BoundOptions& o, Tally& total,
                   std::size_t& spent) {
    auto threshold = [&] { return tightEnough(total.seen); };
    double settled = total.settled;
    std::vector<Box> heap;
    for (Box& b : total.boxes)
        if (b.bound > threshold())
            heap.push_back(std::move(b));
        else
            settled = std::max(settled, b.bound);
    total.boxes.clear();
    if (heap.size() > kKeptBoxes) {
        std::nth_element(heap.begin(), heap.begin() + static_cast<std::ptrdiff_t>(kKeptBoxes),
                         heap.end(),
                         [](const Box& a, const Box& b) { return ByBoundDescending()(b, a); });
        for (std::size_t i = kKeptBoxes; i < heap.size(); ++i)
            settled = std::max(settled, heap[i].bound);
        heap.resize(kKeptBoxes);
    }
    std::make_heap(heap.begin(), heap.end(), ByBoundDescending());
    const int dims = o.greyOnly ? 1 : 3;
    const std::size_t kids = std::size_t{1} << dims;
    const std::size_t budget = std::max<std::size_t>(o.budget / 2, 4096);
    spent = 0;
    std::vector<Box> batch;
    std::vector<glm::dvec3> in, out;
    while (!heap.empty() && heap.front().bound > threshold() && spent < budget) {
        batch.clear();
        while (!heap.empty() && heap.front().bound > threshold() && batch.size() < 4096) {
            std::pop_heap(heap.begin(), heap.end(), ByBoundDescending());
            batch.push_back(std::move(heap.back()));
            heap.pop_back();
        }
        in.resize(batch.size() * kids);
        out.resize(in.size());
        for (std::size_t i = 0; i < batch.size(); ++i)
            for (std::size_t k = 0; k < kids; ++k) {
                glm::dvec3 p = batch[i].centre;
                for (int a = 0; a < dims; ++a)
                    p[a] += ((k >> a) & 1u ? 0.5 : -0.5) * batch[i].half[a];
                in[i * kids + k] = o.greyOnly ? glm::dvec3(p.x) : p;
            }
        const int chunks = static_cast<int>((in.size() + 1023) / 1024);
        parallelFor(chunks, o.nthreads, [&](int c0, int c1) {
            for (int ch = c0; ch < c1; ++ch) {
                const std::size_t b = static_cast<std::size_t>(ch) * 1024;
                fn(in.data() + b, out.data() + b, std::min<std::size_t>(1024, in.size() - b));
            }
        });
        spent += in.size();
        for (std::size_t i = 0; i < batch.size(); ++i) {
            const Box& parent = batch[i];
            for (std::size_t k = 0; k < kids; ++k) {
                Box child;
                child.centre = parent.centre;
                for (int a = 0; a < dims; ++a) {
                    child.centre[a] += ((k >> a) & 1u ? 0.5 : -0.5) * parent.half[a];
                    child.half[a] = 0.5 * parent.half[a];
                }
                child.e = out[i * kids + k];
                child.slope = parent.slope;
                for (int a = 0; a < dims; ++a) {
                    const glm::dvec3& other = out[i * kids + (k ^ (std::size_t{1} << a))];
                    for (int c = 0; c < 3; ++c) {
                        float& sl = child.slope[static_cast<std::size_t>(3 * a + c)];
                        sl = std::max(sl, roundUp(slope(child.e[c], other[c], parent.half[a])));
                    }
                }
                for (int c = 0; c < 3; ++c) // the mean stays the grid's, a midpoint rule
                    if (!std::isnan(child.e[c]))
                        total.seen = std::max(total.seen, std::fabs(child.e[c]));
                child.bound = boxBound(child);
                if (child.bound > threshold()) {
                    heap.push_back(std::move(child));
                    std::push_heap(heap.begin(), heap.end(), ByBoundDescending());
                } else {
                    settled = std::max(settled, child.bound);
                }
            }
        }
    }
    const double top = heap.empty() ? 0.0 : heap.front().bound;
    return std::max({settled, top, total.seen});
}

} // namespace

ErrorStats boundError(const DifferenceFn& fn, const BoundOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    const int cells = std::max(1, o.cells);
    const int intervals = gridIntervals(o, cells);
    // Planes that would take the grid far over its budget (a 256^3 lattice's) are left out: the
    // slope term covers the kinks between the grid's planes then, and jumps too (the difference
    // is no longer constant in a box).
    BoundOptions opts = o;
    double gridPoints = 1.0;
    for (int a = 0; a < (o.greyOnly ? 1 : 3); ++a)
        gridPoints *= intervals + static_cast<double>(o.breaks[static_cast<std::size_t>(a)].size());
    if (gridPoints > 16.0 * static_cast<double>(std::max<std::size_t>(o.budget, 1)) &&
        gridPoints > lut::math::pow(static_cast<double>(intervals), o.greyOnly ? 1.0 : 3.0)) {
        for (auto& all : opts.breaks)
            all.clear();
        opts.constantBetweenBreaks = false;
    }
    Tally total;
    std::size_t points = 0;
    if (o.greyOnly) {
        const Axis t = makeAxis(o.lo.x, o.hi.x, intervals, opts.breaks[0]);
        points = t.centre.size();
        total = boundCurve(fn, opts, t);
    } else {
        std::array<Axis, 3> axes;
        for (int a = 0; a < 3; ++a)
            axes[static_cast<std::size_t>(a)] =
                makeAxis(o.lo[a], o.hi[a], intervals, opts.breaks[static_cast<std::size_t>(a)]);
        points = axes[0].centre.size() * axes[1].centre.size() * axes[2].centre.size();
        if (o.values)
            o.values->assign(3 * points, NAN);
        const Grid3 grid(fn, opts, std::move(axes));
        const int mz = grid.planes();
        // Slabs of at least 8 planes: the halo (up to 4 planes) is recomputed by both neighbours.
        // The slabs and the order their tallies are merged in are the same whatever the threads
        // (the boxes' order decides which the refinement takes first among equal bounds, and the
        // sum's order its last bits): the printed figures are the same on every run, machine
        // and edition (they varied from run to run: 3.58e-07, 3.88e-07, 4.18e-07).
        const int slabPlanes = std::max(8, mz / 16);
        const int slabs = (mz + slabPlanes - 1) / slabPlanes;
        std::vector<Tally> parts(static_cast<std::size_t>(slabs));
        parallelForDynamic(slabs, o.nthreads, 1, [&](int s0, int s1) {
            for (int s = s0; s < s1; ++s)
                parts[static_cast<std::size_t>(s)] =
                    grid.slab(s * slabPlanes, std::min(mz, (s + 1) * slabPlanes));
        });
        for (Tally& t : parts)
            total.merge(std::move(t));
    }
    std::size_t refinedPoints = 0;
    const double refined = refineBoxes(fn, opts, total, refinedPoints);
    ErrorStats stats;
    stats.maxAbs = refined;
    stats.sampledMax = total.seen;
    stats.meanAbs = total.count ? total.sum / static_cast<double>(total.count) : 0.0;
    stats.count = total.count;
    stats.bounded = true;
    stats.heldOutPoints = points + refinedPoints;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats;
}

Breaks latticeBreaks(const Lut3D& lut, Interpolation method) {
    Breaks out;
    const int n = lut.size();
    const glm::vec3 lo = lut.domainMin(), hi = lut.domainMax();
    const double shift = method == Interpolation::Nearest ? 0.5 : 0.0;
    for (int a = 0; a < 3; ++a) {
        auto& v = out[static_cast<std::size_t>(a)];
        for (int i = 0; i < n; ++i)
            if (i + shift < n - 1 || shift == 0.0)
                v.push_back(double(lo[a]) + (double(hi[a]) - lo[a]) * ((i + shift) / (n - 1)));
    }
    return out;
}

void addBreaks(Breaks& into, const Breaks& more) {
    for (std::size_t a = 0; a < 3; ++a)
        into[a].insert(into[a].end(), more[a].begin(), more[a].end());
}

ErrorStats boundLatticeError(const Lut3D& approx, Interpolation method, const BatchFn& exact,
                             const Breaks& breaks, int nthreads) {
    const auto sampler = makeSampler(approx, method);
    BoundOptions o;
    o.lo = glm::dvec3(approx.domainMin());
    o.hi = glm::dvec3(approx.domainMax());
    o.cells = approx.size() - 1;
    o.breaks = breaks;
    addBreaks(o.breaks, latticeBreaks(approx, method));
    o.constantBetweenBreaks = method == Interpolation::Nearest;
    o.nthreads = nthreads;
    return boundError(
        [&](const glm::dvec3* in, glm::dvec3* diff, std::size_t n) {
            std::vector<glm::vec3> x(n), want(n);
            for (std::size_t i = 0; i < n; ++i)
                x[i] = glm::vec3(in[i]);
            exact(x.data(), want.data(), n);
            for (std::size_t i = 0; i < n; ++i)
                diff[i] = glm::dvec3(want[i]) - glm::dvec3(sampler->sample(x[i]));
        },
        o);
}

} // namespace lut
