// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/Compose.h"

#include "lut/Error.h"
#include "lut/Parallel.h"
#include "lut/interp/Sampler.h"
#include "lut/ops/Adjust.h"
#include "lut/ops/ErrorBound.h"
#include "ops/OpsDetail.h"

#include <algorithm>
#include <cmath>

namespace lut {

namespace {

Lut3D latticeLike(int size, const Lut3D& domainOf) {
    Lut3D out(size);
    out.setDomain(domainOf.domainMin(), domainOf.domainMax());
    return out;
}

// Fills every entry of `out` with fn(lattice input), slices of blue on up to nthreads threads.
template <class Fn> void fillLattice(Lut3D& out, int nthreads, Fn fn) {
    const int n = out.size();
    parallelFor(n, n < 17 ? 1 : nthreads, [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r)
                    out.at(r, g, b) = fn(out.latticeInput(r, g, b));
    });
}

bool sameLattice(const Lut3D& a, const Lut3D& b) {
    return a.size() == b.size() && a.domainMin() == b.domainMin() && a.domainMax() == b.domainMax();
}

} // namespace

OpResult compose(const Lut3D& a, const Lut3D& b, const ComposeOptions& options) {
    if (a.empty() || b.empty())
        throw Error("compose: both LUTs must have entries");
    const long long t0 = detail::nowNanos();
    std::size_t ra = 0, rb = 0;
    const Lut3D sa = detail::sanitizedCopy(a, ra), sb = detail::sanitizedCopy(b, rb);
    const auto pa = makeSampler(sa, options.method);
    const auto pb = makeSampler(sb, options.method);
    const int size = options.size > 0 ? options.size : std::max(a.size(), b.size());
    OpResult result{latticeLike(size, a), {}, ra + rb};
    result.lut.setTitle(a.title());
    fillLattice(result.lut, options.nthreads,
                [&](glm::vec3 in) { return pb->sample(pa->sample(in)); });
    const double seconds = detail::secondsSince(t0);
    // B(A(x)) kinks (or jumps) where A does; where B does, too, but those places depend on A.
    result.error = boundLatticeError(
        result.lut, options.method,
        [&](const glm::vec3* in, glm::vec3* out, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i)
                out[i] = pb->sample(pa->sample(in[i]));
        },
        latticeBreaks(sa, options.method), options.nthreads);
    result.error.seconds = seconds;
    return result;
}

OpResult mix(const Lut3D& a, const Lut3D& b, double t, Interpolation method, int nthreads) {
    if (a.empty() || b.empty())
        throw Error("mix: both LUTs must have entries");
    const long long t0 = detail::nowNanos();
    t = std::isnan(t) ? 0.0 : std::clamp(t, -1.0, 2.0);
    std::size_t ra = 0, rb = 0;
    const Lut3D sa = detail::sanitizedCopy(a, ra), sb = detail::sanitizedCopy(b, rb);
    OpResult result{sa, {}, ra + rb};
    auto blend = [t](glm::vec3 x, glm::vec3 y) {
        glm::vec3 o;
        for (int c = 0; c < 3; ++c)
            o[c] = detail::sanitizeValue(
                static_cast<float>((1.0 - t) * static_cast<double>(x[c]) + t * y[c]));
        return o;
    };
    if (sameLattice(sa, sb)) {
        auto& out = result.lut.entries();
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i] = blend(sa.entries()[i], sb.entries()[i]);
        result.error.count = out.size() * 3;
        result.error.bounded = true; // exact: the interpolant of mixed entries is the mix
        result.error.seconds = detail::secondsSince(t0);
        return result;
    }
    const auto pa = makeSampler(sa, method);
    const auto pb = makeSampler(sb, method);
    fillLattice(result.lut, nthreads,
                [&](glm::vec3 in) { return blend(pa->sample(in), pb->sample(in)); });
    const double seconds = detail::secondsSince(t0);
    result.error = boundLatticeError(
        result.lut, method,
        [&](const glm::vec3* in, glm::vec3* out, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i)
                out[i] = blend(pa->sample(in[i]), pb->sample(in[i]));
        },
        latticeBreaks(sb, method), nthreads);
    result.error.seconds = seconds;
    return result;
}

Lut3D withStrength(const Lut3D& a, double strength) {
    Lut3D out = a;
    const int n = a.size();
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                out.at(r, g, b) = glm::vec3(adjustStrength(glm::dvec3(a.latticeInput(r, g, b)),
                                                           glm::dvec3(a.at(r, g, b)), strength));
    return out;
}

} // namespace lut
