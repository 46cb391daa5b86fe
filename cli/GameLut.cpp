#include "GameLut.h"

#include "LutFiles.h"

#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"

#include <algorithm>
#include <memory>

namespace lut::cli {

Lut3D makeGameLut(const Lut3D& edit, const GameLutRequest& q, const Verbosity& v, std::ostream& os,
                  SmashAuthoringResult* out) {
    LutFile file;
    file.cube = edit;
    return makeGameLut(file, q, v, os, out);
}

Lut3D makeGameLut(const LutFile& edit, const GameLutRequest& q, const Verbosity& v,
                  std::ostream& os, SmashAuthoringResult* out) {
    SmashAuthoringOptions o;
    Lut3D stage;
    if (!q.stageLut.empty()) {
        stage = readStageLut(q.stageLut, v);
        o.gameLut = &stage;
    }
    Image shot;
    ImageView view;
    if (!q.screenshot.empty()) {
        shot = formats::readImage(q.screenshot).image;
        view = shot.view();
        o.screenshot = &view;
    }
    o.refine = true; // always measured: the report says what --refine gives
    if (!edit.cube && !edit.shaper)
        throw Error("the edit holds no table");
    const std::string title = edit.cube ? edit.cube->title() : edit.shaper->title();
    SmashAuthoringResult r;
    if (!edit.shaper) {
        r = authorSmashLutForEdit(*edit.cube, q.interp, o);
    } else {
        // The shaper, then the table, at every colour the authoring evaluates.
        const std::shared_ptr<const Sampler> exact = makeSampler(edit, q.interp);
        r = authorSmashLutForEdit([exact](glm::vec3 c) { return exact->sample(c); }, o);
        r.exact.setTitle(title);
        r.lut.setTitle(title);
    }
    const std::string stageText = q.stageLut.empty() ? "neutral" : q.stageLut;
    os << "game     the LUT that makes Smash Ultimate show this edit of its own picture (stage "
          "LUT: "
       << stageText << "; the edit evaluated " << toString(q.interp) << ", entries rounded to "
       << "nearest)\n";
    os << "in game  what the game shows with the 8-bit LUT vs the edited colours, over "
       << r.measuredOver << ":\n";
    os << "         exact composition:       " << r.exactError.str()
       << (q.refine ? "" : "  (written)") << "\n";
    os << "         least-squares refinement: " << r.refinedError.str()
       << (q.refine ? "  (written)" : "  (--refine writes it)") << "\n";
    if (r.clampedEntries > 0)
        os << "clamped  " << r.clampedEntries << " values the game cannot reach (up to "
           << r.clampedMax * 255.0 << " 8-bit steps outside [0,1])\n";
    (void)v;
    Lut3D lut = q.refine ? r.lut : r.exact;
    if (!q.refine)
        for (auto& e : lut.entries())
            for (int c = 0; c < 3; ++c)
                e[c] = std::min(1.0f, std::max(0.0f, e[c]));
    lut.setTitle(title);
    if (out)
        *out = std::move(r);
    return lut;
}

} // namespace lut::cli
