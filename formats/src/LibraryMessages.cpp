// SPDX-License-Identifier: Apache-2.0
#include "lut/formats/LibraryMessages.h"

#include "ocio/OcioSession.h"

namespace lut::formats {

void captureLibraryMessages() {
    installOcioLogSink();
}

} // namespace lut::formats
