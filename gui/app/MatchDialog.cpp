// SPDX-License-Identifier: Apache-2.0
#include "MatchDialog.h"

#include "Document.h"
#include "ErrorText.h"
#include "PreviewController.h"
#include "Prompts.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

namespace lut::gui {

QSlider* MatchDialog::addAmount(QFormLayout* form, const QString& label, const char* name) {
    // percent: 0 = neutral, 100 = the match, 200 = twice; the number box shows and takes it
    auto* s = new QSlider(Qt::Horizontal, this);
    s->setObjectName(QString::fromLatin1(name));
    s->setRange(0, 200);
    s->setValue(100);
    auto* box = new QSpinBox(this);
    box->setObjectName(QString::fromLatin1(name) + QStringLiteral(".value"));
    box->setRange(0, 200);
    box->setSuffix(QStringLiteral(" %"));
    box->setValue(100);
    connect(s, &QSlider::valueChanged, box, &QSpinBox::setValue);
    // held: the preview renders its proxy (as the Adjustments panel's sliders), the full frame
    // follows on release
    connect(s, &QSlider::sliderPressed, this, [this] { m_preview->setInteractive(true); });
    connect(s, &QSlider::sliderReleased, this, [this] { m_preview->setInteractive(false); });
    connect(box, &QSpinBox::valueChanged, s, &QSlider::setValue);
    auto* row = new QHBoxLayout;
    row->addWidget(s, 1);
    row->addWidget(box);
    form->addRow(label, row);
    return s;
}

void MatchDialog::keepAmount(QSlider* slider) {
    (slider == m_luma ? m_lumaOwn : m_chromaOwn) = true;
    apply();
}

MatchDialog::MatchDialog(QWidget* parent, const EditorContext& context,
                         std::unique_ptr<MatchSession> session)
    : QDialog(parent), m_doc(context.document), m_preview(context.preview),
      m_prompts(context.prompts), m_session(std::move(session)) {
    setWindowTitle(tr("Match to Reference"));
    setObjectName("matchDialog");
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("The open picture matched to <b>%1</b>: the preview shows "
                                    "the result while you move the sliders.")
                                     .arg(QFileInfo(m_session->referencePath()).fileName()),
                                 this));
    auto* form = new QFormLayout;
    m_strength = addAmount(form, tr("Strength"), "matchStrength");
    m_luma = addAmount(form, tr("Lightness share"), "matchLuma");
    m_chroma = addAmount(form, tr("Colour share"), "matchChroma");
    m_luma->setToolTip(tr("How much of the match's lightness change: follows Strength until "
                          "you move it"));
    m_chroma->setToolTip(tr("How much of the match's colour change: follows Strength until you "
                            "move it"));
    auto* keep = new QHBoxLayout;
    const char* names[3] = {"matchPreserveLuma", "matchPreserveNeutrals", "matchPreserveSkin"};
    const QString labels[3] = {tr("Lightness"), tr("Neutrals"), tr("Skin tones")};
    for (int i = 0; i < 3; ++i) {
        m_preserve[i] = new QCheckBox(labels[i], this);
        m_preserve[i]->setObjectName(QString::fromLatin1(names[i]));
        keep->addWidget(m_preserve[i]);
        connect(m_preserve[i], &QCheckBox::toggled, this, &MatchDialog::apply);
    }
    form->addRow(tr("Keep the picture's"), keep);
    layout->addLayout(form);
    m_report = new QPlainTextEdit(this);
    m_report->setObjectName("matchReport");
    m_report->setReadOnly(true);
    m_report->setPlainText(m_session->reportText());
    m_report->setMinimumSize(560, 160);
    layout->addWidget(m_report);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &MatchDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &MatchDialog::reject);
    layout->addWidget(buttons);
    // Lightness and Colour share show Strength's value while they follow it (their number boxes
    // too: the signal is blocked for the slider only); once moved on their own they keep theirs.
    connect(m_strength, &QSlider::valueChanged, this, [this](int v) {
        for (QSlider* s : {m_luma, m_chroma})
            if (!(s == m_luma ? m_lumaOwn : m_chromaOwn)) {
                const QSignalBlocker block(s);
                s->setValue(v);
                if (auto* box = findChild<QSpinBox*>(s->objectName() + QStringLiteral(".value")))
                    box->setValue(v);
            }
        apply();
    });
    connect(m_luma, &QSlider::valueChanged, this, [this] { keepAmount(m_luma); });
    connect(m_chroma, &QSlider::valueChanged, this, [this] { keepAmount(m_chroma); });
    m_baker = new MatchBaker(m_session->transfer(), m_session->tableTitle(), this);
    connect(m_baker, &MatchBaker::baked, this, &MatchDialog::showBaked);
    connect(m_baker, &MatchBaker::failed, this, [this](const QString& message) {
        m_acceptWanted = false;
        m_ok->setEnabled(true);
        m_prompts->reportError(tr("Cannot match"), message);
    });
    apply();
}

bool MatchDialog::isBaking() const {
    return m_baker->isBusy();
}

void MatchDialog::waitForBake() {
    m_baker->waitForIdle();
}

void MatchDialog::apply() {
    MatchOptions o = m_session->options();
    o.strength = m_strength->value() / 100.0;
    o.lumaStrength.reset(); // following Strength: unset, as lutkit match without the option
    o.chromaStrength.reset();
    if (m_lumaOwn)
        o.lumaStrength = m_luma->value() / 100.0;
    if (m_chromaOwn)
        o.chromaStrength = m_chroma->value() / 100.0;
    o.preserve.clear();
    const MatchPreserve kinds[3] = {MatchPreserve::Luma, MatchPreserve::Neutrals,
                                    MatchPreserve::Skin};
    for (int i = 0; i < 3; ++i)
        if (m_preserve[i]->isChecked())
            o.preserve.push_back(kinds[i]);
    m_session->setOptions(o);
    m_baker->request(o); // on the worker: showBaked() takes the table
}

void MatchDialog::showBaked(std::shared_ptr<const Lut3D> table, bool exact) {
    // Not exact: the values a drag passed, overtaken while baking; still closer than what the
    // preview shows, and the exact table follows.
    LutSource source;
    source.effective = table;
    m_preview->setSource(source);
    if (exact && m_acceptWanted)
        commit(*table);
}

void MatchDialog::accept() {
    if (const std::shared_ptr<const Lut3D> table = m_baker->exactTable()) {
        commit(*table);
        return;
    }
    m_acceptWanted = true; // showBaked() commits the sliders' table when it is baked
    m_ok->setEnabled(false);
    if (!m_baker->isBusy())
        apply(); // the last bake failed: again (its error is shown again)
}

void MatchDialog::commit(const Lut3D& table) {
    m_acceptWanted = false;
    m_ok->setEnabled(true);
    try {
        const QString ref = QFileInfo(m_session->referencePath()).fileName();
        m_doc->replaceLutUndoable(table, tr("matched to %1").arg(ref), tr("Match to %1").arg(ref));
        m_baker->drop();
        m_preview->setInteractive(false);
        QDialog::accept();
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot match"), QString::fromStdString(humanErrorText(e)));
    }
}

void MatchDialog::reject() {
    m_baker->drop(); // a table still baking never reaches the preview
    m_acceptWanted = false;
    m_ok->setEnabled(true);
    m_preview->setInteractive(false);
    m_preview->setSource(m_doc->lutSource());
    QDialog::reject();
}

} // namespace lut::gui
