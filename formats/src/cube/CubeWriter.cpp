// SPDX-License-Identifier: Apache-2.0
// The .cube writer.
//
// Comments first (as "# text"), TITLE when set (as a comment in the Resolve dialect, which has
// no TITLE), the size line(s), DOMAIN_MIN/MAX (Adobe) or
// LUT_*_INPUT_RANGE (Resolve) only when the domain is not the default 0..1 (the default is implied
// by the spec, and some readers mishandle DOMAIN lines), then the rows, LF line ends. Floats are
// written as the shortest text that reads back as the same float (std::to_chars), so write ->
// read is bit-exact. A shaper + cube file is written in the Resolve dialect when every domain is
// equal on all channels; otherwise the shaper is baked into the cube (Warning). Non-finite
// entries are written as 0 (NaN) or +-FLT_MAX (Inf) with a Warning. Big tables are formatted on
// all cores.
#include "LutPrep.h"

#include "lut/NumberText.h"
#include "lut/formats/Cube.h"

#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/io/AtomicFile.h"
#include "lut/ops/Lattice.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

namespace lut::formats {

namespace {

// Appends the shortest round-trip text of v (or fixed decimals).
inline char* putFloat(char* p, float v, int decimals) {
    if (decimals < 0)
        return lut::toChars(p, p + 48, v).ptr;
    return lut::toCharsFixed(p, p + 80, v, decimals).ptr;
}

// Shortest texts of recently written floats. LUTs repeat values a lot (a neutral N^3 table has N
// distinct values, one from 8-bit data at most 256), and a lookup costs a fraction of to_chars.
class FloatTextCache {
public:
    FloatTextCache() {
        for (auto& s : m_slots)
            s.bits = 0xFFFFFFFFu; // a NaN pattern: never looked up
    }
    char* put(char* p, float v) {
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        Slot& s = m_slots[(bits * 0x9E3779B1u) >> (32 - kBits)];
        if (s.bits != bits) {
            s.bits = bits;
            s.length = static_cast<std::uint8_t>(
                lut::toChars(s.text, s.text + sizeof s.text, v).ptr - s.text);
        }
        std::memcpy(p, s.text, sizeof s.text);
        return p + s.length;
    }

private:
    static constexpr int kBits = 10;
    struct Slot {
        std::uint32_t bits;
        std::uint8_t length;
        char text[19]; // the longest shortest float text is 15 bytes ("-1.17549435e-38")
    };
    std::array<Slot, 1u << kBits> m_slots;
};

// Formats rows [0, count) of v (3 floats each) into dst; returns the number of non-finite values
// replaced. Plain loop, one bounds check per row.
std::size_t formatRows(std::string& dst, const float* v, std::size_t count, int decimals) {
    // Room for the longest row; the cache copies whole 19-byte slots, hence the margin.
    const std::size_t rowMax =
        decimals < 0 ? 3 * 20 + 19 : 3 * (static_cast<std::size_t>(decimals) + 42);
    auto cache = std::make_unique<FloatTextCache>();
    std::size_t nonFinite = 0;
    std::size_t used = dst.size();
    dst.resize(used + count * 3 * 12 + rowMax);
    for (std::size_t r = 0; r < count; ++r) {
        if (dst.size() - used < rowMax)
            dst.resize(dst.size() + (count - r) * 3 * 12 + rowMax);
        char* p = dst.data() + used;
        for (int c = 0; c < 3; ++c) {
            float x = v[r * 3 + static_cast<std::size_t>(c)];
            if (!std::isfinite(x)) {
                ++nonFinite;
                x = std::isnan(x) ? 0.0f : (x > 0 ? FLT_MAX : -FLT_MAX);
            }
            p = decimals < 0 ? cache->put(p, x) : putFloat(p, x, decimals);
            *p++ = c == 2 ? '\n' : ' ';
        }
        used = static_cast<std::size_t>(p - dst.data());
    }
    dst.resize(used);
    return nonFinite;
}

// Appends the rows to out, formatted on all cores in rounds of bounded size (so a 256^3 table
// does not need a second full-size copy of its text).
std::size_t putRows(std::string& out, const float* v, std::size_t count, int decimals) {
    constexpr std::size_t kParallelMin = 16384;
    constexpr std::size_t kRoundRows = std::size_t(1) << 20;
    const int threads = count < kParallelMin ? 1 : resolveThreads(0);
    if (threads <= 1)
        return formatRows(out, v, count, decimals);
    std::vector<std::string> parts(static_cast<std::size_t>(threads));
    std::vector<std::size_t> bad(static_cast<std::size_t>(threads));
    std::size_t nonFinite = 0;
    for (std::size_t begin = 0; begin < count; begin += kRoundRows) {
        const std::size_t n = std::min(kRoundRows, count - begin);
        parallelFor(threads, threads, [&](int t0, int t1) {
            for (int t = t0; t < t1; ++t) {
                const std::size_t a = begin + n * static_cast<std::size_t>(t) / threads;
                const std::size_t b = begin + n * static_cast<std::size_t>(t + 1) / threads;
                auto& part = parts[static_cast<std::size_t>(t)];
                part.clear();
                bad[static_cast<std::size_t>(t)] = formatRows(part, v + 3 * a, b - a, decimals);
            }
        });
        for (int t = 0; t < threads; ++t) {
            out += parts[static_cast<std::size_t>(t)];
            nonFinite += bad[static_cast<std::size_t>(t)];
        }
    }
    return nonFinite;
}

bool uniform(glm::vec3 v) {
    return v.x == v.y && v.y == v.z;
}

std::string oneLine(std::string s, const char* what, Diagnostics& d, bool isTitle) {
    bool changed = false;
    for (char& c : s)
        if (c == '\n' || c == '\r' || (isTitle && c == '"')) {
            c = c == '"' ? '\'' : ' ';
            changed = true;
        }
    // Leave room for the keyword and quotes so the line stays readable by our own limit.
    const std::size_t cap = limits::kMaxTextLineBytes - 16;
    if (s.size() > cap) {
        s.resize(cap);
        changed = true;
    }
    if (changed)
        d.push_back({Diagnostic::Severity::Warning,
                     {},
                     0,
                     0,
                     std::string(what) + " changed to fit one .cube line (quotes, line breaks or "
                                         "length)"});
    return s;
}

} // namespace

std::string writeCubeString(const LutFile& lut, Diagnostics* diagnostics,
                            const CubeWriteOptions& options) {
    if (!lut.cube && !lut.shaper)
        throw Error("cannot write a .cube: the LUT holds no table");
    Diagnostics local;
    Diagnostics& diags = diagnostics ? *diagnostics : local;
    const Lut1D* shaper = lut.shaper ? &*lut.shaper : nullptr;
    const Lut3D* cube = lut.cube ? &*lut.cube : nullptr;
    std::optional<Lut3D> baked;
    using Dialect = CubeWriteOptions::Dialect;
    bool resolve = false;
    if (shaper && cube) {
        const bool canResolve = uniform(shaper->domainMin()) && uniform(shaper->domainMax()) &&
                                uniform(cube->domainMin()) && uniform(cube->domainMax());
        if (options.dialect == Dialect::Adobe || !canResolve) {
            // The shaper, then the table, at the lattice over the shaper's domain, or over 0..1
            // (where display pictures live) when the Adobe dialect was asked for and the
            // shaper's domain holds it (over 0..64 inputs in 0..1 fall in the first cells), with
            // what one lattice costs between its points (a bound).
            LatticeRequest q;
            q.size = cube->size();
            const glm::vec3 lo = lut.inputDomainMin(), hi = lut.inputDomainMax();
            const bool unit = options.dialect == Dialect::Adobe && samplesDisplayRange(lo, hi);
            if (unit) {
                q.domainMin = glm::vec3(0.0f);
                q.domainMax = glm::vec3(1.0f);
            }
            LatticeResult r = sampleOnLattice(lut, q);
            r.error.seconds = 0.0;
            baked = std::move(r.lut);
            cube = &*baked;
            shaper = nullptr;
            diags.push_back({Diagnostic::Severity::Warning,
                             {},
                             0,
                             0,
                             std::string(options.dialect == Dialect::Adobe
                                             ? "1D shaper baked into the 3D table: the Adobe "
                                               "dialect has no shaper"
                                             : "1D shaper baked into the 3D table: its domain "
                                               "differs per channel, and the Resolve dialect has "
                                               "one input range for all channels") +
                                 (unit && (lo != glm::vec3(0.0f) || hi != glm::vec3(1.0f))
                                      ? std::string(" ") + kDisplayRangeWords +
                                            " (inputs outside it take the edge value)"
                                      : std::string()) +
                                 " (" + r.error.str() + " on " + std::to_string(r.heldOut) +
                                 " inputs between lattice points)"});
        } else {
            resolve = true;
        }
    } else if (options.dialect == Dialect::Resolve ||
               (options.dialect == Dialect::Auto && lut.dialect == "resolve")) {
        const glm::vec3 mn = cube ? cube->domainMin() : shaper->domainMin();
        const glm::vec3 mx = cube ? cube->domainMax() : shaper->domainMax();
        resolve = uniform(mn) && uniform(mx);
        if (!resolve && options.dialect == Dialect::Resolve)
            diags.push_back({Diagnostic::Severity::Warning,
                             {},
                             0,
                             0,
                             "written in the Adobe dialect: the domain differs per channel, and "
                             "the Resolve dialect has one input range for all channels"});
    }

    const std::size_t rows =
        (shaper ? static_cast<std::size_t>(shaper->size()) : 0) + (cube ? cube->entryCount() : 0);
    std::string out;
    out.reserve(rows * (options.decimals < 0 ? 30 : 3 * (options.decimals + 4)) + 4096);

    // What the LUT is for, first: a comment every other reader skips (lut/LutPurpose.h).
    if (lut.purpose)
        out += "# " + purposeTag(*lut.purpose) + "\n";
    static const std::vector<std::string> kNoComments;
    const std::vector<std::string>& comments = cube ? cube->comments() : kNoComments;
    for (const std::string& c : comments) {
        // A comment with line breaks becomes several comment lines.
        std::size_t start = 0;
        for (;;) {
            const std::size_t nl = c.find('\n', start);
            std::string part =
                c.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
            if (!part.empty() && part.back() == '\r')
                part.pop_back();
            part = oneLine(std::move(part), "a comment", diags, false);
            out += part.empty() ? "#\n" : "# " + part + "\n";
            if (nl == std::string::npos)
                break;
            start = nl + 1;
        }
    }
    // The Resolve dialect has no TITLE (OpenColorIO's Resolve reader refuses the file): there
    // the title is a comment, which every reader skips.
    const std::string& title = cube ? cube->title() : shaper->title();
    if (!title.empty())
        out += std::string(resolve ? "# " : "") + "TITLE \"" +
               oneLine(title, "the title", diags, true) + "\"\n";

    char buf[256];
    auto putTriple = [&](const char* keyword, glm::vec3 v) {
        char* p = buf;
        for (int c = 0; c < 3; ++c) {
            *p++ = ' ';
            p = putFloat(p, v[c], -1);
        }
        out += keyword;
        out.append(buf, static_cast<std::size_t>(p - buf));
        out += '\n';
    };
    auto putRange = [&](const char* keyword, float a, float b) {
        char* p = buf;
        *p++ = ' ';
        p = putFloat(p, a, -1);
        *p++ = ' ';
        p = putFloat(p, b, -1);
        out += keyword;
        out.append(buf, static_cast<std::size_t>(p - buf));
        out += '\n';
    };
    auto isDefault = [](glm::vec3 mn, glm::vec3 mx) {
        return mn == glm::vec3(0.0f) && mx == glm::vec3(1.0f);
    };
    if (shaper) {
        out += "LUT_1D_SIZE " + std::to_string(shaper->size()) + "\n";
        if (resolve) {
            if (cube || !isDefault(shaper->domainMin(), shaper->domainMax()))
                putRange("LUT_1D_INPUT_RANGE", shaper->domainMin().x, shaper->domainMax().x);
        } else if (!isDefault(shaper->domainMin(), shaper->domainMax())) {
            putTriple("DOMAIN_MIN", shaper->domainMin());
            putTriple("DOMAIN_MAX", shaper->domainMax());
        }
    }
    if (cube) {
        out += "LUT_3D_SIZE " + std::to_string(cube->size()) + "\n";
        if (resolve) {
            if (shaper || !isDefault(cube->domainMin(), cube->domainMax()))
                putRange("LUT_3D_INPUT_RANGE", cube->domainMin().x, cube->domainMax().x);
        } else if (!isDefault(cube->domainMin(), cube->domainMax())) {
            putTriple("DOMAIN_MIN", cube->domainMin());
            putTriple("DOMAIN_MAX", cube->domainMax());
        }
    }

    const int decimals = std::min(options.decimals, 40);
    const std::size_t nonFinite =
        (shaper ? putRows(out, &shaper->entries()[0].x, static_cast<std::size_t>(shaper->size()),
                          decimals)
                : 0) +
        (cube ? putRows(out, cube->data(), cube->entryCount(), decimals) : 0);
    if (nonFinite)
        diags.push_back({Diagnostic::Severity::Warning,
                         {},
                         0,
                         0,
                         std::to_string(nonFinite) +
                             " non-finite value(s) written as 0 (NaN) or +-3.40282347e+38 "
                             "(infinity): .cube readers refuse NaN and Inf"});
    return out;
}

Diagnostics writeCube(const std::string& path, const LutFile& lut,
                      const CubeWriteOptions& options) {
    Diagnostics diags;
    const std::string text = writeCubeString(lut, &diags, options);
    writeFileAtomically(path, text);
    for (auto& d : diags)
        if (d.path.empty())
            d.path = path;
    return diags;
}

} // namespace lut::formats
