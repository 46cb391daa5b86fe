// SPDX-License-Identifier: Apache-2.0
#pragma once
// The wheel over a dock of controls scrolls the dock; it changes a slider or a number box only
// once that control has the focus (a click or Tab), so a wheel passing over the Adjustments dock
// does not move every slider under the pointer (issue 43: 40 notches moved Lift G to -0.17 and
// added dozens of undo steps). FineSlider does this itself; number boxes get it here.
class QAbstractSpinBox;

namespace lut::gui {

// The box takes the focus by click or Tab only (not by the wheel) and the wheel only when it has
// the focus; otherwise the wheel goes to the widget behind it (the dock's scroll area).
void takeWheelOnlyWhenFocused(QAbstractSpinBox* box);

} // namespace lut::gui
