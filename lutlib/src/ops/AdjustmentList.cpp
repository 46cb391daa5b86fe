// SPDX-License-Identifier: Apache-2.0
#include "lut/ops/AdjustmentList.h"
#include "lut/NumberText.h"

#include "lut/Error.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <set>
#include <vector>

namespace lut {

namespace {

std::string number(double v) {
    char buf[64];
    const auto r = toChars(buf, buf + sizeof buf, v); // shortest exact round trip
    return std::string(buf, r.ptr);
}

// Written when the bits differ from the default (so -0 survives the round trip too).
bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameBits(glm::dvec3 a, glm::dvec3 b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

struct Token {
    std::string_view text;
    int column; // 1-based
};

class LineParser {
public:
    LineParser(const std::string& path, int line) : m_path(path), m_line(line) {}

    [[noreturn]] void fail(const Token& t, const std::string& message) const {
        throw ParseError(m_path, m_line, t.column, message, std::string(t.text));
    }

    double parseNumber(std::string_view s, int column) const {
        std::string_view v = s;
        if (!v.empty() && v.front() == '+')
            v.remove_prefix(1);
        double out = 0.0;
        const auto r = fromChars(v.data(), v.data() + v.size(), out);
        if (v.empty() || r.ec != std::errc() || r.ptr != v.data() + v.size())
            throw ParseError(m_path, m_line, column, "expected a number", std::string(s));
        if (!std::isfinite(out))
            throw ParseError(m_path, m_line, column, "numbers must be finite", std::string(s));
        return out;
    }
    double parseNumber(const Token& t) const { return parseNumber(t.text, t.column); }

    glm::dvec2 parsePoint(const Token& t) const {
        const auto comma = t.text.find(',');
        if (comma == std::string_view::npos)
            fail(t, "expected a point x,y");
        const double x = parseNumber(t.text.substr(0, comma), t.column);
        const double y =
            parseNumber(t.text.substr(comma + 1), t.column + static_cast<int>(comma) + 1);
        return {x, y};
    }

private:
    const std::string& m_path;
    int m_line;
};

std::vector<Token> tokenize(std::string_view line) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
            ++i;
        if (i >= line.size() || line[i] == '#')
            break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' &&
               line[i] != '#')
            ++i;
        out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return out;
}

void writeScalar(std::string& out, const char* key, double v, double def) {
    if (!sameBits(v, def))
        out += std::string(key) + " " + number(v) + "\n";
}

void writeVector(std::string& out, const char* key, glm::dvec3 v, glm::dvec3 def) {
    if (!sameBits(v, def))
        out += std::string(key) + " " + number(v.x) + " " + number(v.y) + " " + number(v.z) + "\n";
}

void writeCurve(std::string& out, const char* key, const Curve& c) {
    if (c.empty())
        return;
    out += key;
    for (const auto& p : c.points())
        out += " " + number(p.x) + "," + number(p.y);
    out += "\n";
}

} // namespace

std::string formatAdjustmentList(const Adjustments& a) {
    const Adjustments d;
    std::string out = "# lutkit adjustment list 1\n";
    writeScalar(out, "temperature", a.temperature, d.temperature);
    writeScalar(out, "tint", a.tint, d.tint);
    writeScalar(out, "exposure", a.exposure, d.exposure);
    writeScalar(out, "contrast", a.contrast, d.contrast);
    writeVector(out, "lift", a.lift, d.lift);
    writeScalar(out, "lift.master", a.liftMaster, d.liftMaster);
    writeVector(out, "gamma", a.gamma, d.gamma);
    writeScalar(out, "gamma.master", a.gammaMaster, d.gammaMaster);
    writeVector(out, "gain", a.gain, d.gain);
    writeScalar(out, "gain.master", a.gainMaster, d.gainMaster);
    writeScalar(out, "saturation", a.saturation, d.saturation);
    writeCurve(out, "curve.master", a.curveMaster);
    writeCurve(out, "curve.red", a.curveRed);
    writeCurve(out, "curve.green", a.curveGreen);
    writeCurve(out, "curve.blue", a.curveBlue);
    writeCurve(out, "hue.hue", a.hueVsHue);
    writeCurve(out, "hue.sat", a.hueVsSat);
    writeCurve(out, "hue.lum", a.hueVsLum);
    writeScalar(out, "strength", a.strength, d.strength);
    return out;
}

Adjustments parseAdjustmentList(std::string_view text, const std::string& path) {
    Adjustments a;
    std::set<std::string, std::less<>> seen;
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string_view line = text.substr(pos, end - pos);
        ++lineNo;
        pos = end + 1;
        const auto tokens = tokenize(line);
        if (tokens.empty())
            continue;
        const LineParser p(path, lineNo);
        const Token& key = tokens.front();
        const std::size_t args = tokens.size() - 1;
        if (!seen.insert(std::string(key.text)).second)
            p.fail(key, "this adjustment was already given");
        auto scalar = [&](double& field) {
            if (args != 1)
                p.fail(key, "expected one number after '" + std::string(key.text) + "'");
            field = p.parseNumber(tokens[1]);
        };
        auto vector = [&](glm::dvec3& field) {
            if (args != 3)
                p.fail(key, "expected three numbers (R G B) after '" + std::string(key.text) + "'");
            for (int c = 0; c < 3; ++c)
                field[c] = p.parseNumber(tokens[static_cast<std::size_t>(c) + 1]);
        };
        auto curve = [&](Curve& field, CurveKind kind) {
            std::vector<glm::dvec2> pts;
            for (std::size_t i = 1; i < tokens.size(); ++i)
                pts.push_back(p.parsePoint(tokens[i]));
            try {
                field = Curve(kind, std::move(pts));
            } catch (const ParseError&) {
                throw;
            } catch (const Error& e) {
                p.fail(key, e.what());
            }
        };
        const std::string_view k = key.text;
        if (k == "exposure")
            scalar(a.exposure);
        else if (k == "contrast")
            scalar(a.contrast);
        else if (k == "saturation")
            scalar(a.saturation);
        else if (k == "temperature")
            scalar(a.temperature);
        else if (k == "tint")
            scalar(a.tint);
        else if (k == "lift")
            vector(a.lift);
        else if (k == "lift.master")
            scalar(a.liftMaster);
        else if (k == "gamma")
            vector(a.gamma);
        else if (k == "gamma.master")
            scalar(a.gammaMaster);
        else if (k == "gain")
            vector(a.gain);
        else if (k == "gain.master")
            scalar(a.gainMaster);
        else if (k == "curve.master")
            curve(a.curveMaster, CurveKind::Tone);
        else if (k == "curve.red")
            curve(a.curveRed, CurveKind::Tone);
        else if (k == "curve.green")
            curve(a.curveGreen, CurveKind::Tone);
        else if (k == "curve.blue")
            curve(a.curveBlue, CurveKind::Tone);
        else if (k == "hue.hue")
            curve(a.hueVsHue, CurveKind::Hue);
        else if (k == "hue.sat")
            curve(a.hueVsSat, CurveKind::Hue);
        else if (k == "hue.lum")
            curve(a.hueVsLum, CurveKind::Hue);
        else if (k == "strength")
            scalar(a.strength);
        else
            p.fail(key, "unknown adjustment '" + std::string(k) + "'");
    }
    return a;
}

} // namespace lut
