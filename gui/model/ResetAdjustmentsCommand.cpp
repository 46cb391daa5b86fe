#include "ResetAdjustmentsCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace lut::gui {

ResetAdjustmentsCommand::ResetAdjustmentsCommand(Document* doc, const Adjustments& before)
    : m_doc(doc), m_before(before) {
    setText(QCoreApplication::translate("Document", "Reset adjustments"));
}

void ResetAdjustmentsCommand::undo() {
    m_doc->applyAdjustmentsState(m_before);
}
void ResetAdjustmentsCommand::redo() {
    m_doc->applyAdjustmentsState(Adjustments{});
}

} // namespace lut::gui
