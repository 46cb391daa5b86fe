// SPDX-License-Identifier: Apache-2.0
#include "cube/ParallelRows.h"

#include "cube/CubeLexer.h"

#include "lut/Limits.h"
#include "lut/Parallel.h"

#include <cstring>
#include <vector>

namespace lut::formats::cube {

bool parallelRows(const char* begin, const char* end, std::size_t rows, const RowTarget& target) {
    const int chunks = resolveThreads(0);
    if (chunks < 2)
        return false;
    std::vector<const char*> cut(static_cast<std::size_t>(chunks) + 1);
    cut[0] = begin;
    cut[static_cast<std::size_t>(chunks)] = end;
    for (int i = 1; i < chunks; ++i) {
        const char* p = begin + (end - begin) * i / chunks;
        if (p < cut[static_cast<std::size_t>(i) - 1])
            p = cut[static_cast<std::size_t>(i) - 1];
        const auto* nl =
            static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
        cut[static_cast<std::size_t>(i)] = nl ? nl + 1 : end;
    }
    // Calls fn(start, lineEnd) for each non-blank line of chunk c (CR of CR LF removed); stops
    // and returns false when fn does or the line is not a plain data line.
    auto eachRow = [&](int c, auto&& fn) {
        const char* p = cut[static_cast<std::size_t>(c)];
        const char* e = cut[static_cast<std::size_t>(c) + 1];
        while (p < e) {
            const auto* nl =
                static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(e - p)));
            const char* le = nl ? nl : e;
            const char* next = nl ? nl + 1 : e;
            if (static_cast<std::size_t>(le - p) > limits::kMaxTextLineBytes)
                return false;
            if (le > p && le[-1] == '\r')
                --le;
            const char* s = skipSpace(p, le);
            if (s != le) {
                if (*s == '#' || isAlpha(*s))
                    return false;
                if (!fn(s, le))
                    return false;
            }
            p = next;
        }
        return true;
    };
    std::vector<std::size_t> count(static_cast<std::size_t>(chunks), 0);
    std::vector<char> ok(static_cast<std::size_t>(chunks), 1);
    parallelFor(chunks, chunks, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            std::size_t n = 0;
            // A chunk with more rows than the whole table stops at once (a file with a billion
            // rows is not scanned to its end).
            ok[static_cast<std::size_t>(c)] =
                eachRow(c, [&](const char*, const char*) { return ++n <= rows; });
            count[static_cast<std::size_t>(c)] = n;
        }
    });
    std::vector<std::size_t> first(static_cast<std::size_t>(chunks), 0);
    std::size_t total = 0;
    for (int c = 0; c < chunks; ++c) {
        if (!ok[static_cast<std::size_t>(c)])
            return false;
        first[static_cast<std::size_t>(c)] = total;
        total += count[static_cast<std::size_t>(c)];
    }
    if (total != rows)
        return false;
    parallelFor(chunks, chunks, [&](int c0, int c1) {
        for (int c = c0; c < c1; ++c) {
            std::size_t r = first[static_cast<std::size_t>(c)];
            ok[static_cast<std::size_t>(c)] = eachRow(
                c, [&](const char* s, const char* le) { return fastRow(s, le, target.row(r++)); });
        }
    });
    for (char c : ok)
        if (!c)
            return false;
    return true;
}

} // namespace lut::formats::cube
