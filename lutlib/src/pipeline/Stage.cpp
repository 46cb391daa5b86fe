// SPDX-License-Identifier: Apache-2.0
#include "lut/pipeline/Stage.h"
#include "lut/NumberText.h"

#include "lut/Error.h"
#include "lut/Parallel.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace lut {

std::string StageParam::valueString() const {
    if (!choices.empty()) {
        const auto i = static_cast<std::size_t>(value);
        return i < choices.size() ? choices[i] : std::string("?");
    }
    std::ostringstream os;
    os << value;
    return os.str();
}

Stage::~Stage() = default;

void Stage::process(const ImageView& frame, const StageContext& ctx) {
    if (frame.empty())
        return;
    if (needsPrepare())
        prepare(frame, ctx);
    // Small row blocks keep the work balanced; each block is written by exactly one thread.
    parallelFor(frame.height, ctx.nthreads,
                [&](int y0, int y1) { processRows(frame, y0, y1, ctx); });
    finish();
}

float Stage::param(std::string_view n) const {
    for (const auto& p : m_params)
        if (p.name == n)
            return p.value;
    throw Error(std::string("stage '") + name() + "' has no parameter '" + std::string(n) + "'");
}

void Stage::setParam(std::string_view n, float value) {
    for (std::size_t i = 0; i < m_params.size(); ++i) {
        StageParam& p = m_params[i];
        if (p.name != n)
            continue;
        if (!std::isfinite(value) || value < p.min || value > p.max) {
            std::ostringstream os;
            os << "stage '" << name() << "' parameter '" << p.name << "': value " << value
               << " is outside " << p.min << ".." << p.max;
            throw Error(os.str());
        }
        if (!p.choices.empty())
            value = std::round(value);
        p.value = value;
        *m_targets[i] = value;
        return;
    }
    throw Error(std::string("stage '") + name() + "' has no parameter '" + std::string(n) + "'");
}

void Stage::setParam(std::string_view n, std::string_view text) {
    for (const auto& p : m_params) {
        if (p.name != n)
            continue;
        if (!p.choices.empty()) {
            for (std::size_t c = 0; c < p.choices.size(); ++c)
                if (p.choices[c] == text)
                    return setParam(n, static_cast<float>(c));
            std::string list;
            for (const auto& c : p.choices)
                list += (list.empty() ? "" : "|") + c;
            throw Error(std::string("stage '") + name() + "' parameter '" + p.name + "': '" +
                        std::string(text) + "' is not one of " + list);
        }
        float v = 0.0f;
        const char* b = text.data();
        const char* e = text.data() + text.size();
        const auto r = fromChars(b, e, v);
        if (r.ec != std::errc() || r.ptr != e)
            throw Error(std::string("stage '") + name() + "' parameter '" + p.name + "': '" +
                        std::string(text) + "' is not a number");
        return setParam(n, v);
    }
    throw Error(std::string("stage '") + name() + "' has no parameter '" + std::string(n) + "'");
}

void Stage::copySettingsFrom(const Stage& other) {
    m_enabled = other.m_enabled;
    for (const auto& p : other.m_params)
        setParam(p.name, p.value);
}

void Stage::addParam(float* target, std::string n, float def, float min, float max,
                     std::string help) {
    StageParam p;
    p.name = std::move(n);
    p.help = std::move(help);
    p.value = p.defaultValue = def;
    p.min = min;
    p.max = max;
    *target = def;
    m_params.push_back(std::move(p));
    m_targets.push_back(target);
}

void Stage::addChoice(float* target, std::string n, std::vector<std::string> choices, int def,
                      std::string help) {
    StageParam p;
    p.name = std::move(n);
    p.help = std::move(help);
    p.value = p.defaultValue = static_cast<float>(def);
    p.min = 0.0f;
    p.max = static_cast<float>(choices.size() - 1);
    p.choices = std::move(choices);
    *target = p.value;
    m_params.push_back(std::move(p));
    m_targets.push_back(target);
}

} // namespace lut
