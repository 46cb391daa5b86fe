#pragma once
// The screenshot round trip: paste a neutral LUT patch with a self-describing marker frame into a
// screenshot, let the modder grade it in any editor, then find the patch again and turn what the
// editor did to it into a LUT. Works on lut::Image (no file I/O); see docs/roundtrip.md.
//
// The marker frame (two cells wide around the patch, one cell = scale x scale pixels):
//  - outer ring: a checkerboard of two symbols, white and black;
//  - inner ring: a 34-bit header (sync word, bit depth, layout, size, scale, CRC-8) written
//    clockwise from the top-left inner corner and repeated.
// Detection never looks at absolute levels: a symbol is "the colour of the even outer cells" or
// "the colour of the odd outer cells", whatever the edit made of white and black. Any per-pixel
// global edit (curves, levels, inversion, gradient maps, channel mixing) keeps equal pixels equal
// and so keeps the pattern; only an edit that maps white and black to the same colour destroys it.
#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/Image.h"
#include "lut/Lut3D.h"
#include "lut/io/Layout.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lut {

// Which inputs the patch samples per channel.
//  - Uniform: j/(N-1), the lattice of an N^3 LUT (what raw engines use).
//  - Smash: the 12 display values the unedited game shows for its lattice inputs i/15 (with a
//    neutral stage LUT): srgbEncode(min(1, (1.3703 i/15)^2.2)), i = 0..10, and 1 (i >= 11 all clip
//    to white). Extracting for --target smash then reads the edit exactly where the game's 16^3
//    LUT needs it instead of interpolating: docs/roundtrip.md has the numbers.
enum class PatchLattice { Uniform, Smash };
const char* toString(PatchLattice);
PatchLattice parseLattice(std::string_view name); // "uniform", "smash"
constexpr int kSmashLatticeSize = 12;

// The default patch is the Smash lattice (12^3, pilot layout, 2x2 pixels per entry: 296x32
// pixels with its frame); with a uniform lattice the default size is 16 (the game's and Pilot's
// lattice, 8-bit exact since 255/15 = 17) as a 64x64 Hald image.
constexpr int kDefaultPatchSize = 16;
constexpr int kDefaultPatchScale = 2;
constexpr int kDefaultPatchMargin = 8; // pixels between the frame and the screenshot's edge
constexpr int kMaxPatchScale = 31;     // five header bits

enum class PatchCorner { TopLeft, TopRight, BottomLeft, BottomRight };
const char* toString(PatchCorner);
// "top-left", "top-right", "bottom-left", "bottom-right"; throws lut::Error.
PatchCorner parseCorner(std::string_view name);

// Where a patch sits, in pixels of the image it was found in or drawn into.
struct PatchPlacement {
    PatchLattice lattice = PatchLattice::Uniform;
    LutLayout layout = LutLayout::Hald;
    int size = 0;     // N
    int scale = 1;    // pixels per entry (edge of the square block) as embedded
    int cell = 1;     // pixels per entry as found (== scale unless the image was upscaled)
    int bitDepth = 8; // what the patch values were quantised to when embedded (8, 16, 32)
    int frameX = 0;   // top-left pixel of the marker frame
    int frameY = 0;
    int frameWidth = 0; // frame size in pixels
    int frameHeight = 0;
    int patchX() const { return frameX + 2 * cell; }
    int patchY() const { return frameY + 2 * cell; }
};

// Frame size in pixels of a patch (throws lut::Error for unsupported combinations: the header
// needs a patch at least 19 entries wide, i.e. N >= 5 for strips and N >= 9 for Hald).
void patchFrameSize(LutLayout layout, int size, int scale, int& width, int& height);

struct EmbedOptions {
    PatchLattice lattice = PatchLattice::Smash;
    int size = kDefaultPatchSize;    // uniform lattice only (the smash lattice is 12^3)
    std::optional<LutLayout> layout; // default: hald when N is a square, else pilot
    int scale = kDefaultPatchScale;
    PatchCorner corner = PatchCorner::TopLeft;
    int margin = kDefaultPatchMargin;
    int bitDepth =
        8; // the bit depth the image will be written at: patch values are quantised to it
};
LutLayout defaultPatchLayout(int size);

// The input value a patch lattice index stands for once stored at bitDepth: j/(N-1) (or the
// Smash lattice value) rounded to the nearest 8- or 16-bit step (exact for 32).
float patchInputValue(PatchLattice lattice, int index, int size, int bitDepth);
float patchInputValue(int index, int size, int bitDepth); // uniform

// Draws the frame and the neutral patch into `image` (in place). Throws lut::Error if it does
// not fit.
PatchPlacement embedPatch(const ImageView& image, const EmbedOptions& options);

// --- Finding ---------------------------------------------------------------------------------

enum class FindStatus { Found, NotFound, Scaled };
struct FindResult {
    FindStatus status = FindStatus::NotFound;
    PatchPlacement placement;
    // Scaled: the marker's observed cell period in pixels (not a whole number); Found: cell/scale.
    double observedPeriod = 0.0;
    std::string message; // why it was not found / how it looks scaled
};
// Searches the whole image (the patch may have been moved or the image cropped by whole pixels).
FindResult findPatch(const ImageView& image);

// --- Extracting ------------------------------------------------------------------------------

enum class ExtractTarget { Raw, Smash };
const char* toString(ExtractTarget);
ExtractTarget parseTarget(std::string_view name);

// The warnings extract can give, each with a test that triggers it.
enum class RoundtripWarning {
    NonGlobalEdit, // blocks not uniform / entries a smooth global edit cannot give
    ProfileChange, // greys follow a pure gamma / sRGB<->2.2 curve: a colour-profile conversion?
    Clipping,      // many entries at 0 or 1
    Rescaled,      // the image was upscaled by a whole number (read anyway)
    OutOfRange,    // smash: entries the game cannot reach, clamped
    LowCoverage,   // fit: the pixels cover little of the cube
    FewColours,    // fit: too few distinct colours for a 3D fit
    Outliers,      // fit: pixels the robust fit down-weighted
};
const char* toString(RoundtripWarning);

struct ExtractOptions {
    ExtractTarget target = ExtractTarget::Raw;
    const Lut3D* originalLut = nullptr; // smash: the stage's LUT the screenshot was taken with
    int outputSize = 0;                 // 0: 16, or the patch size for a uniform patch and raw
    int nthreads = 0;
};

// What the patch says before any target is applied.
struct PatchReading {
    PatchPlacement placement;
    Lut3D values; // the edit E at the patch lattice, entry (r,g,b) = E(axis[r], axis[g], axis[b])
    std::vector<float> axis;        // input value of each lattice index (quantised neutral values)
    double blockMaxDeviation = 0.0; // largest pixel deviation from its block mean (8-bit steps)
    std::size_t nonUniformBlocks = 0; // blocks with a deviation above 2.5 8-bit steps
};
PatchReading readPatch(const ImageView& image, const PatchPlacement& placement);

// Evaluates the edit the patch measured at any input: tetrahedral interpolation on the patch's
// (rectilinear, possibly quantised) lattice, clamped to the patch's input range.
class PatchFunction {
public:
    PatchFunction(const Lut3D& values, std::vector<float> axis);
    glm::vec3 operator()(glm::vec3 in) const;

private:
    void locate(float v, int& i, float& f) const;
    Lut3D m_values;
    std::vector<float> m_axis;
};

struct ExtractResult {
    Lut3D lut;
    PatchPlacement placement;
    Diagnostics diagnostics;
    std::vector<RoundtripWarning> warnings;
    bool has(RoundtripWarning w) const;

    // Sub-lattice check: the patch's even lattice points predict the odd ones (spacing 2h);
    // between lattice points at spacing h the error is expected to be about a quarter of this.
    ErrorStats subLatticeError;
    ErrorStats expectedError; // subLatticeError / 4: the interpolation error at the patch spacing
    // Smash: what the game shows with the written (8-bit) LUT vs the edited look, on probes
    // between the 16^3 lattice points, display-encoded (8-bit steps via maxSteps8()).
    ErrorStats gameError;
    std::size_t clampedEntries = 0; // smash: channel values that needed L outside [0,1]
    double clampedMax = 0.0;        // ... and the farthest one (in [0,1] units)
    std::size_t clippedValues = 0;  // channel values at 0 or 1 that were not 0 or 1 in the neutral
    std::size_t suspiciousEntries = 0; // entries no smooth or piecewise-smooth edit explains
    double gamma = 1.0;                // fitted grey-axis exponent
};

// Finds the patch (throws lut::Error when not found or scaled by a non-integer factor), reads it,
// checks it and builds the LUT for the target.
ExtractResult extractLut(const ImageView& edited, const ExtractOptions& options);
// The same from an already read patch.
ExtractResult extractLut(const PatchReading& patch, const ExtractOptions& options);

} // namespace lut
