// SPDX-License-Identifier: Apache-2.0
#include "ErrorExit.h"

#include "Usage.h"

#include "lut/Error.h"
#include "lut/formats/ColorConfig.h"
#include "lut/formats/RequestError.h"
#include "lut/io/TempFiles.h"

namespace lut::cli {

ErrorKind errorKind(const std::exception& e) {
    if (dynamic_cast<const InterruptedError*>(&e))
        return ErrorKind::Interrupted;
    if (dynamic_cast<const UsageError*>(&e) || dynamic_cast<const formats::RequestError*>(&e) ||
        dynamic_cast<const formats::ColorOptionError*>(&e))
        return ErrorKind::Usage;
    if (dynamic_cast<const IoError*>(&e))
        return ErrorKind::Io;
    if (dynamic_cast<const Error*>(&e))
        return ErrorKind::Input;
    return ErrorKind::Other;
}

int exitCode(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::Usage:
        return kExitUsage;
    case ErrorKind::Interrupted:
        return kExitInterrupted;
    case ErrorKind::Input:
    case ErrorKind::Io:
    case ErrorKind::Other:
        break;
    }
    return kExitFailure;
}

} // namespace lut::cli
