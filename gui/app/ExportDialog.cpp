#include "ExportDialog.h"

#include "lut/formats/Registry.h"
#include "lut/io/Layout.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
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
    return out;
}

ExportDialog::ExportDialog(const QString& suggestedBase, QWidget* parent)
    : QDialog(parent), m_choices(exportChoices()), m_base(suggestedBase) {
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
    m_path->setMinimumWidth(360);
    auto* browse = new QPushButton(tr("Browse…"), this);
    pathRow->addWidget(m_path);
    pathRow->addWidget(browse);
    form->addRow(tr("File"), pathRow);

    m_size = new QSpinBox(this);
    m_size->setRange(0, 256);
    m_size->setSpecialValueText(tr("as edited / format default"));
    form->addRow(tr("Size"), m_size);
    m_bitDepth = new QComboBox(this);
    m_bitDepth->addItem(tr("format default"), 0);
    m_bitDepth->addItem(tr("8-bit"), 8);
    m_bitDepth->addItem(tr("16-bit"), 16);
    m_bitDepth->addItem(tr("32-bit float"), 32);
    form->addRow(tr("Bit depth"), m_bitDepth);
    m_dither = new QCheckBox(tr("Ordered dither for 8-bit images"), this);
    form->addRow(QString(), m_dither);
    m_compensate =
        new QCheckBox(tr("Game compensation (Smash): the game shows this LUT's look"), this);
    m_compensate->setObjectName("compensate");
    m_compensate->setToolTip(
        tr("Writes the 16³ LUT that makes Smash Ultimate's grading and "
           "brighten pass reproduce the LUT as edited (docs/specs/smash-pipeline.md)"));
    form->addRow(QString(), m_compensate);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::choiceChanged);
    choiceChanged();
}

void ExportDialog::choiceChanged() {
    const ExportChoice c = choice();
    const QString layoutSuffix = c.layout.isEmpty() ? QString() : QStringLiteral("_") + c.layout;
    m_path->setText(m_base + layoutSuffix + c.extension);
    m_compensate->setChecked(c.format == QLatin1String("nutexb"));
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

FormatOptions ExportDialog::options() const {
    FormatOptions o;
    o.layout = parseOptionalLayout(choice().layout.toStdString());
    o.size = m_size->value();
    o.bitDepth = m_bitDepth->currentData().toInt();
    o.dither = m_dither->isChecked();
    return o;
}

bool ExportDialog::smashCompensate() const {
    return m_compensate->isChecked();
}

} // namespace lut::gui
