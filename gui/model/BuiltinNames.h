// SPDX-License-Identifier: Apache-2.0
#pragma once
// The built-in LUTs (lut/io/BuiltinLut.h: "builtin:neutral", "builtin:smash-default") as a
// person reads them in the editor's menu, the LUT dock and the window's title: "Neutral" and
// "Smash Ultimate's default stage LUT", with the "builtin:NAME" spelling (what lutkit and scripts
// take) kept for tooltips.
#include <QString>

namespace lut::gui {

// "Smash Ultimate's default stage LUT" for "builtin:smash-default" or "smash-default"; a name
// this list does not know is given back as it is.
QString builtinLutTitle(const QString& nameOrPath);

} // namespace lut::gui
