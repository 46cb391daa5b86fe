// SPDX-License-Identifier: Apache-2.0
#include "match/MatchColours.h"

#include "lut/Parallel.h"
#include "lut/match/WorkingSpace.h"
#include "lut/ops/ColorDifference.h"

namespace lut::detail {

glm::dvec3 labOfStored(const glm::dvec3& x, bool linear) {
    return linear ? xyzToLab(linearSrgbToXyz(x)) : srgbToLab(x);
}

namespace {
template <class F>
std::vector<glm::vec3> convert(const std::vector<glm::vec3>& in, int nthreads, F f) {
    std::vector<glm::vec3> out(in.size());
    parallelFor(static_cast<int>(in.size()), nthreads, [&](int a, int b) {
        for (int i = a; i < b; ++i)
            out[static_cast<std::size_t>(i)] =
                glm::vec3(f(glm::dvec3(in[static_cast<std::size_t>(i)])));
    });
    return out;
}
} // namespace

std::vector<glm::vec3> labOfWorking(const std::vector<glm::vec3>& working, bool linear,
                                    int nthreads) {
    return convert(working, nthreads, [linear](const glm::dvec3& w) {
        return labOfStored(glm::dvec3(decodeWorking(w.x, linear), decodeWorking(w.y, linear),
                                      decodeWorking(w.z, linear)),
                           linear);
    });
}

std::vector<glm::vec3> labOfStored(const std::vector<glm::vec3>& stored, bool linear,
                                   int nthreads) {
    return convert(stored, nthreads,
                   [linear](const glm::dvec3& x) { return labOfStored(x, linear); });
}

} // namespace lut::detail
