// SPDX-License-Identifier: Apache-2.0
#pragma once
// Undo step for a LUT replaced by one the editor made from the document (Tools > Match to
// Reference): the whole LUT state before and after (base, adjustments, purpose, file), so Undo
// gives back exactly what was there, adjustments included.
#include "Document.h"

#include <QUndoCommand>

namespace lut::gui {

class ReplaceLutCommand : public QUndoCommand {
public:
    ReplaceLutCommand(Document* doc, Document::LutState before, Document::LutState after,
                      const QString& text);
    void undo() override;
    void redo() override;

private:
    Document* m_doc;
    Document::LutState m_before;
    Document::LutState m_after;
};

} // namespace lut::gui
