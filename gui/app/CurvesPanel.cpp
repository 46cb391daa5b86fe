// SPDX-License-Identifier: Apache-2.0
#include "CurvesPanel.h"
#include "FocusWheel.h"

#include "CurveEditor.h"
#include "HueRanges.h"

#include <QButtonGroup>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace lut::gui {

namespace {

// The chosen curve's button in the highlight colour, bold: which curve the editor edits is never
// a matter of telling two greys apart.
const char* kChoiceStyle = "QPushButton { padding: 3px 2px; }"
                           "QPushButton:checked { background: #3d8ee6; color: white; "
                           "font-weight: bold; border: 1px solid #8cc0ff; }";

} // namespace

CurvesPanel::CurvesPanel(Document* doc, QWidget* parent)
    : QWidget(parent), m_doc(doc), m_editor(new CurveEditor(doc, CurveId::Master, this)),
      m_choice(new QButtonGroup(this)) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);
    auto* grid = new QGridLayout;
    grid->setSpacing(2);
    auto* hueRow = new QHBoxLayout; // three equal buttons: the names fit in bold
    hueRow->setSpacing(2);
    const CurveId choices[] = {CurveId::Master,  CurveId::Red,      CurveId::Green,
                               CurveId::Blue,    CurveId::HueVsHue, CurveId::HueVsSat,
                               CurveId::HueVsLum};
    int i = 0;
    for (const CurveId id : choices) {
        const QString label =
            i > 0 && i < 4 ? CurveEditor::curveName(id).left(1) : CurveEditor::curveName(id);
        auto* b = new QPushButton(label, this);
        b->setCheckable(true);
        b->setStyleSheet(QString::fromLatin1(kChoiceStyle));
        b->setObjectName(QStringLiteral("curve.%1").arg(static_cast<int>(id)));
        b->setToolTip(tr("Edit the %1 curve").arg(CurveEditor::curveName(id)));
        m_choice->addButton(b, static_cast<int>(id));
        // Tone curves on the first row, hue curves on the second.
        if (i < 4)
            grid->addWidget(b, 0, i);
        else
            hueRow->addWidget(b, 1);
        ++i;
    }
    m_choice->button(static_cast<int>(CurveId::Master))->setChecked(true);
    v->addLayout(grid);
    v->addLayout(hueRow);
    v->addWidget(m_editor, 1);

    // Hue curves: the six ranges and the selected point's amount.
    m_hueRow = new QWidget(this);
    auto* hv = new QVBoxLayout(m_hueRow);
    hv->setContentsMargins(0, 0, 0, 0);
    hv->setSpacing(2);
    auto* ranges = new QHBoxLayout;
    ranges->setSpacing(2);
    for (const HueRange& r : hueRanges()) {
        auto* b = new QPushButton(tr(r.label), m_hueRow);
        b->setObjectName(QStringLiteral("hueRange.%1").arg(QString::fromLatin1(r.key)));
        const QColor c = QColor::fromHsv(static_cast<int>(r.centre) % 360, 190, 220);
        b->setStyleSheet(QStringLiteral("QPushButton { padding: 2px 2px; border-bottom: 3px solid "
                                        "%1; }")
                             .arg(c.name()));
        b->setToolTip(tr("Select the %1 (%2°) on this curve: only hues within 60° of it change")
                          .arg(tr(r.label).toLower())
                          .arg(r.centre));
        connect(b, &QPushButton::clicked, this,
                [this, centre = r.centre] { m_editor->selectHue(centre); });
        ranges->addWidget(b);
    }
    hv->addLayout(ranges);
    auto* amountRow = new QHBoxLayout;
    m_pointLabel = new QLabel(m_hueRow);
    m_pointLabel->setObjectName("hueRange.point");
    m_amount = new QDoubleSpinBox(m_hueRow);
    takeWheelOnlyWhenFocused(m_amount);
    m_amount->setObjectName("hueRange.amount");
    m_amount->setKeyboardTracking(false);
    m_amount->setToolTip(tr("The selected point's value: hue shift in degrees, or the saturation "
                            "or luminance change (-1 .. 1; 0 = none)"));
    amountRow->addWidget(m_pointLabel, 1);
    amountRow->addWidget(new QLabel(tr("Amount"), m_hueRow));
    amountRow->addWidget(m_amount);
    hv->addLayout(amountRow);
    v->addWidget(m_hueRow);
    connect(m_amount, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_editor->selectedPoint() >= 0)
            m_editor->setSelectedValue(value);
    });
    connect(m_editor, &CurveEditor::selectionChanged, this, &CurvesPanel::updateHueRow);
    connect(m_doc, &Document::adjustmentsChanged, this, &CurvesPanel::updateHueRow);

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
    updateHueRow();
}

void CurvesPanel::showCurve(CurveId id) {
    m_editor->setCurveId(id);
    if (auto* b = m_choice->button(static_cast<int>(id)))
        b->setChecked(true);
    updateHueRow();
}

CurveId CurvesPanel::shownCurve() const {
    return m_editor->curveId();
}

QPushButton* CurvesPanel::curveButton(CurveId id) const {
    return qobject_cast<QPushButton*>(m_choice->button(static_cast<int>(id)));
}

QPushButton* CurvesPanel::rangeButton(const char* key) const {
    return findChild<QPushButton*>(QStringLiteral("hueRange.%1").arg(QString::fromLatin1(key)));
}

void CurvesPanel::updateHueRow() {
    const bool hue = m_editor->isHueCurve();
    m_hueRow->setVisible(hue);
    if (!hue)
        return;
    const bool degrees = m_editor->curveId() == CurveId::HueVsHue;
    const QSignalBlocker block(m_amount);
    m_amount->setDecimals(degrees ? 1 : 2);
    m_amount->setSingleStep(degrees ? 1.0 : 0.05);
    m_amount->setRange(m_editor->yMin(), m_editor->yMax());
    m_amount->setSuffix(degrees ? QStringLiteral("°") : QString());
    const int selected = m_editor->selectedPoint();
    m_amount->setEnabled(selected >= 0);
    if (selected < 0) {
        m_pointLabel->setText(tr("Click the curve or pick a range"));
        m_amount->setValue(0.0);
        return;
    }
    const glm::dvec2 p = m_editor->selectedPointValue();
    m_pointLabel->setText(tr("Point at %1°").arg(std::lround(p.x)));
    m_amount->setValue(p.y);
}

} // namespace lut::gui
