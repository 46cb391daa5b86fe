// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numbered frame sequences, spelled as oiiotool and ffmpeg spell them:
//   frame.%04d.exr   printf style: %0Nd pads to N digits, %d does not pad (ffmpeg, oiiotool)
//   frame.#.exr      one # is 4 digits (oiiotool); a run of 2 or more # is one digit per #
//   frame.####.exr   (frame.####.exr = 4 digits, as Nuke, RV and most tools read it)
//   frame.@@@.exr    one digit per @ (oiiotool)
// and frame ranges as oiiotool's --frames takes them: "1-100", "100-1", "1-100x2" (every 2nd),
// "1-10y3" (the frames "x3" leaves out), and lists "1,3,7-9". A path that names an existing file
// is that file, even if it contains '#', '@' or '%'.
#include <optional>
#include <string>
#include <vector>

namespace lut {

struct FramePattern {
    std::string prefix;
    std::string suffix;
    int padding = 0; // digits, zero-padded; 0 = not padded (%d)

    std::string path(long frame) const; // prefix + number + suffix
    // The frame number a file name (the whole path) stands for, if it matches.
    std::optional<long> frameOf(const std::string& path) const;
};

// The pattern in path, or nullopt when path has no frame placeholder (or names an existing
// file). Throws lut::Error for a path with two placeholders.
std::optional<FramePattern> parseFramePattern(const std::string& path);

// Frame numbers from oiiotool's range syntax, in the order given. Throws lut::Error naming the
// text for anything else (and for more than 10 million frames).
std::vector<long> parseFrameRange(const std::string& text);

// The frames of pattern present in its folder (regular files, sorted).
std::vector<long> findFrames(const FramePattern& pattern);

// The frames between the first and last of sorted `frames` that are absent ("" if none):
// "5, 9-11".
std::string missingFrames(const std::vector<long>& sortedFrames);
// "1-3, 7" for a sorted list.
std::string describeFrames(const std::vector<long>& sortedFrames);

} // namespace lut
