// SPDX-License-Identifier: Apache-2.0
#pragma once
// The colour wheels dock: lift, gamma and gain wheels side by side (ColorWheel), each editing the
// per-channel values of its range; the master values stay on the Adjustments sliders.
#include <QWidget>

namespace lut::gui {

class ColorWheel;
class Document;

class WheelsPanel : public QWidget {
    Q_OBJECT
public:
    explicit WheelsPanel(Document* doc, QWidget* parent = nullptr);
    ColorWheel* wheel(int index) const { return m_wheels[index]; } // 0 lift, 1 gamma, 2 gain

signals:
    void interactiveChanged(bool interactive);

private:
    ColorWheel* m_wheels[3];
};

} // namespace lut::gui
