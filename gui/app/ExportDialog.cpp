// SPDX-License-Identifier: Apache-2.0
#include "ExportDialog.h"

#include "Document.h"

#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/Layout.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace lut::gui {

static bool isImageLayoutFormat(const Format& f) {
    for (const auto& e : f.extensions())
        if (e == ".png" || e == ".tif" || e == ".tiff" || e == ".exr" || e == ".jpg")
            return true;
    return false;
}

QList<ExportChoice> exportChoices() {
    formats::registerBuiltinFormats();
    QList<ExportChoice> out;
    for (const Format* f : FormatRegistry::instance().all()) {
        if (!f->canWrite())
            continue;
        const QString name = QString::fromStdString(f->name());
        const QString desc = QString::fromStdString(f->description());
        // A format reached by name only (hald shares the image extensions with strip) writes PNG.
        const QString ext = f->extensions().empty()
                                ? QStringLiteral(".png")
                                : QString::fromStdString(f->extensions().front());
        if (isImageLayoutFormat(*f) && !f->name().starts_with("hald")) {
            for (LutLayout l : allLayouts()) {
                if (l == LutLayout::Hald)
                    continue;
                const QString ln = QString::fromLatin1(toString(l));
                out.push_back(
                    {name, ln, QStringLiteral("%1 — %2 layout (%3)").arg(desc, ln, ext), ext});
            }
        } else {
            out.push_back({name, {}, QStringLiteral("%1 (%2)").arg(desc, ext), ext});
        }
    }
    // Atlases: the LUT as a row of a MultiLUT-style picture (AtlasExport.h, lutkit atlas build).
    for (LutLayout l : {LutLayout::Reshade, LutLayout::Unity32}) {
        const QString ln = QString::fromLatin1(toString(l));
        out.push_back({QString::fromLatin1(kAtlasFormat), ln,
                       l == LutLayout::Reshade
                           ? QObject::tr("LUT atlas — a row added, ReShade MultiLUT.fx (.png)")
                           : QObject::tr("LUT atlas — a row added, Unity 1024x32 rows (.png)"),
                       QStringLiteral(".png")});
    }
    return out;
}

ExportDialog::ExportDialog(ExportTarget target, const ExportNameInput& naming, QWidget* parent)
    : QDialog(parent), m_choices(exportChoices()), m_target(target), m_naming(naming) {
    setWindowTitle(tr("Export LUT"));
    auto* form = new QFormLayout(this);
    m_format = new QComboBox(this);
    m_format->setObjectName("format");
    for (const auto& c : m_choices)
        m_format->addItem(c.label);
    form->addRow(tr("Format"), m_format);

    auto* pathRow = new QHBoxLayout;
    m_path = new QLineEdit(this);
    m_path->setObjectName("path");
    m_path->setMinimumWidth(420);
    auto* browse = new QPushButton(tr("Browse…"), this);
    pathRow->addWidget(m_path);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);

    m_size = new QSpinBox(this);
    m_size->setObjectName("size");
    m_size->setRange(0, 256);
    m_size->setSpecialValueText(tr("as edited"));
    form->addRow(tr("Size"), m_size);
    m_bitDepth = new QComboBox(this);
    m_bitDepth->addItem(tr("format default"), 0);
    m_bitDepth->addItem(tr("8-bit"), 8);
    m_bitDepth->addItem(tr("16-bit"), 16);
    m_bitDepth->addItem(tr("32-bit float"), 32);
    form->addRow(tr("Bit depth"), m_bitDepth);
    m_dither = new QCheckBox(tr("Ordered dither for 8-bit images"), this);
    form->addRow(QString(), m_dither);
    auto amount = [this](const char* name, const QString& tip) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(QString::fromLatin1(name));
        s->setRange(0.0, 2.0);
        s->setDecimals(2);
        s->setSingleStep(0.05);
        s->setValue(1.0);
        s->setToolTip(tip);
        return s;
    };
    m_strength = amount("strength", tr("How much of the edit: 0 = neutral, 1 = the edit, up to 2 "
                                       "exaggerates it (blended with neutral in Oklab)"));
    form->addRow(tr("Strength"), m_strength);
    m_separate = new QCheckBox(tr("Lightness and colour apart"), this);
    m_separate->setObjectName("separate");
    m_luma = amount("luma", tr("How much of the edit's lightness change (Oklab L)"));
    m_chroma = amount("chroma", tr("How much of the edit's colour change (Oklab a, b)"));
    auto* apart = new QHBoxLayout;
    apart->addWidget(m_separate);
    apart->addWidget(new QLabel(tr("Lightness"), this));
    apart->addWidget(m_luma);
    apart->addWidget(new QLabel(tr("Colour"), this));
    apart->addWidget(m_chroma);
    form->addRow(QString(), apart);
    m_luma->setEnabled(false);
    m_chroma->setEnabled(false);
    m_note = new QLabel(this);
    m_note->setObjectName("note");
    m_note->setWordWrap(true);
    form->addRow(tr("Holds"), m_note);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::choiceChanged);
    connect(m_size, &QSpinBox::valueChanged, this, &ExportDialog::updateNote);
    connect(m_bitDepth, &QComboBox::currentIndexChanged, this, &ExportDialog::updateNote);
    connect(m_dither, &QCheckBox::toggled, this, &ExportDialog::updateNote);
    connect(m_separate, &QCheckBox::toggled, this, [this](bool apart) {
        m_strength->setEnabled(!apart);
        m_luma->setEnabled(apart);
        m_chroma->setEnabled(apart);
        updateNote();
    });
    for (QDoubleSpinBox* s : {m_strength, m_luma, m_chroma})
        connect(s, &QDoubleSpinBox::valueChanged, this, &ExportDialog::updateNote);

    // The target's own export first.
    const ExportTargetInfo& t = exportTargetInfo(target);
    const QString layout = t.layout ? QString::fromLatin1(toString(*t.layout)) : QString();
    if (!selectChoice(QString::fromStdString(t.format), layout))
        choiceChanged();
}

bool ExportDialog::selectChoice(const QString& format, const QString& layout) {
    for (int i = 0; i < m_choices.size(); ++i)
        if (m_choices[i].format == format && m_choices[i].layout == layout) {
            if (m_format->currentIndex() == i)
                choiceChanged();
            else
                m_format->setCurrentIndex(i);
            return true;
        }
    return false;
}

void ExportDialog::choiceChanged() {
    const ExportChoice c = choice();
    ExportNameInput n = m_naming;
    n.format = c.format;
    n.layout = c.layout;
    n.extension = c.extension;
    n.gameLut = exportTargetInfo(m_target).purpose == LutPurpose::Smash;
    m_path->setText(suggestedExportPath(n));
    // The size the format stores, from the library's rule for where a LUT goes
    // (lut/formats/LutDestination.h: the game's 16^3, reshade and unity-32's 32^3; an atlas row
    // is a strip); else the target's own size for its format, strips at their natural size
    // (16^3 = 256x16), else as edited.
    const ExportTargetInfo& t = exportTargetInfo(m_target);
    const bool strip = !c.layout.isEmpty();
    const bool atlas = c.format == QLatin1String(kAtlasFormat);
    const formats::LutDestination d = formats::resolveLutDestination(
        {("export" + c.extension).toStdString(), atlas ? "strip" : c.format.toStdString(),
         std::nullopt, 0,
         strip ? std::optional(parseLayout(c.layout.toStdString())) : std::nullopt});
    m_size->setValue(d.fixedSize                                    ? d.fixedSize
                     : c.format == QString::fromStdString(t.format) ? t.size
                     : strip                                        ? formats::kLutImageSize
                                                                    : 0);
    m_size->setEnabled(d.fixedSize == 0);
    m_bitDepth->setCurrentIndex(0);
    m_dither->setChecked(false);
    updateNote();
}

bool ExportDialog::matchesPreview() const {
    const ExportTargetInfo& t = exportTargetInfo(m_target);
    const FormatOptions want = targetFormatOptions(m_target);
    const ExportChoice c = choice();
    const FormatOptions o = options();
    // Another layout of the same strip holds the same entries.
    const bool sameFormat = c.format == QString::fromStdString(t.format);
    return sameFormat && o.size == want.size && (o.bitDepth == 0 || o.bitDepth == want.bitDepth) &&
           !o.dither && isFullStrength(strength());
}

void ExportDialog::updateNote() {
    QString what = exportTargetInfo(m_target).purpose == LutPurpose::Smash
                       ? tr("the Smash Ultimate game LUT that shows your edit (16³), "
                            "marked as the game's (LUTKIT_PURPOSE smash)")
                       : tr("the LUT as edited, marked as an edit (LUTKIT_PURPOSE raw)");
    if (choice().format == QLatin1String(kAtlasFormat))
        what += tr(", as the last row of the atlas: a file that is an atlas keeps its rows, a new "
                   "one starts with the neutral row (MultiLUT's \"Neutral\")");
    const StrengthAmounts a = strengthAmounts(strength());
    if (a.luma != 1.0 || a.chroma != 1.0)
        what += a.luma == a.chroma
                    ? tr(", at strength %1").arg(a.luma)
                    : tr(", at lightness %1 and colour %2").arg(a.luma).arg(a.chroma);
    const QString target = QString::fromStdString(exportTargetInfo(m_target).label);
    m_note->setText(matchesPreview()
                        ? tr("%1; exactly what the preview shows (target: %2).").arg(what, target)
                        : tr("%1, written differently from the target's file (%2): the "
                             "preview shows that one.")
                              .arg(what, target));
}

void ExportDialog::browse() {
    const ExportChoice c = choice();
    const QString file =
        QFileDialog::getSaveFileName(this, tr("Export LUT"), m_path->text(),
                                     QStringLiteral("%1 (*%2)").arg(c.label, c.extension));
    if (!file.isEmpty())
        m_path->setText(file);
}

QString ExportDialog::path() const {
    return m_path->text();
}

ExportChoice ExportDialog::choice() const {
    const int i = m_format->currentIndex();
    return i >= 0 && i < m_choices.size() ? m_choices[i] : ExportChoice{};
}

StrengthOptions ExportDialog::strength() const {
    StrengthOptions s;
    s.strength = m_strength->value();
    if (m_separate->isChecked()) {
        s.luma = m_luma->value();
        s.chroma = m_chroma->value();
    }
    return s;
}

void ExportDialog::setStrength(const StrengthOptions& s) {
    const StrengthAmounts a = strengthAmounts(s);
    m_strength->setValue(s.strength);
    m_luma->setValue(a.luma);
    m_chroma->setValue(a.chroma);
    m_separate->setChecked(a.luma != a.chroma);
}

FormatOptions ExportDialog::options() const {
    FormatOptions o;
    o.layout = parseOptionalLayout(choice().layout.toStdString());
    o.size = m_size->value();
    o.bitDepth = m_bitDepth->currentData().toInt();
    o.dither = m_dither->isChecked();
    return o;
}

} // namespace lut::gui
