// SPDX-License-Identifier: Apache-2.0
#include "SetAdjustmentsCommand.h"

#include "Document.h"
#include "EditText.h"

namespace lut::gui {

SetAdjustmentsCommand::SetAdjustmentsCommand(Document* doc, Adjustments before, Adjustments after,
                                             int mergeKey, int gesture, const QString& text)
    : m_doc(doc), m_before(std::move(before)), m_after(std::move(after)), m_key(mergeKey),
      m_gesture(gesture), m_action(text) {
    setText(describeAdjustmentChange(m_action, m_before, m_after));
}

void SetAdjustmentsCommand::undo() {
    m_doc->applyAdjustmentsState(m_before);
}

void SetAdjustmentsCommand::redo() {
    m_doc->applyAdjustmentsState(m_after);
}

bool SetAdjustmentsCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = dynamic_cast<const SetAdjustmentsCommand*>(other);
    if (!o || m_key < 0 || o->m_key != m_key || o->m_gesture != m_gesture)
        return false;
    m_after = o->m_after;
    setText(describeAdjustmentChange(m_action, m_before, m_after)); // where the drag ended
    if (m_after == m_before)
        setObsolete(true);
    return true;
}

} // namespace lut::gui
