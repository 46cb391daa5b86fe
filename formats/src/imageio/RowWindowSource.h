// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to formats: the ImageSource of a file whose pixel rows lie one after another from a
// start offset, top-down or bottom-up, either raw (a fixed number of bytes a row, read where they
// lie in blocks of at most 1 MiB) or packed (a run-length stream the codec decodes): BMP and TGA.
// The codec reads the header in its constructor, sets the fields below, and converts a stored
// row to the image's samples; readRows maps the image's rows to the file's and back.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace lut::formats {

class RowWindowSource : public ImageSource {
public:
    void readRows(int y0, int y1, void* dst) final;

protected:
    // kind names the format in messages ("BMP", "TGA").
    RowWindowSource(const std::string& path, std::string memory, std::string kind);

    // Where the image row of file row r goes, for a readRows(y0, y1, dst) call.
    class RowPlace {
    public:
        RowPlace(unsigned char* out, std::size_t rowBytes, int y0, int height, bool topDown)
            : m_out(out), m_rowBytes(rowBytes), m_y0(y0), m_height(height), m_topDown(topDown) {}
        unsigned char* operator()(std::int64_t r) const {
            const std::int64_t y = m_topDown ? r : m_height - 1 - r;
            return m_out + static_cast<std::size_t>(y - m_y0) * m_rowBytes;
        }

    private:
        unsigned char* m_out;
        std::size_t m_rowBytes;
        int m_y0, m_height;
        bool m_topDown;
    };

    // A raw stored row (file row r, m_stride bytes at s) to the image's samples at out.
    virtual void convertRow(const unsigned char* s, unsigned char* out, std::int64_t r) = 0;
    // A packed file: decodes file rows [a, b), each to place(r).
    virtual void readPackedRows(std::int64_t a, std::int64_t b, const RowPlace& place) = 0;

    [[noreturn]] void fail(const std::string& what) const;

    ByteReader m_in;
    ByteWindow m_window;
    bool m_packed = false;         // readPackedRows, else raw rows
    bool m_topDown = false;        // file row 0 is the image's top row (else its bottom row)
    std::uint64_t m_dataStart = 0; // the first file row's offset (a raw file)
    std::size_t m_stride = 0;      // the bytes of a raw file row

private:
    std::string m_kind;
    UninitBytes m_block;
};

} // namespace lut::formats
