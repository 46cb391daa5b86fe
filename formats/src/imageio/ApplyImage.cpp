// SPDX-License-Identifier: Apache-2.0
// applyToImage (lut/formats/ApplyImage.h): read, compute and write overlapped, chunk by chunk.
//
//   reader thread   decodes chunk i+2 into a free slot
//   compute threads run chunk i+1 through the chain in runs of kRun pixels (stored type -> float
//                   RGBA -> chain -> output type; extra channels copied as they are)
//   calling thread  encodes chunk i, in order, then frees its slot
//
// A run's result depends only on its pixels, so any chunk size and any number of threads give
// the same bytes as one chunk on one thread (tests/formats/test_apply_image.cpp checks it).
#include "lut/formats/ApplyImage.h"

#include "imageio/ImageCodec.h"
#include "imageio/PixelConvert.h"

#include "lut/Parallel.h"
#include "lut/formats/ImageFiles.h"
#include "lut/io/OutputPolicy.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>
#include <vector>

namespace lut::formats {

namespace {

constexpr std::size_t kRun = 2048; // pixels per run: 32 KiB of float RGBA, in L1/L2
constexpr int kSlots = 4;

struct Plan {
    ImageInfo in, out;
    RgbaMap inMap, outMap;
    std::vector<std::pair<int, int>> extras; // channel in -> channel out, copied as they are
    bool unchanged = false;                  // stored values copied, the chain skipped
    // Whether the chain's LUT can see a value outside its domain: not when the input is integer
    // (R, G, B in [0, 1]) and nothing runs before a LUT whose domain holds [0, 1] (a pass over
    // every pixel saved: 6% of an 8-bit apply's time).
    bool checkDomain = true;
    // Whether an integer output type can clamp a value: not when integer input leaves the chain
    // in [0, 1] (PixelChain::unitInputGivesUnitOutput; another pass saved).
    bool checkClamp = true;
};

// What the chain saw outside the LUT's domain, and the values outside [0,1] an integer output
// type clamps.
struct ChunkStats {
    DomainStats domain, clamped;
    void merge(const ChunkStats& o) {
        domain.merge(o.domain);
        clamped.merge(o.clamped);
    }
};

void computeChunk(const Plan& p, const PixelChain& chain, const unsigned char* src,
                  unsigned char* dst, std::size_t pixels, ChunkStats& stats) {
    const bool countClamped =
        p.checkClamp && (p.out.type == PixelType::UInt8 || p.out.type == PixelType::UInt16);
    // Half a step of the output type beyond [0,1]: what rounding alone maps to 0 or the top code,
    // so only values the clamp changes are counted.
    const float half = p.out.type == PixelType::UInt8 ? 0.5f / 255.0f : 0.5f / 65535.0f;
    const std::size_t inPix = static_cast<std::size_t>(p.in.channels * bytesPerSample(p.in.type));
    const std::size_t outPix =
        static_cast<std::size_t>(p.out.channels * bytesPerSample(p.out.type));
    thread_local std::vector<float> rgba;
    rgba.resize(4 * kRun);
    for (std::size_t at = 0; at < pixels; at += kRun) {
        const std::size_t n = std::min(kRun, pixels - at);
        const unsigned char* s = src + at * inPix;
        unsigned char* d = dst + at * outPix;
        toRgba(s, p.in.type, p.in.channels, p.inMap, n, rgba.data());
        chain.run(rgba.data(), n, p.checkDomain ? &stats.domain : nullptr);
        if (countClamped)
            countOutsideDomain(rgba.data(), n, glm::vec3(-half), glm::vec3(1.0f + half),
                               stats.clamped);
        for (const auto& [ci, co] : p.extras)
            copyChannel(s, p.in.type, p.in.channels, ci, d, p.out.type, p.out.channels, co, n);
        fromRgba(rgba.data(), n, d, p.out.type, p.out.channels, p.outMap);
    }
}

int channelIndex(const std::vector<std::string>& names, const std::string& n) {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == n)
            return static_cast<int>(i);
    return -1;
}

} // namespace

namespace {

// What one part (an image, a subimage, a MIP level) of the input becomes in the output.
Plan planPart(const ImageInfo& in, const std::string& outFormat, const PixelChain& chain,
              const ApplyImageOptions& o, SinkSpec& spec, Diagnostics& diagnostics) {
    Plan p;
    p.in = in;
    p.inMap = rgbaMapOf(p.in);
    const RenderedLayout layout = appliedImageLayout(p.in, outFormat, o.bitDepth);
    diagnostics = layout.diagnostics;
    const std::string fmt = canonicalImageFormat(outFormat);
    spec.width = p.in.width;
    spec.height = p.in.height;
    spec.channelNames = layout.channelNames;
    spec.alphaChannel = channelIndex(layout.channelNames, "A");
    spec.type = layout.type;
    spec.bitsPerSample = layout.bitsPerSample;
    spec.compression = !o.compression.empty() ? o.compression : layout.keepCompression;
    spec.mipLevel = p.in.mipLevel;
    // Tiles where the file had them and the output has tiles too (OpenEXR, TIFF).
    if (p.in.tileWidth > 0 && (fmt == "openexr" || fmt == "tiff")) {
        spec.tileWidth = p.in.tileWidth;
        spec.tileHeight = p.in.tileHeight;
    }
    p.out = p.in;
    p.out.channels = static_cast<int>(spec.channelNames.size());
    p.out.channelNames = spec.channelNames;
    p.out.alphaChannel = spec.alphaChannel;
    p.out.type = spec.type;
    p.outMap = rgbaMapOf(p.out);
    const bool greyIn = p.inMap.r == p.inMap.g && p.inMap.g == p.inMap.b;
    for (std::size_t co = 0; co < spec.channelNames.size(); ++co) {
        const std::string& n = spec.channelNames[co];
        if (n == "R" || n == "G" || n == "B" || n == "A" || (greyIn && n == "Y"))
            continue;
        const int ci = channelIndex(p.in.channelNames, n);
        if (ci >= 0)
            p.extras.emplace_back(ci, static_cast<int>(co));
    }
    const bool integerIn = p.in.type == PixelType::UInt8 || p.in.type == PixelType::UInt16;
    p.unchanged = chain.isIdentityOnUnitRange() && integerIn && p.out.type == p.in.type &&
                  p.out.channelNames == p.in.channelNames && p.in.channelNames.size() > 0;
    p.checkDomain = !(integerIn && chain.unitInputStaysInDomain());
    p.checkClamp = !(integerIn && chain.unitInputGivesUnitOutput());
    return p;
}

// Rows per chunk for a part: a multiple of both codecs' blocks of rows.
int chunkRowsFor(const Plan& p, int srcGranularity, int sinkGranularity,
                 const ApplyImageOptions& o) {
    const int gran =
        std::min(1 << 16, std::lcm(std::max(1, srcGranularity), std::max(1, sinkGranularity)));
    const int byWidth = std::max(1, (1 << 17) / std::max(1, p.in.width));
    int rows = o.rowsPerChunk > 0 ? o.rowsPerChunk : std::max(gran, byWidth / gran * gran);
    if (o.rowsPerChunk > 0 && rows % gran != 0)
        rows = (rows / gran + 1) * gran;
    return std::min(rows, p.in.height);
}

// One part through the chain, read, computed and written overlapped when asked.
void streamPart(ImageSource& src, ImageSink& sink, const Plan& p, const PixelChain& chain,
                const ApplyImageOptions& o, ChunkStats& total) {
    const int rows = chunkRowsFor(p, src.rowGranularity(), sink.rowGranularity(), o);
    const int chunks = (p.in.height + rows - 1) / rows;
    const std::size_t inRow = rowBytes(p.in), outRow = rowBytes(p.out);

    std::mutex m;
    auto rowsOf = [&](int c) { return std::min(rows, p.in.height - c * rows); };
    const bool threaded = o.overlap && chunks > 1 && threadsAvailable();
    if (!threaded) {
        std::vector<unsigned char> inBuf(inRow * static_cast<std::size_t>(rows));
        std::vector<unsigned char> outBuf(p.unchanged ? 0
                                                      : outRow * static_cast<std::size_t>(rows));
        for (int c = 0; c < chunks; ++c) {
            const int y0 = c * rows, n = rowsOf(c);
            src.readRows(y0, y0 + n, inBuf.data());
            if (!p.unchanged)
                computeChunk(p, chain, inBuf.data(), outBuf.data(),
                             static_cast<std::size_t>(p.in.width) * static_cast<std::size_t>(n),
                             total);
            sink.writeRows(y0, y0 + n, p.unchanged ? inBuf.data() : outBuf.data());
        }
        return;
    }
    struct Slot {
        std::vector<unsigned char> in, out;
        int chunk = -1;
        int state = 0; // 0 free, 1 read, 2 computing, 3 computed
    };
    std::vector<Slot> slots(kSlots);
    for (auto& s : slots) {
        s.in.resize(inRow * static_cast<std::size_t>(rows));
        if (!p.unchanged)
            s.out.resize(outRow * static_cast<std::size_t>(rows));
    }
    std::condition_variable cv;
    bool stop = false;
    std::exception_ptr failure;
    auto fail = [&](std::exception_ptr e) {
        std::lock_guard<std::mutex> lock(m);
        if (!failure)
            failure = e;
        stop = true;
        cv.notify_all();
    };
    std::thread reader([&] {
        try {
            for (int c = 0; c < chunks; ++c) {
                Slot* s = nullptr;
                {
                    std::unique_lock<std::mutex> lock(m);
                    cv.wait(lock, [&] {
                        return stop || slots[static_cast<std::size_t>(c % kSlots)].state == 0;
                    });
                    if (stop)
                        return;
                    s = &slots[static_cast<std::size_t>(c % kSlots)];
                }
                src.readRows(c * rows, c * rows + rowsOf(c), s->in.data());
                std::lock_guard<std::mutex> lock(m);
                s->chunk = c;
                s->state = p.unchanged ? 3 : 1;
                cv.notify_all();
            }
        } catch (...) {
            fail(std::current_exception());
        }
    });
    const int computeThreads =
        p.unchanged ? 0 : std::max(1, std::min(2, resolveThreads(o.threads)));
    std::vector<std::thread> workers;
    for (int w = 0; w < computeThreads; ++w)
        workers.emplace_back([&] {
            ChunkStats local;
            try {
                for (;;) {
                    Slot* s = nullptr;
                    {
                        std::unique_lock<std::mutex> lock(m);
                        cv.wait(lock, [&] {
                            if (stop)
                                return true;
                            for (auto& x : slots)
                                if (x.state == 1)
                                    return true;
                            return false;
                        });
                        if (stop)
                            break;
                        for (auto& x : slots)
                            if (x.state == 1 && (!s || x.chunk < s->chunk))
                                s = &x;
                        s->state = 2;
                    }
                    computeChunk(p, chain, s->in.data(), s->out.data(),
                                 static_cast<std::size_t>(p.in.width) *
                                     static_cast<std::size_t>(rowsOf(s->chunk)),
                                 local);
                    std::lock_guard<std::mutex> lock(m);
                    s->state = 3;
                    cv.notify_all();
                }
            } catch (...) {
                fail(std::current_exception());
            }
            std::lock_guard<std::mutex> lock(m);
            total.merge(local);
        });
    try {
        for (int c = 0; c < chunks; ++c) {
            Slot* s = &slots[static_cast<std::size_t>(c % kSlots)];
            {
                std::unique_lock<std::mutex> lock(m);
                cv.wait(lock, [&] { return stop || (s->chunk == c && s->state == 3); });
                if (stop)
                    break;
            }
            sink.writeRows(c * rows, c * rows + rowsOf(c),
                           p.unchanged ? s->in.data() : s->out.data());
            std::lock_guard<std::mutex> lock(m);
            s->state = 0;
            cv.notify_all();
        }
    } catch (...) {
        fail(std::current_exception());
    }
    {
        std::lock_guard<std::mutex> lock(m);
        stop = true; // the workers wait for more chunks: let them go
        cv.notify_all();
    }
    reader.join();
    for (auto& w : workers)
        w.join();
    if (failure)
        std::rethrow_exception(failure);
}

// What streaming a part holds at once: its chunk buffers, and what the codec decodes whole.
std::uint64_t partMemory(const Plan& p, int srcGranularity, int sinkGranularity,
                         const ApplyImageOptions& o) {
    const int rows = chunkRowsFor(p, srcGranularity, sinkGranularity, o);
    const int chunks = (p.in.height + rows - 1) / rows;
    const std::uint64_t slots = o.overlap && chunks > 1 && threadsAvailable() ? kSlots : 1;
    const std::uint64_t perSlot =
        (rowBytes(p.in) + (p.unchanged ? 0 : rowBytes(p.out))) * static_cast<std::uint64_t>(rows);
    return slots * perSlot + p.in.decoderBytes;
}

} // namespace

ApplyImageReport applyToImage(const std::string& input, const OutputTarget& target,
                              const PixelChain& chain, const ApplyImageOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    ApplyImageReport report;
    auto src = openImageSource(input, o.inFormat);
    const std::string name = isStdStream(input) ? std::string("-") : input;
    const ImageInfo first = src->info();
    const std::string outFormat =
        target.inPlace() ? (o.outFormat.empty() ? first.format : o.outFormat) : target.path;
    const std::string fmt = canonicalImageFormat(outFormat);
    // Every part of the file (subimages and their MIP levels), or the one subimage asked for.
    std::vector<int> parts;
    if (o.subimage >= 0) {
        parts = selectSubimage(*src, input, o.subimage);
    } else {
        for (int i = 0; i < src->parts(); ++i)
            parts.push_back(i);
    }
    if (first.subimages > 1 && o.subimage < 0 && !formatHoldsParts(fmt))
        throw MultiImageError(name, first.subimages, subimageKind(first.format));
    std::vector<Plan> plans;
    std::vector<SinkSpec> specs;
    std::uint64_t memory = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        src->selectPart(parts[i]);
        if (src->info().mipLevel > 0 && !formatHoldsParts(fmt)) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.path = input;
            d.message = "MIP levels below the first not written: " + fmt + " holds none (write " +
                        ".exr or .tif to keep them)";
            report.diagnostics.push_back(d);
            break;
        }
        SinkSpec spec;
        spec.format = target.inPlace() ? fmt : std::string();
        spec.metadata = src->metadata();
        spec.threads = std::max(1, resolveThreads(o.threads));
        Diagnostics notes;
        plans.push_back(planPart(src->info(), outFormat, chain, o, spec, notes));
        if (i == 0)
            for (auto& d : notes) {
                d.path = input;
                report.diagnostics.push_back(d);
            }
        specs.push_back(spec);
        // The sink's granularity is known once it is open; a tiled output's is its tile height.
        memory = std::max(memory, partMemory(plans.back(), src->rowGranularity(),
                                             spec.tileWidth > 0 ? spec.tileHeight : 1, o));
    }
    // Before anything is decoded: the batch's memory budget (--max-memory) holds this file.
    if (o.reserveMemory)
        o.reserveMemory(
            memory, "reading " + std::to_string(first.width) + "x" + std::to_string(first.height) +
                        " " + first.format +
                        (plans.size() > 1 ? " (" + std::to_string(plans.size()) + " parts)" : ""));
    report.input = plans.front().in;
    report.unchanged = plans.front().unchanged;
    report.parts = static_cast<int>(plans.size());

    auto sink = createImageSink(target, specs);
    report.output = plans.front().out;
    report.output.format = fmt;
    ChunkStats total;
    for (std::size_t i = 0; i < plans.size(); ++i) {
        if (plans.size() > 1 || parts.size() > 1)
            src->selectPart(parts[i]); // planning left the source at the last part
        if (i > 0)
            sink->nextPart();
        streamPart(*src, *sink, plans[i], chain, o, total);
    }
    src->finish();
    sink->finish();
    report.domain = total.domain;
    report.clamped = total.clamped;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return report;
}

} // namespace lut::formats
