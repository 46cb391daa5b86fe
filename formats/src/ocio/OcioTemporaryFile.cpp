// SPDX-License-Identifier: Apache-2.0
#include "ocio/OcioTemporaryFile.h"

#include "lut/Error.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/os/Memory.h"
#include "lut/os/Paths.h"

#include <filesystem>
#include <random>

namespace lut::formats {

namespace {

// A private temporary folder, removed with what it holds when it goes.
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
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    // A file name inside the folder that keeps `name`'s extension.
    std::string file(const std::string& name) const {
        return os::fromPath(m_path / os::toPath("data" + extensionOf(name)));
    }

private:
    std::filesystem::path m_path;
};

} // namespace

LutFile readThroughTemporaryFile(std::string_view bytes, const std::string& name,
                                 const std::function<LutFile(const std::string& path)>& read) {
    TempDir dir;
    const std::string path = dir.file(name);
    writeFileAtomically(path, bytes);
    // OpenColorIO's own messages name the file it opened: the temporary one is said as `name`.
    auto rename = [&](std::string text) {
        for (std::size_t at; (at = text.find(path)) != std::string::npos;)
            text.replace(at, path.size(), name);
        return text;
    };
    try {
        LutFile f = read(path);
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

} // namespace lut::formats
