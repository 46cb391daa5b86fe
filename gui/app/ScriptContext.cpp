// SPDX-License-Identifier: Apache-2.0
#include "ScriptContext.h"

#include "BackgroundTask.h"
#include "ExportDialog.h"
#include "FileActions.h"
#include "FileLoader.h"
#include "MainWindow.h"
#include "WindowActions.h"

#include <QApplication>
#include <QDir>

namespace lut::gui {

void need(bool ok, const QString& why) {
    if (!ok)
        throw ScriptFailure(why.toStdString());
}

bool onOff(const QString& v) {
    if (v == QLatin1String("on"))
        return true;
    if (v == QLatin1String("off"))
        return false;
    throw ScriptFailure("expected on or off, got '" + v.toStdString() + "'");
}

QString onOffText(bool v) {
    return v ? QStringLiteral("on") : QStringLiteral("off");
}

ScriptContext::ScriptContext(ScriptSession& s, QStringList arguments)
    : session(s), w(s.window), out(s.out), args(std::move(arguments)), error0(w.lastError()) {}

Document* ScriptContext::doc() const {
    return w.document();
}

PreviewController* ScriptContext::preview() const {
    return w.preview();
}

QString ScriptContext::arg(int i) const {
    need(i < args.size(), QStringLiteral("missing argument %1").arg(i + 1));
    return args[i];
}

void ScriptContext::setOptions(const std::function<void(PreviewOptions&)>& change) const {
    PreviewOptions o = preview()->options();
    change(o);
    preview()->setOptions(o);
}

void ScriptContext::noNewError(bool ok) const {
    need(ok, w.lastError().isEmpty() || w.lastError() == error0 ? QStringLiteral("failed")
                                                                : w.lastError());
}

void settle(MainWindow& w) {
    w.waitForLoads();
    w.windowActions()->compareTask()->waitForIdle();
    w.windowActions()->matchTask()->waitForIdle();
    w.fileActions()->saveTask()->waitForIdle();
    w.waitForPreview();
    QApplication::processEvents();
}

BackgroundTask* taskByName(MainWindow& w, const QString& name) {
    BackgroundTask* t = name == "compare"        ? w.windowActions()->compareTask()
                        : name == "match"        ? w.windowActions()->matchTask()
                        : name == "save-preview" ? w.fileActions()->saveTask()
                                                 : nullptr;
    need(t != nullptr,
         QStringLiteral("unknown task '%1' (load, compare, match, save-preview)").arg(name));
    return t;
}

QString taskState(MainWindow& w, const QString& name) {
    auto state = [](bool busy, double fraction, const QString& idle) {
        return busy ? QStringLiteral("busy %1 %").arg(static_cast<int>(fraction * 100)) : idle;
    };
    auto outcome = [](BackgroundTask* t) {
        switch (t->lastOutcome()) {
        case BackgroundTask::Outcome::Done:
            return QStringLiteral("idle done");
        case BackgroundTask::Outcome::Cancelled:
            return QStringLiteral("idle cancelled");
        case BackgroundTask::Outcome::Failed:
            return QStringLiteral("idle failed");
        case BackgroundTask::Outcome::None:
            break;
        }
        return QStringLiteral("idle");
    };
    if (name == "load")
        return state(w.fileActions()->loader()->isBusy(), w.fileActions()->loader()->fraction(),
                     QStringLiteral("idle"));
    BackgroundTask* t = taskByName(w, name);
    return state(t->isBusy(), t->fraction(), outcome(t));
}

const AdjustParamInfo& paramByKey(const QString& key) {
    for (const auto& p : adjustParams())
        if (QString::fromStdString(p.key) == key)
            return p;
    throw ScriptFailure("unknown adjustment '" + key.toStdString() + "'");
}

CurveId curveByName(const QString& n) {
    const std::pair<const char*, CurveId> names[] = {
        {"master", CurveId::Master},    {"red", CurveId::Red},
        {"green", CurveId::Green},      {"blue", CurveId::Blue},
        {"hue.hue", CurveId::HueVsHue}, {"hue.sat", CurveId::HueVsSat},
        {"hue.lum", CurveId::HueVsLum}};
    for (const auto& [name, id] : names)
        if (n == QLatin1String(name))
            return id;
    throw ScriptFailure("unknown curve '" + n.toStdString() + "'");
}

QWidget* widgetByName(MainWindow& w, const QString& name) {
    for (QWidget* c : w.findChildren<QWidget*>(name))
        if (c->isVisible() || c->isVisibleTo(&w))
            return c;
    throw ScriptFailure("no widget named '" + name.toStdString() + "'");
}

QString suggestedExport(MainWindow& w, ExportChoice* choice) {
    ExportNameInput naming;
    naming.lutPath = w.document()->lutPath();
    naming.imagePath = w.document()->imagePath();
    naming.fallbackFolder = QDir::currentPath();
    ExportDialog dlg(w.document()->target(), naming, &w);
    *choice = dlg.choice();
    return dlg.path();
}

} // namespace lut::gui
