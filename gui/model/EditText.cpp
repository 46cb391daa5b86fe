// SPDX-License-Identifier: Apache-2.0
#include "EditText.h"

#include "AdjustParam.h"
#include "Document.h"

#include <QCoreApplication>
#include <QStringList>

#include <vector>

namespace lut::gui {

namespace {

QString curveText(const Curve& c) {
    const int n = static_cast<int>(c.points().size());
    QString s = n == 1 ? QCoreApplication::translate("lut::gui", "1 point")
                       : QCoreApplication::translate("lut::gui", "%1 points").arg(n);
    int shown = 0;
    for (const glm::dvec2& p : c.points()) {
        if (++shown > 5) {
            s += QStringLiteral(" …");
            break;
        }
        s += QStringLiteral(" (%1, %2)").arg(p.x, 0, 'f', 2).arg(p.y, 0, 'f', 2);
    }
    return s;
}

} // namespace

QString describeAdjustmentChange(const QString& action, const Adjustments& before,
                                 const Adjustments& after) {
    struct Change {
        QString what, values;
    };
    std::vector<Change> changes;
    for (const AdjustParamInfo& p : adjustParams()) {
        const double a = getParam(before, p.id), b = getParam(after, p.id);
        if (a == b)
            continue;
        QString ta = QString::number(a, 'f', p.decimals), tb = QString::number(b, 'f', p.decimals);
        if (ta == tb) { // a change finer than the dock shows
            ta = QString::number(a, 'g', 6);
            tb = QString::number(b, 'g', 6);
        }
        changes.push_back({QString::fromStdString(p.label), ta + QStringLiteral(" → ") + tb});
    }
    for (CurveId id : {CurveId::Master, CurveId::Red, CurveId::Green, CurveId::Blue,
                       CurveId::HueVsHue, CurveId::HueVsSat, CurveId::HueVsLum})
        if (!(curveOf(before, id) == curveOf(after, id)))
            changes.push_back({QString::fromLatin1(curveLabel(id)), curveText(curveOf(after, id))});
    if (changes.empty())
        return action;
    // One change the action names already ("Set Exposure (stops)"): its values alone.
    if (changes.size() == 1 && action.contains(changes[0].what, Qt::CaseInsensitive))
        return action + QStringLiteral(": ") + changes[0].values;
    QStringList shown;
    for (std::size_t i = 0; i < changes.size() && i < 3; ++i)
        shown << changes[i].what + QLatin1Char(' ') + changes[i].values;
    QString s = action + QStringLiteral(": ") + shown.join(QStringLiteral(", "));
    if (changes.size() > 3)
        s += QCoreApplication::translate("lut::gui", " and %1 more")
                 .arg(static_cast<int>(changes.size()) - 3);
    return s;
}

} // namespace lut::gui
