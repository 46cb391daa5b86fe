// SPDX-License-Identifier: Apache-2.0
// The formats library's side of the OpenImageIO module: sources and sinks for the formats the
// native codecs do not take load lutkit_imageio.so on first use and forward to it (why: see
// ImageIOModuleApi.h).
// The module is looked for in $LUTKIT_IMAGEIO_MODULE (a file), next to the running executable,
// in ../lib/lutkit/ relative to it, and in the build tree's bin folder.
#include "imageio/ByteIO.h"
#include "imageio/ImageHeaderChecks.h"
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"
#include "lut/io/FileNames.h"
#include "lut/io/TempFiles.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace lut::formats {

namespace {

const module::ImageIOApi& api() {
    static const module::ImageIOApi* loaded = nullptr;
    static std::string failure;
    static std::once_flag once;
    std::call_once(once, [] {
        std::vector<std::string> candidates;
        if (const char* env = std::getenv("LUTKIT_IMAGEIO_MODULE"); env && *env)
            candidates.emplace_back(env);
        const std::string exeDir = executableDir();
        if (!exeDir.empty()) {
            candidates.push_back(exeDir + "/" + module::kImageIOModuleName);
            candidates.push_back(exeDir + "/../lib/lutkit/" + module::kImageIOModuleName);
        }
#ifdef LUTKIT_MODULE_DIR
        candidates.push_back(std::string(LUTKIT_MODULE_DIR) + "/" + module::kImageIOModuleName);
#endif
        std::string tried;
        for (const auto& path : candidates) {
            if (::access(path.c_str(), R_OK) != 0) {
                tried += (tried.empty() ? "" : ", ") + path;
                continue;
            }
            // RTLD_NOW: lazy binding saves nothing measurable here (the time goes into
            // OpenImageIO's dependencies' own relocations) and would turn a missing symbol into a
            // crash.
            void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                const char* err = ::dlerror();
                tried +=
                    (tried.empty() ? "" : ", ") + path + " (" + (err ? err : "dlopen failed") + ")";
                continue;
            }
            auto entry = reinterpret_cast<module::ImageIOEntryPoint>(
                ::dlsym(handle, module::kImageIOEntryPoint));
            const module::ImageIOApi* table = entry ? entry() : nullptr;
            if (!table || table->version != module::kImageIOApiVersion) {
                tried +=
                    (tried.empty() ? "" : ", ") + path + " (not a matching lutkit image module)";
                continue;
            }
            // One list of temporary files for the program and the module (an interrupt removes
            // the module's too).
            using ShareRegistry = void (*)(void*);
            if (auto share = reinterpret_cast<ShareRegistry>(
                    ::dlsym(handle, "lutkit_imageio_use_temp_registry")))
                share(lut::tempFileRegistry());
            loaded = table; // never dlclose'd: OIIO keeps threads and plugins alive until exit
            return;
        }
        failure = std::string("image support (") + module::kImageIOModuleName +
                  ", OpenImageIO) could not be loaded; tried: " + tried;
    });
    if (!loaded)
        throw Error(failure);
    return *loaded;
}

void rethrow(int status, const std::string& error) {
    switch (status) {
    case module::kOk:
        return;
    case module::kLimitError:
        throw LimitError(error);
    case module::kInterrupted:
        throw InterruptedError(error);
    case module::kOutOfMemory:
        throw std::bad_alloc();
    default:
        throw Error(error);
    }
}

class ModuleSource : public ImageSource {
public:
    ModuleSource(const std::string& path, std::string memory, const std::string& format)
        : m_memory(std::move(memory)) {
        module::SourceOpen req;
        req.path = path;
        // Bytes in memory (standard input's, or Format::readMemory's; never empty then) go to
        // OpenImageIO's in-memory reader.
        req.memory = path == "-" || !m_memory.empty() ? &m_memory : nullptr;
        req.format = format;
        std::string error;
        rethrow(api().openSource(req, &m_handle, m_parts, error), error);
        // A constructor that throws runs no destructor: the open source (OpenImageIO's reader
        // and its buffers) is closed here, or each refused file leaked it (LeakSanitizer, under
        // the image_oiio fuzzer: 2.2 GB over 166 files whose first part failed to select).
        try {
            selectPart(0);
        } catch (...) {
            api().closeSource(m_handle);
            m_handle = nullptr;
            throw;
        }
    }
    ~ModuleSource() override {
        if (m_handle)
            api().closeSource(m_handle);
    }
    int rowGranularity() const override { return m_granularity; }
    int parts() const override { return m_parts; }
    void selectPart(int index) override {
        auto meta = std::make_shared<ImageMetadata>();
        std::string error;
        rethrow(api().selectPart(m_handle, index, m_info, *meta, m_granularity, error), error);
        m_metadata = meta;
    }
    void readRows(int y0, int y1, void* dst) override {
        std::string error;
        rethrow(api().readRows(m_handle, y0, y1, dst, error), error);
    }

private:
    std::string m_memory;
    void* m_handle = nullptr;
    int m_parts = 1;
    int m_granularity = 1;
};

class ModuleSink : public ImageSink {
public:
    ModuleSink(const OutputTarget& target, const std::vector<SinkSpec>& parts)
        : m_out(target, true), m_path(target.path) {
        module::ByteCallbacks cb;
        cb.context = this;
        cb.pwrite = [](void* ctx, const void* data, std::size_t n, std::uint64_t offset,
                       std::string& error) {
            try {
                static_cast<ModuleSink*>(ctx)->m_out.pwrite(data, n, offset);
                return true;
            } catch (const std::exception& e) {
                error = e.what();
                // "OUT: cannot write: reason" -> "reason": the module names the file again.
                const std::string prefix =
                    static_cast<ModuleSink*>(ctx)->m_path + ": cannot write: ";
                if (error.rfind(prefix, 0) == 0)
                    error.erase(0, prefix.size());
                return false;
            }
        };
        // The writer is picked by the extension of the name it is given.
        const SinkSpec& spec = parts.front();
        m_format = spec.format.empty() ? target.path : spec.format;
        m_width = spec.width;
        m_height = spec.height;
        std::string name = target.path;
        if (!spec.format.empty() && spec.format.find('.') == std::string::npos &&
            (target.inPlace() || canonicalImageFormat(name) != canonicalImageFormat(spec.format)))
            name = "out." + spec.format;
        if (parts.size() > 1) {
            // OpenImageIO 2.4 writes a multi-part OpenEXR by name only (and libtiff reads back
            // the pages it chains): the writer gets the temporary file itself, which commit()
            // then checks and renames like any other.
            if (target.inPlace() || target.kind == OutputKind::Memory)
                throw Error(
                    target.path + ": a file of " + std::to_string(parts.size()) +
                    " images (parts, pages, frames or MIP levels) cannot be written to " +
                    (target.kind == OutputKind::Memory ? "memory" : "standard output or a device") +
                    ": name a file");
            name = m_out.tempPath();
            cb.pwrite = nullptr;
        }
        // A writer that must read back what it writes writes this file by name (OiioSink.cpp).
        cb.file = m_out.tempPath();
        m_temp = cb.file;
        std::string error;
        // The call first, then the message: argument order is unspecified.
        const int status = api().openSink(parts.data(), static_cast<int>(parts.size()), name, cb,
                                          &m_handle, m_granularity, error);
        rethrow(status, userFacing(error));
    }
    ~ModuleSink() override {
        if (m_handle)
            api().closeSink(m_handle);
    }
    int rowGranularity() const override { return m_granularity; }
    void nextPart() override {
        std::string error;
        const int status = api().nextPart(m_handle, m_granularity, error);
        rethrow(status, userFacing(error));
    }
    void writeRows(int y0, int y1, const void* src) override {
        std::string error;
        const int status = api().writeRows(m_handle, y0, y1, src, error);
        rethrow(status, userFacing(error));
    }
    void finish() override {
        std::string error;
        const int status = api().finishSink(m_handle, error);
        rethrow(status, userFacing(error));
        m_out.commit([this](const std::string& temp) { checkWrittenHeader(temp); });
    }

private:
    // A written file (before its rename) declares the image written, as lutkit's own header
    // scanners read it: a writer that leaves a file no reader opens is an error, not exit 0 (issue
    // 41: OpenImageIO's TIFF writer through a proxy left a first directory of Exif tags only).
    void checkWrittenHeader(const std::string& temp) const {
        const DeclaredImage d = checkImageHeader(temp, m_format);
        if (d.format.empty())
            return; // a format the scanners do not know
        if (d.parts.empty() || d.parts.front().width != static_cast<std::uint64_t>(m_width) ||
            d.parts.front().height != static_cast<std::uint64_t>(m_height))
            throw Error(temp + ": the file written does not declare the " +
                        std::to_string(m_width) + "x" + std::to_string(m_height) +
                        " image written (" + d.format + ")");
    }

    // Messages name the user's path, never the temporary file a multi-part writer was given.
    std::string userFacing(std::string text) const {
        if (!m_temp.empty())
            for (std::size_t at; (at = text.find(m_temp)) != std::string::npos;)
                text.replace(at, m_temp.size(), m_path);
        return text;
    }

    ByteWriter m_out;
    std::string m_path;
    std::string m_temp;   // the temporary file, which a writer may write by name ("" = none)
    std::string m_format; // the format's name, or the file's name
    int m_width = 0, m_height = 0; // of the first image
    void* m_handle = nullptr;
    int m_granularity = 1;
};

} // namespace

std::unique_ptr<ImageSource> openOiioSource(const std::string& path, std::string memory,
                                            const std::string& format) {
    return std::make_unique<ModuleSource>(path, std::move(memory), format);
}

std::unique_ptr<ImageSink> createOiioSink(const OutputTarget& target,
                                          const std::vector<SinkSpec>& parts) {
    if (parts.empty())
        throw Error(target.path + ": cannot write an image of no parts");
    return std::make_unique<ModuleSink>(target, parts);
}

} // namespace lut::formats
