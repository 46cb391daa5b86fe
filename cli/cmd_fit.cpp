#include "cmd_fit.h"

#include "Commands.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/roundtrip/Fit.h"

#include <cstdio>
#include <iostream>

namespace lut::cli {

int runFit(const FitOptions& o) {
    checkNotSameFile(o.before, o.output); // never overwrite an input (issue 7)
    checkNotSameFile(o.after, o.output);
    auto before = formats::readImage(o.before);
    auto after = formats::readImage(o.after);
    lut::FitOptions fo;
    fo.size = o.size;
    fo.smoothness = o.smoothness;
    fo.robust = !o.noRobust;
    FitResult res = fitLut(before.image.view(), after.image.view(), fo);
    for (const auto& d : res.diagnostics)
        std::cerr << "lutkit: " << d.str() << "\n";
    char buf[400];
    std::snprintf(
        buf, sizeof buf,
        "fit %d^3 to %zu pixels (%zu distinct colours): error rms %.3g, max %.3g 8-bit steps; "
        "%.3g%% of the cube extrapolated; %zu outlier pixels\n",
        o.size, res.pixels, res.distinctColours, res.rmsSteps8, res.maxSteps8,
        100.0 * res.extrapolatedShare, res.outlierPixels);
    std::cout << buf;
    LutFile file;
    file.cube = std::move(res.lut);
    FormatOptions wo;
    wo.layout = layoutOption("--layout", o.layout);
    const Diagnostics wd = formats::writeLut(o.output, file, wo, o.format);
    for (const auto& d : wd)
        std::cerr << "lutkit: " << d.str() << "\n";
    std::cout << "wrote " << o.output << "\n";
    return kExitOk;
}

} // namespace lut::cli
