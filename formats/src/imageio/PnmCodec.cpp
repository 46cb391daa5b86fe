// SPDX-License-Identifier: Apache-2.0
// Binary PNM, natively: P5 (grey) and P6 (RGB), maxval 1..65535 (16-bit samples big-endian),
// the netpbm definition (http://netpbm.sourceforge.net/doc/ppm.html). A header of three numbers
// with '#' comments; rows follow uncompressed, so the file size is checked against the header
// before a row is read. Other maxvals than 255 and 65535 are scaled to 8 or 16 bits on read, as
// OpenImageIO does. ASCII PNM (P1-P3) and PAM go through OpenImageIO.
#include "imageio/ByteIO.h"
#include "imageio/ImageCodec.h"

#include "lut/Error.h"

#include <cctype>
#include <cstring>
#include <vector>

namespace lut::formats {

namespace {

class PnmSource : public ImageSource {
public:
    PnmSource(const std::string& path, std::string memory) : m_in(path, std::move(memory)) {
        const std::string head = m_in.head(1024);
        std::size_t i = 0;
        if (head.size() < 3 || head[0] != 'P' || (head[1] != '5' && head[1] != '6'))
            throw Error(path + ": not a binary PNM file (P5 or P6)");
        const int ch = head[1] == '6' ? 3 : 1;
        i = 2;
        long v[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            for (;;) { // blanks and comments
                while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i])))
                    ++i;
                if (i < head.size() && head[i] == '#') {
                    while (i < head.size() && head[i] != '\n')
                        ++i;
                    continue;
                }
                break;
            }
            if (i >= head.size() || !std::isdigit(static_cast<unsigned char>(head[i])))
                throw Error(path + ": bad PNM header (expected width, height and maxval)");
            while (i < head.size() && std::isdigit(static_cast<unsigned char>(head[i])) &&
                   v[k] < (1L << 30))
                v[k] = v[k] * 10 + (head[i++] - '0');
        }
        if (i >= head.size() || !std::isspace(static_cast<unsigned char>(head[i])))
            throw Error(path + ": bad PNM header (no blank after maxval)");
        m_dataStart = i + 1;
        if (v[2] < 1 || v[2] > 65535)
            throw Error(path + ": PNM maxval " + std::to_string(v[2]) + " is outside 1..65535");
        m_maxval = static_cast<int>(v[2]);
        checkImageSize(path, static_cast<int>(v[0]), static_cast<int>(v[1]), ch);
        m_info.width = static_cast<int>(v[0]);
        m_info.height = static_cast<int>(v[1]);
        m_info.channels = ch;
        m_info.format = "pnm";
        m_info.type = m_maxval > 255 ? PixelType::UInt16 : PixelType::UInt8;
        m_info.bitDepth = m_info.bitsPerSample = m_maxval > 255 ? 16 : 8;
        m_info.compression = "none";
        m_info.channelNames =
            ch == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
        const std::uint64_t need = m_dataStart + static_cast<std::uint64_t>(rowBytes(m_info)) *
                                                     static_cast<std::uint64_t>(m_info.height);
        if (m_in.size() < need)
            throw Error(path + ": PNM file is " + std::to_string(m_in.size()) +
                        " bytes, its header needs " + std::to_string(need) +
                        " (truncated or corrupt)");
        auto meta = std::make_shared<ImageMetadata>();
        meta->format = "pnm";
        m_metadata = meta;
    }

    void readRows(int y0, int y1, void* dst) override {
        const std::size_t rb = rowBytes(m_info);
        const std::size_t n = rb * static_cast<std::size_t>(y1 - y0);
        if (m_in.pread(dst, n, m_dataStart + rb * static_cast<std::uint64_t>(y0)) != n)
            throw Error(m_in.path() + ": PNM file ends early (truncated)");
        const std::size_t samples = n / static_cast<std::size_t>(bytesPerSample(m_info.type));
        if (m_info.type == PixelType::UInt16) {
            auto* p = static_cast<unsigned char*>(dst);
            for (std::size_t k = 0; k < samples; ++k) { // big-endian on disk
                const unsigned v = (unsigned(p[2 * k]) << 8) | p[2 * k + 1];
                const unsigned s = m_maxval == 65535 ? v : (v * 65535u + m_maxval / 2) / m_maxval;
                const std::uint16_t o = static_cast<std::uint16_t>(s > 65535u ? 65535u : s);
                std::memcpy(p + 2 * k, &o, 2);
            }
        } else if (m_maxval != 255) {
            auto* p = static_cast<unsigned char*>(dst);
            for (std::size_t k = 0; k < samples; ++k) {
                const unsigned s = (unsigned(p[k]) * 255u + m_maxval / 2) / m_maxval;
                p[k] = static_cast<unsigned char>(s > 255u ? 255u : s);
            }
        }
    }

private:
    ByteReader m_in;
    std::uint64_t m_dataStart = 0;
    int m_maxval = 255;
};

class PnmSink : public ImageSink {
public:
    PnmSink(const OutputTarget& target, const SinkSpec& spec) : m_out(target, false), m_spec(spec) {
        const std::size_t ch = spec.channelNames.size();
        if (ch != 1 && ch != 3)
            throw Error(target.path + ": PNM stores grey or RGB (1 or 3 channels), not " +
                        std::to_string(ch));
        if (spec.type != PixelType::UInt8 && spec.type != PixelType::UInt16)
            throw Error(target.path + ": PNM stores 8 or 16 bits per channel, not " +
                        std::string(toString(spec.type)));
        const std::string head = std::string(ch == 3 ? "P6\n" : "P5\n") +
                                 std::to_string(spec.width) + " " + std::to_string(spec.height) +
                                 "\n" + (spec.type == PixelType::UInt16 ? "65535" : "255") + "\n";
        m_out.write(head.data(), head.size());
        m_rowBytes = static_cast<std::size_t>(spec.width) * ch *
                     static_cast<std::size_t>(bytesPerSample(spec.type));
    }
    void writeRows(int y0, int y1, const void* src) override {
        const std::size_t n = m_rowBytes * static_cast<std::size_t>(y1 - y0);
        if (m_spec.type == PixelType::UInt8) {
            m_out.write(src, n);
            return;
        }
        m_swap.resize(n);
        const auto* s = static_cast<const unsigned char*>(src);
        for (std::size_t i = 0; i < n; i += 2) {
            m_swap[i] = s[i + 1];
            m_swap[i + 1] = s[i];
        }
        m_out.write(m_swap.data(), n);
    }
    void finish() override { m_out.commit(); }

private:
    ByteWriter m_out;
    SinkSpec m_spec;
    std::size_t m_rowBytes = 0;
    std::vector<unsigned char> m_swap;
};

} // namespace

std::unique_ptr<ImageSource> openPnmSource(const std::string& path, std::string memory) {
    return std::make_unique<PnmSource>(path, std::move(memory));
}

std::unique_ptr<ImageSink> createPnmSink(const OutputTarget& target, const SinkSpec& spec) {
    return std::make_unique<PnmSink>(target, spec);
}

} // namespace lut::formats
