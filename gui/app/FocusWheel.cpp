// SPDX-License-Identifier: Apache-2.0
#include "FocusWheel.h"

#include <QAbstractSpinBox>
#include <QEvent>
#include <QObject>

namespace lut::gui {

namespace {

class FocusWheelFilter : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (e->type() == QEvent::Wheel) {
            auto* w = static_cast<QWidget*>(watched);
            if (!w->hasFocus()) {
                e->ignore(); // to the parent: the dock scrolls
                return true;
            }
        }
        return false;
    }
};

} // namespace

void takeWheelOnlyWhenFocused(QAbstractSpinBox* box) {
    box->setFocusPolicy(Qt::StrongFocus);
    box->installEventFilter(new FocusWheelFilter(box));
}

} // namespace lut::gui
