// SPDX-License-Identifier: Apache-2.0
#pragma once
// Export settings: one entry per (writable format, layout) so every strip layout is a choice,
// plus size, bit depth, dither, and the target file. What the file holds follows the window's
// target (the toolbar): for Smash the game LUT that shows the edit, else the LUT as edited; the
// dialog says which, and whether the file is exactly what the preview shows (the target's
// default format and settings). The suggested file is never one the user opened
// (ExportNaming.h); each format choice suggests its own name. Strength blends the edit with
// neutral before it is written (lut/ops/Strength.h, as lutkit's --strength), in lightness and
// chroma together or apart.
#include "ExportNaming.h"
#include "ExportTarget.h"

#include "lut/io/Format.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace lut::gui {

struct ExportChoice {
    QString format; // registry name
    QString layout; // "" unless the format is an image layout
    QString label;
    QString extension; // with dot
};

// Every (format, layout) the registry can write. Image formats are offered once per layout.
QList<ExportChoice> exportChoices();

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `naming` gives the opened files (format, layout and extension are filled per choice).
    ExportDialog(ExportTarget target, const ExportNameInput& naming, QWidget* parent = nullptr);

    QString path() const;
    ExportChoice choice() const;
    FormatOptions options() const;
    // The strength asked for (full unless the user changed it).
    StrengthOptions strength() const;
    // Sets the strength controls (both amounts, or lightness and chroma apart when they differ).
    void setStrength(const StrengthOptions& strength);
    ExportTarget target() const { return m_target; }
    // Selects a format (and layout) by registry name; false if there is no such choice.
    bool selectChoice(const QString& format, const QString& layout = {});
    // Whether the file will be exactly the target's default export (what the preview shows).
    bool matchesPreview() const;

private:
    void choiceChanged();
    void updateNote();
    void browse();

    QList<ExportChoice> m_choices;
    ExportTarget m_target;
    ExportNameInput m_naming;
    QComboBox* m_format;
    QLineEdit* m_path;
    QSpinBox* m_size;
    QComboBox* m_bitDepth;
    QCheckBox* m_dither;
    QDoubleSpinBox* m_strength;
    QCheckBox* m_separate;
    QDoubleSpinBox* m_luma;
    QDoubleSpinBox* m_chroma;
    QLabel* m_note;
};

} // namespace lut::gui
