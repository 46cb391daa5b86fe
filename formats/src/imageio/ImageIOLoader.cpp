// The formats library's side of the OpenImageIO module: readImage, readImageInfo and writeImage
// load lutkit_imageio.so on first use and forward to it (why: see ImageIOModuleApi.h).
// The module is looked for in $LUTKIT_IMAGEIO_MODULE (a file), next to the running executable,
// in ../lib/lutkit/ relative to it, and in the build tree's bin folder.
#include "imageio/ImageHeaderChecks.h"
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"
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

std::string executableDir() {
    std::vector<char> buf(4096);
    const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0)
        return {};
    std::string p(buf.data(), static_cast<std::size_t>(n));
    const auto slash = p.find_last_of('/');
    return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

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

} // namespace

LoadedImage readImage(const std::string& path) {
    checkImageHeader(path); // declared sizes against the file, before a codec believes them
    LoadedImage out;
    std::string error;
    rethrow(api().readImage(path, out, error), error);
    return out;
}

ImageInfo readImageInfo(const std::string& path) {
    checkImageHeader(path);
    ImageInfo out;
    std::string error;
    rethrow(api().readImageInfo(path, out, error), error);
    return out;
}

void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    std::string error;
    rethrow(api().writeImage(path, image, options, error), error);
}

} // namespace lut::formats
