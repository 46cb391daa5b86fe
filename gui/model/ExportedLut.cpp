// SPDX-License-Identifier: Apache-2.0
#include "ExportedLut.h"

#include "Document.h"

#include "lut/ops/Plot.h"

namespace lut::gui {

std::shared_ptr<const Lut3D> exportedLut(const Document& doc, ExportTarget target) {
    return makeTargetLut(doc.lutSource(), target).shown;
}

Image plotExportedLut(const Document& doc, ExportTarget target) {
    return plotLut(*exportedLut(doc, target)).image;
}

} // namespace lut::gui
