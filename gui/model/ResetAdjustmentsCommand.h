#pragma once
// Undo step for "Reset adjustments": back to neutral adjustments on the base LUT.
#include "lut/ops/Adjust.h"

#include <QUndoCommand>

namespace lut::gui {

class Document;

class ResetAdjustmentsCommand : public QUndoCommand {
public:
    ResetAdjustmentsCommand(Document* doc, const Adjustments& before);
    void undo() override;
    void redo() override;

private:
    Document* m_doc;
    Adjustments m_before;
};

} // namespace lut::gui
