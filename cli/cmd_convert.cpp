// lutkit convert: any readable LUT file to any writable one, saying what the conversion cost.
// Two losses are measured apart: resampling (when the output stores another lattice size) is
// measured by lut::resampleWithError on a probe grid; storage (integer quantisation, clipping,
// dropped domain or shaper) by reading the written file back and comparing it with the table
// that was handed to the writer.
#include "cmd_convert.h"

#include "Commands.h"
#include "cmd_json.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/ops/CompareLuts.h"
#include "lut/ops/Resample.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace lut::cli {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string ms(double seconds) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g ms", seconds * 1e3);
    return buf;
}

// Compares the table handed to the writer with what the file reads back as. When both have the
// same lattice, domain and shaper shape, entry by entry (exact); otherwise as functions on a probe
// grid over the written table's domain.
ErrorStats storageError(const LutFile& written, const LutFile& back) {
    const bool sameShape =
        written.cube && back.cube && written.cube->size() == back.cube->size() &&
        written.cube->domainMin() == back.cube->domainMin() &&
        written.cube->domainMax() == back.cube->domainMax() &&
        written.shaper.has_value() == back.shaper.has_value() &&
        (!written.shaper || (written.shaper->size() == back.shaper->size() &&
                             written.shaper->domainMin() == back.shaper->domainMin() &&
                             written.shaper->domainMax() == back.shaper->domainMax()));
    if (!sameShape)
        return compareLuts(written.toLut3D(), back.toLut3D(), Interpolation::Tetrahedral);
    ErrorAccumulator acc;
    const auto& a = written.cube->entries();
    const auto& b = back.cube->entries();
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c)
            acc.add(a[i][c], b[i][c]);
    if (written.shaper)
        for (int i = 0; i < written.shaper->size(); ++i)
            for (int c = 0; c < 3; ++c)
                acc.add((*written.shaper)[i][c], (*back.shaper)[i][c]);
    return acc.result();
}

std::string describe(const LutFile& f) {
    std::string s = f.format;
    if (!f.dialect.empty())
        s += " (" + f.dialect + ")";
    if (f.shaper)
        s += ", 1D shaper " + std::to_string(f.shaper->size());
    if (f.cube)
        s += ", " + std::to_string(f.cube->size()) + "^3";
    if (f.sourceBitDepth)
        s += ", " + std::to_string(f.sourceBitDepth) + "-bit";
    return s;
}

std::string fileJson(const std::string& path, const LutFile& f, double seconds) {
    return "{\"path\": " + json::quote(path) + ", \"format\": " + json::quote(f.format) +
           ", \"dialect\": " + json::quote(f.dialect) +
           ", \"size\": " + std::to_string(f.cube ? f.cube->size() : 0) +
           ", \"shaper_size\": " + std::to_string(f.shaper ? f.shaper->size() : 0) +
           ", \"bit_depth\": " + std::to_string(f.sourceBitDepth) +
           ", \"seconds\": " + json::number(seconds) + "}";
}

} // namespace

int runConvert(const ConvertOptions& o) {
    const auto tStart = Clock::now();
    if (o.size != 0 && (o.size < limits::kMin3DSize || o.size > limits::kMax3DSize)) {
        std::cerr << "lutkit convert: --size " << o.size << " is outside " << limits::kMin3DSize
                  << ".." << limits::kMax3DSize << "\n";
        return kExitUsage;
    }
    Interpolation interp;
    try {
        interp = parseInterpolation(o.interp);
    } catch (const Error& e) {
        std::cerr << "lutkit convert: --interp: " << e.what() << "\n";
        return kExitUsage;
    }
    checkNotSameFile(o.input, o.output);

    formats::registerBuiltinFormats();
    const auto& registry = FormatRegistry::instance();
    const Format* writer = nullptr;
    for (const std::string* name : {&o.format, &o.inFormat})
        if (!name->empty() && !registry.byName(*name)) {
            std::string known;
            for (const Format* f : registry.all())
                known += (known.empty() ? "" : " ") + f->name();
            std::cerr << "lutkit convert: unknown format '" << *name << "' (known: " << known
                      << ")\n";
            return kExitUsage;
        }
    if (!o.format.empty()) {
        writer = registry.byName(o.format);
    } else {
        writer = registry.writerForPath(o.output);
    }
    if (!writer || !writer->canWrite())
        throw Error(o.output + ": no format writes '" + extensionOf(o.output) +
                    "' files (use --format)");

    // Read.
    auto t0 = Clock::now();
    FormatOptions readOptions;
    readOptions.layout = layoutOption("--in-layout", o.inLayout);
    LutFile input = formats::readLut(o.input, readOptions, o.inFormat);
    const double readSeconds = since(t0);
    if (!input.cube && !input.shaper)
        throw Error(o.input + ": holds no table");

    // Resample when the output stores another lattice size.
    const int sourceSize = input.cube ? input.cube->size() : 0;
    int targetSize = o.size ? o.size : writer->fixedSize();
    if (targetSize == 0)
        targetSize = sourceSize; // 0 stays 0 for a pure 1D file: the writer decides
    LutFile toWrite = input;
    std::optional<ErrorStats> resampleError;
    if (targetSize != 0 && targetSize != sourceSize) {
        const Lut3D source = input.toLut3D(0);
        ResampleResult r = resampleWithError(source, targetSize, interp);
        resampleError = r.error;
        toWrite.shaper.reset();
        toWrite.cube = std::move(r.lut);
    }
    toWrite.diagnostics.clear();

    // Write.
    FormatOptions writeOptions;
    writeOptions.layout = layoutOption("--layout", o.layout);
    writeOptions.size = targetSize;
    writeOptions.bitDepth = o.bitDepth;
    writeOptions.dither = o.dither;
    if (!o.name.empty())
        writeOptions.setAttribute(formats::nutexb::kNameAttribute, o.name);
    t0 = Clock::now();
    const Diagnostics writeDiags = writer->write(o.output, toWrite, writeOptions);
    const double writeSeconds = since(t0);

    // Read back what was written.
    std::optional<ErrorStats> storage;
    std::optional<LutFile> back;
    std::string readBackError;
    t0 = Clock::now();
    try {
        FormatOptions backOptions;
        backOptions.layout = layoutOption("--layout", o.layout);
        back = formats::readLut(o.output, backOptions);
        storage = storageError(toWrite, *back);
        storage->seconds = since(t0);
    } catch (const Error& e) {
        readBackError = e.what();
    }
    const double totalSeconds = since(tStart);

    if (o.json) {
        std::ostringstream js;
        js << "{\"input\": " << fileJson(o.input, input, readSeconds) << ",\n \"output\": "
           << (back ? fileJson(o.output, *back, writeSeconds)
                    : "{\"path\": " + json::quote(o.output) +
                          ", \"format\": " + json::quote(writer->name()) +
                          ", \"seconds\": " + json::number(writeSeconds) + "}")
           << ",\n \"output_format\": " << json::quote(writer->name()) << ",\n \"resample\": ";
        if (resampleError)
            js << "{\"from\": " << sourceSize << ", \"to\": " << targetSize
               << ", \"interp\": " << json::quote(toString(interp))
               << ", \"error\": " << json::stats(*resampleError) << "}";
        else
            js << "null";
        js << ",\n \"storage\": " << (storage ? json::stats(*storage) : "null")
           << ",\n \"read_back_error\": "
           << (readBackError.empty() ? "null" : json::quote(readBackError))
           << ",\n \"input_diagnostics\": " << json::diagnostics(input.diagnostics)
           << ",\n \"diagnostics\": " << json::diagnostics(writeDiags)
           << ",\n \"seconds\": " << json::number(totalSeconds) << "}\n";
        std::cout << js.str();
        return kExitOk;
    }

    std::cout << "read     " << o.input << ": " << describe(input) << ", " << ms(readSeconds)
              << "\n";
    for (const auto& d : input.diagnostics)
        std::cout << "  " << d.str() << "\n";
    if (resampleError)
        std::cout << "resample " << sourceSize << "^3 -> " << targetSize << "^3 ("
                  << toString(interp) << "): " << resampleError->str() << "\n";
    else
        std::cout << "resample none (same size)\n";
    std::cout << "wrote    " << o.output << ": " << writer->name();
    if (back)
        std::cout << ", reads back as " << describe(*back);
    std::cout << ", " << ms(writeSeconds) << "\n";
    for (const auto& d : writeDiags)
        std::cout << "  " << d.str() << "\n";
    if (storage)
        std::cout << "storage  (quantisation, written file read back): " << storage->str() << "\n";
    else
        std::cout << "storage  not measured: cannot read the output back: " << readBackError
                  << "\n";
    std::cout << "total    " << ms(totalSeconds) << "\n";
    return kExitOk;
}

} // namespace lut::cli
