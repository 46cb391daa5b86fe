// SPDX-License-Identifier: Apache-2.0
#pragma once
// Undo step for any edit of the adjustments: a slider, a spin box, a curve point, a colour wheel,
// reset, a loaded adjustment list. Consecutive edits with the same merge key within one gesture
// (press .. release) merge into one step, so undo returns to where the drag started; a drag that
// ends where it started leaves no step. Key -1 never merges. Its text names the values before
// and after (EditText.h), as the History dock lists it.
#include "lut/ops/Adjust.h"

#include <QUndoCommand>

namespace lut::gui {

class Document;

class SetAdjustmentsCommand : public QUndoCommand {
public:
    SetAdjustmentsCommand(Document* doc, Adjustments before, Adjustments after, int mergeKey,
                          int gesture, const QString& text);
    void undo() override;
    void redo() override;
    int id() const override { return m_key < 0 ? -1 : 1000; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* m_doc;
    Adjustments m_before;
    Adjustments m_after;
    int m_key;
    int m_gesture;
    QString m_action; // "Set Exposure (stops)": the step's text is it with the values (EditText.h)
};

} // namespace lut::gui
