// SPDX-License-Identifier: Apache-2.0
#pragma once
// "Did you mean": the known word closest to a typo.
#include <optional>
#include <string>
#include <vector>

namespace lut::cli {

// Optimal string alignment distance (insertions, deletions, substitutions and transpositions of
// neighbours each cost 1): "nuetral" -> "neutral" is 1.
int editDistance(const std::string& a, const std::string& b);

// The candidate a user most likely meant by `word`: the unique one it is a prefix of, else the
// nearest by edit distance when that is at most a third of the word (at least 1, at most 3).
// nullopt when nothing is close.
std::optional<std::string> closestWord(const std::string& word,
                                       const std::vector<std::string>& candidates);

} // namespace lut::cli
