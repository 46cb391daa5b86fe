// SPDX-License-Identifier: Apache-2.0
#include "Suggest.h"

#include <algorithm>

namespace lut::cli {

int editDistance(const std::string& a, const std::string& b) {
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
    for (std::size_t i = 0; i <= n; ++i)
        d[i][0] = static_cast<int>(i);
    for (std::size_t j = 0; j <= m; ++j)
        d[0][j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[n][m];
}

std::optional<std::string> closestWord(const std::string& word,
                                       const std::vector<std::string>& candidates) {
    if (word.empty())
        return std::nullopt;
    std::vector<std::string> prefixed;
    for (const auto& c : candidates)
        if (c.size() > word.size() && c.compare(0, word.size(), word) == 0)
            prefixed.push_back(c);
    if (prefixed.size() == 1)
        return prefixed.front();
    const int limit = std::clamp(static_cast<int>(word.size()) / 3, 1, 3);
    int best = limit + 1;
    std::optional<std::string> found;
    for (const auto& c : candidates) {
        const int d = editDistance(word, c);
        if (d < best) {
            best = d;
            found = c;
        }
    }
    return found;
}

} // namespace lut::cli
