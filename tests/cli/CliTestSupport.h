// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the tests of the lutkit program (run as a process, support/TestSupport.h's runCli) write
// before they run it: a working folder, small .cube files, the inputs every command takes, and the
// game's model in float64 that the purpose tests compare against. CliTableSupport.h is the other
// half: the command line in-process, without files.
#include "TestSupport.h"

#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/formats/ImageIO.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace lut::test {

// A fresh empty folder for the test's files, beside tempDir()'s folder (tempDir() + ".work"): a
// helper that calls tempDir() again empties that one, not this.
inline std::string workDir() {
    const std::string d = tempDir() + ".work";
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

inline bool has(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

// A small curved .cube of edge n: each channel its input to the power gamma (default precision).
inline std::string writeCube(const std::string& path, int n, float gamma) {
    std::ofstream f(path);
    f << "LUT_3D_SIZE " << n << "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                f << std::pow(r / float(n - 1), gamma) << " " << std::pow(g / float(n - 1), gamma)
                  << " " << std::pow(b / float(n - 1), gamma) << "\n";
    return path;
}

// An n^3 .cube of f over the lattice inputs, entries written with 9 digits (read back exactly).
inline std::string writeCube(const std::string& path, int n,
                             const std::function<glm::vec3(glm::vec3)>& f) {
    std::ofstream o(path);
    o.precision(9);
    o << "LUT_3D_SIZE " << n << "\n";
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r) {
                const glm::vec3 v = f(glm::vec3(r, g, b) / float(n - 1));
                o << v.x << " " << v.y << " " << v.z << "\n";
            }
    return path;
}

// A LUT as a .cube, entries written with 9 digits.
inline std::string writeCube(const std::string& path, const Lut3D& l) {
    std::ofstream f(path);
    f.precision(9);
    f << "LUT_3D_SIZE " << l.size() << "\n";
    for (const auto& e : l.entries())
        f << e.r << " " << e.g << " " << e.b << "\n";
    return path;
}

// The inputs of every command, in `dir`: two curved cubes (a: 9^3, gamma 0.8; b: 5^3, gamma 1.2),
// a 320x200 8-bit screenshot, the neutral strip lutkit writes, an adjustment list.
struct CommandInputs {
    std::string dir, a, b, shot, strip, adjustments;
};

inline CommandInputs makeCommandInputs(const std::string& dir) {
    CommandInputs in;
    in.dir = dir;
    in.a = writeCube(in.dir + "/a.cube", 9, 0.8f);
    in.b = writeCube(in.dir + "/b.cube", 5, 1.2f);
    Image shot(320, 200);
    for (int y = 0; y < shot.height(); ++y)
        for (int x = 0; x < shot.width(); ++x) {
            float* p = shot.pixel(x, y);
            p[0] = x / 319.0f;
            p[1] = y / 199.0f;
            p[2] = 0.3f;
            p[3] = 1.0f;
        }
    in.shot = in.dir + "/shot.png";
    formats::writeImage(in.shot, shot, formats::ImageWriteOptions(8, false, false));
    in.strip = in.dir + "/neutral.png";
    EXPECT_EQ(runCli("neutral " + shellQuoted(in.strip)).exitCode, 0);
    in.adjustments = in.dir + "/adj.txt";
    std::ofstream(in.adjustments) << "# lutkit adjustment list 1\ncontrast 0.2\n";
    return in;
}

// The game's model in float64, written from docs/specs/smash-pipeline.md (sections 2 and 3): the
// oracle of the purpose tests.
namespace game {

inline double srgbEncode(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}
inline double srgbDecode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
// Trilinear over [0,1], clamped to the edge.
inline glm::dvec3 trilinear(const Lut3D& lut, glm::dvec3 in) {
    const int n = lut.size();
    int i[3];
    double f[3];
    for (int c = 0; c < 3; ++c) {
        const double t = std::clamp(in[c], 0.0, 1.0) * (n - 1);
        i[c] = std::min(static_cast<int>(t), n - 2);
        f[c] = t - i[c];
    }
    glm::dvec3 acc(0.0);
    for (int k = 0; k < 8; ++k) {
        const int dr = k & 1, dg = (k >> 1) & 1, db = (k >> 2) & 1;
        acc += (dr ? f[0] : 1 - f[0]) * (dg ? f[1] : 1 - f[1]) * (db ? f[2] : 1 - f[2]) *
               glm::dvec3(lut.at(i[0] + dr, i[1] + dg, i[2] + db));
    }
    return acc;
}
// What the game shows (display-encoded) with LUT g (8-bit, trilinear) for its LUT input s.
inline glm::dvec3 gameShows(const Lut3D& g, const glm::dvec3& s) {
    const glm::dvec3 l = trilinear(g, s);
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c)
        out[c] =
            srgbEncode(std::pow(std::max(((l[c] - s[c]) * 0.99961 + s[c]) * 1.3703, 0.0), 2.2));
    return out;
}

// A game LUT: a warm stage, 8-bit as a .nutexb holds it.
inline Lut3D gameLut() {
    Lut3D g(16);
    for (int b = 0; b < 16; ++b)
        for (int gi = 0; gi < 16; ++gi)
            for (int r = 0; r < 16; ++r) {
                const glm::dvec3 s(r / 15.0, gi / 15.0, b / 15.0);
                glm::dvec3 v(std::min(1.0, s.x * 1.12), 0.04 + 0.9 * s.y, 0.75 * s.z + 0.1 * s.x);
                g.at(r, gi, b) = glm::vec3(glm::round(glm::clamp(v, 0.0, 1.0) * 255.0) / 255.0);
            }
    return g;
}

} // namespace game

} // namespace lut::test
