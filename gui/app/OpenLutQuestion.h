// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one question Open LUT asks before a LUT image is read, as a user expects it: the layout when
// several fit the picture (a 256x16 strip) and, when the file does not say what it is for
// (lut/LutPurpose.h) and nothing answered it yet, what it is for, in the same dialog.
#include "lut/LutPurpose.h"

#include <QString>
#include <QStringList>

#include <optional>

class QWidget;

namespace lut::gui {

struct OpenLutAnswer {
    QString layout; // one of the items given; the first is "detect automatically"
    std::optional<LutPurpose> purpose; // set when it was asked
};

// Shows the dialog (object name "openLut"; the layout list "openLut.layout", the question
// "openLut.question", the purpose choices "purpose.raw" and "purpose.smash" as in the purpose
// question of a LUT that is not a strip). `gameEvidence`: what in the table says it is the game's
// LUT (lut::gameLutEvidence), said in the question, "the game's LUT" then pre-selected. nullopt
// when the user cancelled.
std::optional<OpenLutAnswer> askOpenLut(QWidget* parent, const QString& fileName,
                                        const QStringList& layouts, bool askPurpose,
                                        const QString& gameEvidence = {});

// The purpose question alone, for a LUT that is no strip with several layouts: a message box
// (buttons "purpose.raw", "purpose.smash", Cancel), `gameEvidence` said and "The Game's LUT" the
// default button when there is some. nullopt when the user cancelled.
std::optional<LutPurpose> askLutPurpose(QWidget* parent, const QString& fileName,
                                        const QString& gameEvidence);

} // namespace lut::gui
