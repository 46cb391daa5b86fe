// SPDX-License-Identifier: Apache-2.0
#pragma once
// What an undo step did, with its values, as the History dock lists it and Edit > Undo names it:
// "Set Exposure (stops): 0.000 → 0.500", "Move lift wheel: Lift R 0.000 → 0.020, Lift G ...",
// "Edit master curve: 3 points (0.00, 0.00) (0.50, 0.62) (1.00, 1.00)". The values are the
// adjustments' before and after the whole step (a drag merged into one step: where it started
// and where it ended), at the precision the Adjustments dock shows.
#include "lut/ops/Adjust.h"

#include <QString>

namespace lut::gui {

// `action` ("Set Exposure (stops)", "Reset adjustments") followed by what changed, at most three
// parameters or curves (then "and N more").
QString describeAdjustmentChange(const QString& action, const Adjustments& before,
                                 const Adjustments& after);

} // namespace lut::gui
