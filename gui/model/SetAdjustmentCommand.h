#pragma once
// Undo step for one adjustment slider. Consecutive moves of the same slider within one gesture
// (press .. release) merge into one step, so undo returns to where the drag started.
#include "AdjustParam.h"

#include <QUndoCommand>

namespace lut::gui {

class Document;

class SetAdjustmentCommand : public QUndoCommand {
public:
    SetAdjustmentCommand(Document* doc, AdjustParam param, double before, double after,
                         int gesture);
    void undo() override;
    void redo() override;
    int id() const override { return 1000 + static_cast<int>(m_param); }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* m_doc;
    AdjustParam m_param;
    double m_before;
    double m_after;
    int m_gesture;
};

} // namespace lut::gui
