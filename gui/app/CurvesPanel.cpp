#include "CurvesPanel.h"

#include "CurveEditor.h"

#include <QButtonGroup>
#include <QGridLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace lut::gui {

CurvesPanel::CurvesPanel(Document* doc, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_editor(new CurveEditor(doc, CurveId::Master, this)),
      m_choice(new QButtonGroup(this)) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);
    auto* grid = new QGridLayout;
    grid->setSpacing(2);
    const std::pair<CurveId, QString> choices[] = {
        {CurveId::Master, tr("Master")},
        {CurveId::Red, tr("R")},
        {CurveId::Green, tr("G")},
        {CurveId::Blue, tr("B")},
        {CurveId::HueVsHue, tr("Hue vs Hue")},
        {CurveId::HueVsSat, tr("Hue vs Sat")},
        {CurveId::HueVsLum, tr("Hue vs Lum")},
    };
    int i = 0;
    for (const auto& [id, label] : choices) {
        auto* b = new QPushButton(label, this);
        b->setCheckable(true);
        b->setObjectName(QStringLiteral("curve.%1").arg(static_cast<int>(id)));
        m_choice->addButton(b, static_cast<int>(id));
        // Tone curves on the first row, hue curves on the second.
        if (i < 4)
            grid->addWidget(b, 0, i);
        else
            grid->addWidget(b, 1, (i - 4) * 4 / 3, 1, i == 6 ? 2 : 1);
        ++i;
    }
    m_choice->button(static_cast<int>(CurveId::Master))->setChecked(true);
    v->addLayout(grid);
    v->addWidget(m_editor, 1);
    auto* reset = new QPushButton(tr("Reset curve"), this);
    reset->setObjectName("resetCurve");
    v->addWidget(reset);
    connect(m_choice, &QButtonGroup::idClicked, this,
            [this](int id) { showCurve(static_cast<CurveId>(id)); });
    connect(reset, &QPushButton::clicked, this, [this] {
        const CurveId id = m_editor->curveId();
        const bool hue = m_editor->isHueCurve();
        m_doc->editCurve(id, Curve(hue ? CurveKind::Hue : CurveKind::Tone));
        m_doc->endGesture();
    });
    connect(m_editor, &CurveEditor::interactiveChanged, this, &CurvesPanel::interactiveChanged);
}

void CurvesPanel::showCurve(CurveId id) {
    m_editor->setCurveId(id);
    if (auto* b = m_choice->button(static_cast<int>(id)))
        b->setChecked(true);
}

} // namespace lut::gui
