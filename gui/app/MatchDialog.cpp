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
#include <QSlider>
#include <QVBoxLayout>

namespace lut::gui {

namespace {

QSlider* amountSlider(QWidget* parent, const char* name, int value) {
    auto* s = new QSlider(Qt::Horizontal, parent);
    s->setObjectName(QString::fromLatin1(name));
    s->setRange(0, 200); // percent: 0 = neutral, 100 = the match, 200 = twice
    s->setValue(value);
    return s;
}

} // namespace

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
    m_strength = amountSlider(this, "matchStrength", 100);
    m_luma = amountSlider(this, "matchLuma", 100);
    m_chroma = amountSlider(this, "matchChroma", 100);
    form->addRow(tr("Strength"), m_strength);
    form->addRow(tr("Lightness share"), m_luma);
    form->addRow(tr("Colour share"), m_chroma);
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
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        try {
            m_doc->startFrom(
                m_session->table(),
                tr("matched to %1").arg(QFileInfo(m_session->referencePath()).fileName()));
            accept();
        } catch (const std::exception& e) {
            m_prompts->reportError(tr("Cannot match"),
                                   QString::fromStdString(humanErrorText(e.what())));
        }
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &MatchDialog::reject);
    layout->addWidget(buttons);
    // The second slider's value while the first moves: luma and chroma follow strength until
    // moved on their own.
    connect(m_strength, &QSlider::valueChanged, this, [this](int v) {
        for (QSlider* s : {m_luma, m_chroma}) {
            const QSignalBlocker block(s);
            s->setValue(v);
        }
        apply();
    });
    connect(m_luma, &QSlider::valueChanged, this, &MatchDialog::apply);
    connect(m_chroma, &QSlider::valueChanged, this, &MatchDialog::apply);
    apply();
}

void MatchDialog::apply() {
    MatchOptions o = m_session->options();
    o.strength = m_strength->value() / 100.0;
    o.lumaStrength = m_luma->value() / 100.0;
    o.chromaStrength = m_chroma->value() / 100.0;
    o.preserve.clear();
    const MatchPreserve kinds[3] = {MatchPreserve::Luma, MatchPreserve::Neutrals,
                                    MatchPreserve::Skin};
    for (int i = 0; i < 3; ++i)
        if (m_preserve[i]->isChecked())
            o.preserve.push_back(kinds[i]);
    m_session->setOptions(o);
    try {
        LutSource source;
        source.effective = std::make_shared<const Lut3D>(m_session->table());
        m_preview->setSource(source);
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot match"),
                               QString::fromStdString(humanErrorText(e.what())));
    }
}

void MatchDialog::reject() {
    m_preview->setSource(m_doc->lutSource());
    QDialog::reject();
}

} // namespace lut::gui
