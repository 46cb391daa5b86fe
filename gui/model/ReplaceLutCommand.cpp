// SPDX-License-Identifier: Apache-2.0
#include "ReplaceLutCommand.h"

namespace lut::gui {

ReplaceLutCommand::ReplaceLutCommand(Document* doc, Document::LutState before,
                                     Document::LutState after, const QString& text)
    : m_doc(doc), m_before(std::move(before)), m_after(std::move(after)) {
    setText(text);
}

void ReplaceLutCommand::undo() {
    m_doc->restoreLutState(m_before);
}

void ReplaceLutCommand::redo() {
    m_doc->restoreLutState(m_after);
}

} // namespace lut::gui
