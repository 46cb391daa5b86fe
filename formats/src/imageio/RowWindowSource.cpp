// SPDX-License-Identifier: Apache-2.0
#include "imageio/RowWindowSource.h"

#include "lut/Error.h"

#include <algorithm>

namespace lut::formats {

RowWindowSource::RowWindowSource(const std::string& path, std::string memory, std::string kind)
    : m_in(path, std::move(memory)), m_window(m_in), m_kind(std::move(kind)) {}

void RowWindowSource::fail(const std::string& what) const {
    throw Error(m_in.path() + ": " + what);
}

void RowWindowSource::readRows(int y0, int y1, void* dst) {
    const int h = m_info.height;
    const RowPlace place(static_cast<unsigned char*>(dst), rowBytes(m_info), y0, h, m_topDown);
    // File rows [a, b) hold image rows [y0, y1): the same rows top-down, mirrored bottom-up.
    const std::int64_t a = m_topDown ? y0 : h - y1, b = m_topDown ? y1 : h - y0;
    if (m_packed) {
        readPackedRows(a, b, place);
        return;
    }
    const std::int64_t perBlock =
        std::max<std::int64_t>(1, static_cast<std::int64_t>((std::size_t(1) << 20) / m_stride));
    for (std::int64_t r0 = a; r0 < b; r0 += perBlock) {
        const std::int64_t n = std::min(perBlock, b - r0);
        const std::size_t bytes = m_stride * static_cast<std::size_t>(n);
        m_block.resize(bytes);
        if (m_in.pread(m_block.data(), bytes,
                       m_dataStart + static_cast<std::uint64_t>(r0) * m_stride) != bytes)
            fail(m_kind + " pixel data ends early (the file was cut short while it was read)");
        for (std::int64_t i = 0; i < n; ++i)
            convertRow(m_block.data() + static_cast<std::size_t>(i) * m_stride, place(r0 + i),
                       r0 + i);
    }
}

} // namespace lut::formats
