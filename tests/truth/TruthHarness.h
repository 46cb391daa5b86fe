// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth harness's tools (tests/truth, docs/accuracy.md "The truth harness"): sources written
// here from float64 formulas, the written files evaluated by another program (OpenColorIO's
// unoptimised processors) or by a float64 interpolation written here (LUT images), on random
// inputs lutkit never saw, and the printed maxima read from lutkit's --json output.
#include "OcioTestUtil.h"
#include "ShapedCube.h"
#include "TestSupport.h"

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace lut::truth {

using lut::test::shellQuoted;

inline std::string workDir(const std::string& name) {
    const std::string d = lut::test::tempDir() + "-truth-" + name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

using lut::test::writeShapedCube; // tests/support/ShapedCube.h

using Fn = std::function<glm::dvec3(glm::dvec3)>;

// An n^3 .cube of f over [0,1], 9 digits.
inline std::string writeCube(const std::string& path, int n, const Fn& f) {
    std::FILE* o = std::fopen(path.c_str(), "w");
    std::fprintf(o, "LUT_3D_SIZE %d\n", n);
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::dvec3 v = f(glm::dvec3(r, g, b) / double(n - 1));
                std::fprintf(o, "%.9g %.9g %.9g\n", v.x, v.y, v.z);
            }
    std::fclose(o);
    return path;
}

// Random inputs (packed RGB): `count` uniform in [0,1]^3 and count/4 in [0, 1/16]^3, where a log
// shaper is steepest. Fixed seed; none is a lattice point of any table here.
// darkQuarter = false: the uniform ones only (for a mean over [0,1]).
inline std::vector<float> randomUnitInputs(int count = 150000, unsigned seed = 40,
                                           bool darkQuarter = true) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> v;
    v.reserve(3 * static_cast<std::size_t>(count + count / 4));
    for (int i = 0; i < 3 * count; ++i)
        v.push_back(static_cast<float>(u(rng)));
    for (int i = 0; i < (darkQuarter ? 3 * (count / 4) : 0); ++i)
        v.push_back(static_cast<float>(u(rng) / 16.0));
    return v;
}

inline void ocioApply(const std::string& file, std::vector<float>& rgb) {
    const auto p = lut::test::ocioFileProcessor(file);
    lut::test::OCIO::PackedImageDesc desc(rgb.data(), static_cast<long>(rgb.size() / 3), 1, 3);
    p->apply(desc);
}

// A LUT image in the unreal/pilot layout (N^2 x N, x = r + N*b, y = g), read by OpenImageIO and
// interpolated tetrahedrally in float64 (the Kuhn simplices: the order of the fractions).
inline void stripApply(const std::string& file, std::vector<float>& rgb) {
    auto in = OIIO::ImageInput::open(file);
    ASSERT_TRUE(in) << file;
    const OIIO::ImageSpec spec = in->spec();
    const int n = spec.height, ch = spec.nchannels;
    ASSERT_EQ(spec.width, n * n) << file;
    std::vector<float> px(static_cast<std::size_t>(spec.width) * n * ch);
    in->read_image(0, 0, 0, ch, OIIO::TypeDesc::FLOAT, px.data());
    auto at = [&](int r, int g, int b) {
        const float* p = &px[(static_cast<std::size_t>(g) * spec.width + r + n * b) * ch];
        return glm::dvec3(p[0], p[1], p[2]);
    };
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
        double f[3];
        int i0[3];
        for (int c = 0; c < 3; ++c) {
            const double t = std::clamp(double(rgb[i + c]), 0.0, 1.0) * (n - 1);
            i0[c] = std::min(static_cast<int>(t), n - 2);
            f[c] = t - i0[c];
        }
        int order[3] = {0, 1, 2};
        std::sort(order, order + 3, [&](int a, int b) { return f[a] > f[b]; });
        int idx[3] = {i0[0], i0[1], i0[2]};
        glm::dvec3 v = at(idx[0], idx[1], idx[2]) * (1.0 - f[order[0]]);
        for (int k = 0; k < 3; ++k) {
            ++idx[order[k]];
            const glm::dvec3 next = at(idx[0], idx[1], idx[2]);
            const double w = f[order[k]] - (k < 2 ? f[order[k + 1]] : 0.0);
            v += next * w;
        }
        for (int c = 0; c < 3; ++c)
            rgb[i + c] = static_cast<float>(v[c]);
    }
}

// OpenColorIO evaluates each file in float32: two evaluations of the same function at one input
// differ by their rounding (up to ~2e-6 seen, a thousandth of an 8-bit step), which no printed
// figure about the tables covers.
constexpr double kOracleRounding = 4e-6;

struct Truth {
    double max = 0.0, mean = 0.0;
};

inline Truth compare(const std::vector<float>& a, const std::vector<float>& b) {
    Truth t;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::fabs(double(a[i]) - double(b[i]));
        t.max = std::max(t.max, d);
        t.mean += d;
    }
    t.mean /= static_cast<double>(a.size());
    return t;
}

// The number after "key": in text, searching from `from`; NaN if absent.
inline double jsonNumber(const std::string& text, const std::string& key, std::size_t from = 0) {
    if (from == std::string::npos)
        return NAN;
    const auto k = text.find("\"" + key + "\": ", from);
    return k == std::string::npos ? NAN : std::strtod(text.c_str() + k + key.size() + 4, nullptr);
}

// The number after "max " that follows `key` in printed text (a report line's maximum); NaN if
// either is absent.
inline double maxAfter(const std::string& text, const std::string& key) {
    const auto k = text.find(key);
    if (k == std::string::npos)
        return NAN;
    const auto m = text.find("max ", k);
    return m == std::string::npos ? NAN : std::strtod(text.c_str() + m + 4, nullptr);
}

// An 8-bit RGB PNG written by OpenImageIO (a picture the test made, not one lutkit wrote).
inline void writePng(const std::string& path, int w, int h, const std::vector<unsigned char>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgb.data()));
    out->close();
}

// One row of the harness's table (docs/accuracy.md lists them).
inline void row(const std::string& what, double truth, double printed, double truthMean = NAN) {
    std::printf("[ truth    ] %-58s truth max %8.3f, printed %8.3f 8-bit steps", what.c_str(),
                truth * 255, printed * 255);
    if (!std::isnan(truthMean))
        std::printf(" (truth mean %.3f)", truthMean * 255);
    std::printf("\n");
}

} // namespace lut::truth
