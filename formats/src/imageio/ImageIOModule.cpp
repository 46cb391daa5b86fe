// Entry point of lutkit_imageio.so: the OpenImageIO-backed functions of ImageIO.cpp behind a
// C-callable table (see src/ImageIOModuleApi.h for why this is a separate module).
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"
#include "lut/io/TempFiles.h"

#include <new>

namespace lut::formats::module {
namespace {

template <class Fn> int guarded(std::string& error, Fn&& fn) {
    try {
        fn();
        return kOk;
    } catch (const InterruptedError& e) {
        error = e.what();
        return kInterrupted;
    } catch (const LimitError& e) {
        error = e.what();
        return kLimitError;
    } catch (const std::bad_alloc&) {
        error = "out of memory";
        return kOutOfMemory;
    } catch (const std::exception& e) {
        error = e.what();
        return kError;
    } catch (...) {
        error = "unknown error in the image module";
        return kError;
    }
}

int readImageEntry(const std::string& path, LoadedImage& out, std::string& error) {
    return guarded(error, [&] { out = lut::formats::readImage(path); });
}
int readImageInfoEntry(const std::string& path, ImageInfo& out, std::string& error) {
    return guarded(error, [&] { out = lut::formats::readImageInfo(path); });
}
int writeImageEntry(const std::string& path, const Image& image, const ImageWriteOptions& options,
                    std::string& error) {
    return guarded(error, [&] { lut::formats::writeImage(path, image, options); });
}

const ImageIOApi kApi = {kImageIOApiVersion, &readImageEntry, &readImageInfoEntry,
                         &writeImageEntry};

} // namespace
} // namespace lut::formats::module

extern "C" __attribute__((visibility("default"))) const lut::formats::module::ImageIOApi*
lutkit_imageio_api() {
    return &lut::formats::module::kApi;
}

// The module links its own copy of lutlib: its temporary files must be listed in the program's
// registry so an interrupt removes them too (lut/io/TempFiles.h). Called by the loader once.
extern "C" __attribute__((visibility("default"))) void
lutkit_imageio_use_temp_registry(void* registry) {
    lut::useTempFileRegistry(registry);
}
