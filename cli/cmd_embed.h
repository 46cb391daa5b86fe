#pragma once
// lutkit embed SCREENSHOT OUT: paste a neutral LUT patch with a marker frame into a screenshot.
#include <string>

namespace lut::cli {

struct EmbedOptions {
    std::string input;
    std::string output;
    std::string lattice; // "game-display" (default; alias "smash") or "uniform" (with --size)
    int size = 16;
    std::string layout; // "" = hald when size is a square, else pilot
    int scale = 2;
    std::string corner = "top-left";
    int margin = 8;
};

int runEmbed(const EmbedOptions& options);

} // namespace lut::cli
