#include "SetAdjustmentCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace lut::gui {

SetAdjustmentCommand::SetAdjustmentCommand(Document* doc, AdjustParam param, double before,
                                           double after, int gesture)
    : m_doc(doc), m_param(param), m_before(before), m_after(after), m_gesture(gesture) {
    setText(QCoreApplication::translate("Document", "Set %1")
                .arg(QString::fromStdString(adjustParamInfo(param).label)));
}

void SetAdjustmentCommand::undo() {
    Adjustments a = m_doc->adjustments();
    setParam(a, m_param, m_before);
    m_doc->applyAdjustmentsState(a);
}

void SetAdjustmentCommand::redo() {
    Adjustments a = m_doc->adjustments();
    setParam(a, m_param, m_after);
    m_doc->applyAdjustmentsState(a);
}

bool SetAdjustmentCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = dynamic_cast<const SetAdjustmentCommand*>(other);
    if (!o || o->m_param != m_param || o->m_gesture != m_gesture)
        return false;
    m_after = o->m_after;
    // A drag that ends where it started is no step at all.
    if (m_after == m_before)
        setObsolete(true);
    return true;
}

} // namespace lut::gui
