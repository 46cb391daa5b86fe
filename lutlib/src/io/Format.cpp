// SPDX-License-Identifier: Apache-2.0
// Format's defaults: the memory forms of formats that only know files, through a private
// temporary folder, and the stream bound. The registry is FormatRegistry.cpp.
#include "lut/io/Format.h"

#include "lut/Limits.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"
#include "lut/os/Memory.h"
#include "lut/os/Paths.h"

#include <filesystem>
#include <random>

namespace lut {

Format::~Format() = default;

namespace {

// A private temporary folder for the memory forms of formats that only know files.
class TempDir {
public:
    TempDir() {
        std::random_device rd;
        const auto base = std::filesystem::temp_directory_path();
        for (int attempt = 0; attempt < 16; ++attempt) {
            const auto p =
                base / ("lutkit-" + std::to_string(os::processId()) + "-" + std::to_string(rd()));
            std::error_code ec;
            if (std::filesystem::create_directory(p, ec)) {
                m_path = p;
                return;
            }
        }
        throw Error("cannot create a temporary folder in " + os::fromPath(base));
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    // A file name inside the folder that keeps `name`'s extension.
    std::string file(const std::string& name) const {
        return os::fromPath(m_path / os::toPath("data" + extensionOf(name)));
    }

private:
    std::filesystem::path m_path;
};

} // namespace

std::uint64_t Format::maxStreamBytes(std::string_view head) const {
    return head.find('\0') == std::string_view::npos ? limits::kMaxLutFileBytes : 0;
}

LutFile Format::readMemory(std::string_view bytes, const std::string& name,
                           const FormatOptions& options) const {
    TempDir dir;
    const std::string path = dir.file(name);
    writeFileAtomically(path, bytes);
    // Messages name the caller's name for the data, not the temporary file.
    auto rename = [&](std::string text) {
        for (std::size_t at; (at = text.find(path)) != std::string::npos;)
            text.replace(at, path.size(), name);
        return text;
    };
    try {
        LutFile f = read(path, options);
        for (auto& d : f.diagnostics) {
            d.path = rename(d.path);
            d.message = rename(d.message);
        }
        return f;
    } catch (const ParseError& e) {
        throw ParseError(name, e.line(), e.column(), rename(e.message()), e.offending());
    } catch (const LimitError& e) {
        throw LimitError(rename(e.what()));
    } catch (const Error& e) {
        throw Error(rename(e.what()));
    }
}

std::string Format::writeMemory(const LutFile& lut, const std::string& name,
                                const FormatOptions& options, Diagnostics* diagnostics) const {
    TempDir dir;
    const std::string path = dir.file(name);
    Diagnostics d = write(path, lut, options);
    for (auto& x : d) {
        if (x.path == path)
            x.path = name;
        for (std::size_t at; (at = x.message.find(path)) != std::string::npos;)
            x.message.replace(at, path.size(), name);
    }
    if (diagnostics)
        *diagnostics = std::move(d);
    return readFile(path, limits::kMaxLutFileBytes);
}

} // namespace lut
