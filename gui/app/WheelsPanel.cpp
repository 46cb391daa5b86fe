// SPDX-License-Identifier: Apache-2.0
#include "WheelsPanel.h"

#include "ColorWheel.h"

#include <QHBoxLayout>

namespace lut::gui {

WheelsPanel::WheelsPanel(Document* doc, QWidget* parent) : QWidget(parent) {
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(4, 4, 4, 4);
    const ColorWheel::Range ranges[3] = {ColorWheel::Range::Lift, ColorWheel::Range::Gamma,
                                         ColorWheel::Range::Gain};
    for (int i = 0; i < 3; ++i) {
        m_wheels[i] = new ColorWheel(doc, ranges[i], this);
        h->addWidget(m_wheels[i]);
        connect(m_wheels[i], &ColorWheel::interactiveChanged, this,
                &WheelsPanel::interactiveChanged);
    }
}

} // namespace lut::gui
