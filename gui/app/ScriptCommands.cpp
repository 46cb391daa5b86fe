// SPDX-License-Identifier: Apache-2.0
#include "ScriptCommands.h"

#include "AdjustmentsPanel.h"
#include "BackgroundTask.h"
#include "CheckModel.h"
#include "CheckPanel.h"
#include "Comparison.h"
#include "CurvesPanel.h"
#include "DialogResponder.h"
#include "ExportDialog.h"
#include "ExportedLut.h"
#include "FileActions.h"
#include "HueRanges.h"
#include "MainWindow.h"
#include "MatchDialog.h"
#include "RepaintProbe.h"
#include "ScriptContext.h"
#include "ScriptInput.h"
#include "ScriptPrint.h"
#include "TaskStatus.h"
#include "WindowActions.h"

#include "lut/io/Layout.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QListWidget>
#include <QPushButton>
#include <QSaveFile>
#include <QSlider>
#include <QStatusBar>
#include <QThread>
#include <QToolButton>
#include <QUndoStack>

#include <cstdio>

namespace lut::gui {

namespace {

bool isHueCurve(CurveId id) {
    return id == CurveId::HueVsHue || id == CurveId::HueVsSat || id == CurveId::HueVsLum;
}

void openLut(ScriptContext& c) {
    FormatOptions o;
    if (c.args.size() > 1)
        o.layout = parseOptionalLayout(c.args[1].toStdString());
    c.noNewError(c.w.openLutFile(c.arg(0), o));
}

void lutTarget(ScriptContext& c) { // what LUTs that do not say are for (raw, smash, ask)
    const QString v = c.arg(0);
    c.w.setLutPurposeAnswer(
        v == "ask" ? std::nullopt : std::optional<LutPurpose>(parseLutPurpose(v.toStdString())));
}

void chain(ScriptContext& c) {
    const QString n = c.arg(0);
    const Preset p = n == "filmic"      ? Preset::Pilot
                     : n == "cinematic" ? Preset::Lecture
                                        : parsePreset(n.toStdString());
    c.setOptions([&](PreviewOptions& o) { o.preset = p; });
}

void setParam(ScriptContext& c) {
    const AdjustParamInfo& p = paramByKey(c.arg(0));
    bool ok = false;
    const double v = c.arg(1).toDouble(&ok);
    need(ok && v >= p.min && v <= p.max,
         QStringLiteral("%1 takes a number from %2 to %3").arg(c.arg(0)).arg(p.min).arg(p.max));
    c.doc()->editParam(p.id, v);
    c.doc()->endGesture();
}

void drag(ScriptContext& c) {
    const AdjustParamInfo& p = paramByKey(c.arg(0));
    QSlider* s = c.w.adjustmentsPanel()->slider(p.id);
    need(s->isVisible(), QStringLiteral("the %1 slider is not visible").arg(c.arg(0)));
    dragSlider(s, paramToSlider(p, c.arg(1).toDouble(), AdjustmentsPanel::kSteps));
}

void curve(ScriptContext& c) {
    const CurveId id = curveByName(c.arg(0));
    std::vector<glm::dvec2> pts;
    for (int i = 1; i < c.args.size(); ++i) {
        const QStringList xy = c.args[i].split(',');
        need(xy.size() == 2, QStringLiteral("expected X,Y, got '%1'").arg(c.args[i]));
        pts.push_back({xy[0].toDouble(), xy[1].toDouble()});
    }
    c.doc()->editCurve(id, Curve(isHueCurve(id) ? CurveKind::Hue : CurveKind::Tone, pts));
    c.doc()->endGesture();
}

// As a user does: the curve's button, the range's button, a value typed in Amount.
void hueRange(ScriptContext& c) {
    const CurveId id = curveByName(c.arg(0));
    need(isHueCurve(id), QStringLiteral("hue-range takes hue.hue, hue.sat or hue.lum"));
    const HueRange* range = hueRangeByKey(c.arg(1).toLatin1().constData());
    need(range != nullptr, QStringLiteral("unknown hue range '%1' (reds yellows greens cyans "
                                          "blues magentas)")
                               .arg(c.arg(1)));
    bool ok = false;
    const double amount = c.arg(2).toDouble(&ok);
    need(ok, QStringLiteral("expected an amount, got '%1'").arg(c.arg(2)));
    CurvesPanel* panel = c.w.curvesPanel();
    panel->curveButton(id)->click();
    panel->rangeButton(range->key)->click();
    need(panel->amountBox()->isEnabled(), QStringLiteral("no point selected"));
    panel->amountBox()->setValue(amount);
}

// The status bar's Cancel button of that task, clicked.
void cancel(ScriptContext& c) {
    const QString name =
        c.arg(0) == "load"
            ? QStringLiteral("loading")
            : QStringLiteral("task.") +
                  (c.arg(0) == "save-preview" ? QStringLiteral("savePreview") : c.arg(0));
    auto* status = c.w.statusBar()->findChild<TaskStatus*>(name);
    need(status != nullptr, QStringLiteral("unknown task '%1'").arg(c.arg(0)));
    need(status->isVisible(), QStringLiteral("%1 is not running").arg(c.arg(0)));
    status->cancelButton()->click();
    QApplication::processEvents();
}

// Processes events until the task is done (the window stays live meanwhile).
void waitTask(ScriptContext& c) {
    if (c.arg(0) == "load")
        c.w.waitForLoads();
    else
        taskByName(c.w, c.arg(0))->waitForIdle();
}

void probe(ScriptContext& c) {
    RepaintProbe*& probe = c.session.probe;
    if (onOff(c.arg(0))) {
        if (!probe) {
            probe = new RepaintProbe(c.w.statusBar());
            c.w.statusBar()->addPermanentWidget(probe);
        }
        probe->start();
        return;
    }
    need(probe != nullptr, QStringLiteral("probe on first"));
    probe->stop();
    c.out << "probe longest-gap " << QString::number(probe->longestGapMs(), 'f', 1) << " ms own "
          << QString::number(probe->longestOwnGapMs(), 'f', 1) << " ms over " << probe->paints()
          << " paints\n";
}

void focus(ScriptContext& c) {
    QWidget* target = widgetByName(c.w, c.arg(0));
    // As a click does: the window becomes the active one (there may be no window manager to do
    // it), and a spin box takes the focus into its line edit.
    c.w.activateWindow();
    QApplication::setActiveWindow(target->window());
    target->setFocus(Qt::MouseFocusReason);
    QApplication::processEvents();
}

void key(ScriptContext& c) {
    const QKeySequence seq = QKeySequence::fromString(c.arg(0), QKeySequence::PortableText);
    need(!seq.isEmpty(), QStringLiteral("unknown key '%1'").arg(c.arg(0)));
    sendKeys(seq);
}

// strength=T, luma=T, chroma=T taken out of the arguments: the export dialog's strength (lutkit
// --strength ...).
StrengthOptions takeStrength(QStringList& args) {
    StrengthOptions strength;
    for (int i = args.size() - 1; i >= 0; --i) {
        const QString key = args[i].section(QLatin1Char('='), 0, 0);
        if (!args[i].contains(QLatin1Char('=')) ||
            (key != "strength" && key != "luma" && key != "chroma"))
            continue;
        bool ok = false;
        const double v = args[i].section(QLatin1Char('='), 1).toDouble(&ok);
        need(ok, QStringLiteral("%1 needs a number").arg(key));
        if (key == "strength")
            strength.strength = v;
        else if (key == "luma")
            strength.luma = v;
        else
            strength.chroma = v;
        args.removeAt(i);
    }
    return strength;
}

void exportLut(ScriptContext& c) {
    const bool overwrite = c.args.removeAll(QStringLiteral("overwrite")) > 0;
    const StrengthOptions strength = takeStrength(c.args);
    const ExportTarget target = c.doc()->target();
    ExportChoice choice;
    QString path = suggestedExport(c.w, &choice);
    FormatOptions o = targetFormatOptions(target);
    if (!c.args.isEmpty()) {
        path = c.args[0];
        choice.format = c.args.size() > 1 ? c.args[1] : QString();
        o = FormatOptions{};
        if (c.args.size() > 2)
            o.layout = parseOptionalLayout(c.args[2].toStdString());
        // The target's own file type (by the format that writes the path) takes the target's
        // settings.
        if (isTargetFile(target, path.toStdString(), choice.format.toStdString()))
            o = targetFormatOptions(target);
    }
    c.out << "exported " << path << "\n";
    c.noNewError(c.w.exportLut(path, choice.format, o, target, overwrite, strength));
}

void plotSave(ScriptContext& c) {
    settle(c.w);
    const Image plot = plotExportedLut(*c.doc(), c.doc()->target());
    c.noNewError(c.w.fileActions()->savePicture(c.arg(0), plot));
}

// Through Tools > Compare's worker, as the menu runs it; the report also opens.
void compare(ScriptContext& c) {
    settle(c.w);
    WindowActions* actions = c.w.windowActions();
    actions->startCompare(c.arg(0));
    actions->compareTask()->waitForIdle();
    need(actions->compareTask()->lastOutcome() == BackgroundTask::Outcome::Done &&
             actions->lastComparison(),
         c.w.lastError().isEmpty() ? QStringLiteral("the comparison failed") : c.w.lastError());
    const Comparison& comparison = *actions->lastComparison();
    char exact[40];
    std::snprintf(exact, sizeof exact, "%.9g", comparison.report.maxDeltaE);
    const QString text = comparisonText(comparison) + QStringLiteral("max-delta-e2000 ") +
                         QString::fromLatin1(exact);
    QSaveFile f(c.arg(1));
    need(f.open(QIODevice::WriteOnly) && f.write(text.toUtf8() + '\n') >= 0 && f.commit(),
         QStringLiteral("cannot write %1").arg(c.arg(1)));
    c.out << "compared " << c.arg(0) << ": max ΔE2000 " << exact << "\n";
}

// The Check panel raised and current; with N, finding N clicked (highlighted).
void check(ScriptContext& c) {
    settle(c.w);
    auto* dock = c.w.findChild<QDockWidget*>(QStringLiteral("dock.check"));
    dock->show();
    dock->raise();
    CheckPanel* panel = c.w.checkPanel();
    panel->model()->waitForIdle();
    QApplication::processEvents();
    if (!c.args.isEmpty()) {
        QListWidget* list = panel->findingsList();
        const int n = c.arg(0).toInt();
        const auto report = panel->model()->report();
        const int findings = report ? static_cast<int>(report->findings.size()) : 0;
        need(n >= 1 && n <= findings,
             QStringLiteral("check: no finding %1 (%2 listed)").arg(c.arg(0)).arg(findings));
        list->setCurrentRow(n - 1);
        emit list->itemClicked(list->item(n - 1));
        panel->model()->waitForIdle();
        QApplication::processEvents();
    }
    c.out << "check " << panel->verdictText() << "\n";
}

void screenshot(ScriptContext& c) {
    settle(c.w);
    const QImage shot = c.w.grab().toImage();
    QSaveFile f(c.arg(0));
    need(f.open(QIODevice::WriteOnly) && shot.save(&f, "PNG") && f.commit(),
         QStringLiteral("cannot write %1").arg(c.arg(0)));
}

void sleepMs(ScriptContext& c) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < c.arg(0).toInt()) {
        QApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(2);
    }
}

void dialogs(ScriptContext& c) {
    const QString how = c.arg(0);
    need(how == "accept" || how == "reject" || how == "hold",
         QStringLiteral("dialogs takes accept, reject or hold"));
    c.session.responder.hold = how == "hold";
    c.session.responder.accept = how == "accept";
}

// Tools > Match to Reference's dialog (open, `dialogs hold`): a slider dragged by hand over MS.
void matchDrag(ScriptContext& c) {
    MatchDialog* dlg = c.w.windowActions()->matchDialog();
    need(dlg && dlg->isVisible(), QStringLiteral("no match dialog is open (dialogs hold)"));
    const QString key = c.arg(0);
    const char* name = key == "strength" ? "matchStrength"
                       : key == "luma"   ? "matchLuma"
                       : key == "chroma" ? "matchChroma"
                                         : nullptr;
    need(name != nullptr, QStringLiteral("match-drag takes strength, luma or chroma"));
    auto* s = dlg->findChild<QSlider*>(QString::fromLatin1(name));
    bool ok = false;
    const int to = c.arg(1).toInt(&ok);
    need(s && ok && to >= s->minimum() && to <= s->maximum(),
         QStringLiteral("match-drag takes a percent from 0 to 200"));
    dragSlider(s, to, c.args.size() > 2 ? c.arg(2).toInt() : 0);
}

using C = ScriptContext;
using L = QLatin1StringView;

const ScriptCommand kCommands[] = {
    // Files
    {L("open-image"), "PATH", [](C& c) { c.noNewError(c.w.openImageFile(c.arg(0))); }},
    {L("open-lut"), "PATH [LAYOUT]", openLut},
    {L("drop"), "PATH...",
     [](C& c) {
         need(!c.args.isEmpty(), QStringLiteral("drop needs files"));
         c.noNewError(dropFiles(c.w, c.args));
     }},
    {L("lut-target"), "raw|smash|ask", lutTarget},
    {L("new-neutral"), "N", [](C& c) { c.w.fileActions()->newNeutral(c.arg(0).toInt()); }},
    {L("save"), "", [](C& c) { c.noNewError(c.w.saveDocument()); }},
    {L("save-as"), "PATH", [](C& c) { c.noNewError(c.w.saveDocumentAs(c.arg(0))); }},
    {L("adjustments-save"), "PATH",
     [](C& c) { c.noNewError(c.w.fileActions()->saveAdjustments(c.arg(0))); }},
    {L("adjustments-load"), "PATH",
     [](C& c) { c.noNewError(c.w.fileActions()->loadAdjustments(c.arg(0))); }},
    {L("export"), "[PATH [FORMAT [LAYOUT]]] [strength=T] [luma=T] [chroma=T] [overwrite]",
     exportLut},
    {L("save-preview"), "PATH",
     [](C& c) {
         settle(c.w);
         c.noNewError(c.w.savePreviewImage(c.arg(0)));
     }},
    {L("plot-save"), "PATH", plotSave},
    {L("screenshot"), "PATH", screenshot},
    // The target and the preview's options
    {L("target"), "smash|engine|cube|...",
     [](C& c) { c.doc()->setTarget(parseExportTarget(c.arg(0).toStdString())); }},
    {L("input"), "screenshot|scene",
     [](C& c) {
         const SceneKind k = parseSceneKind(c.arg(0).toStdString());
         c.setOptions([&](PreviewOptions& o) { o.input = k; });
     }},
    {L("chain"), "filmic|cinematic|none|PRESET", chain},
    {L("bloom"), "on|off",
     [](C& c) {
         const bool on = onOff(c.arg(0));
         c.setOptions([&](PreviewOptions& o) { o.bloom = on; });
     }},
    {L("lut"), "on|off",
     [](C& c) {
         const bool on = onOff(c.arg(0));
         c.setOptions([&](PreviewOptions& o) { o.lutEnabled = on; });
     }},
    {L("brighten"), "on|off",
     [](C& c) {
         const bool on = onOff(c.arg(0));
         c.setOptions([&](PreviewOptions& o) { o.brighten = on; });
     }},
    {L("interp"), "NAME",
     [](C& c) {
         const Interpolation m = parseInterpolation(c.arg(0).toStdString());
         c.setOptions([&](PreviewOptions& o) { o.interpolation = m; });
     }},
    {L("clipping"), "on|off",
     [](C& c) { c.w.windowActions()->clippingAction()->setChecked(onOff(c.arg(0))); }},
    // Edits
    {L("set"), "KEY VALUE", setParam},
    {L("drag"), "KEY VALUE", drag},
    {L("curve"), "NAME X,Y...", curve},
    {L("hue-range"), "hue.hue|hue.sat|hue.lum RANGE AMOUNT", hueRange},
    {L("undo"), "", [](C& c) { c.doc()->undoStack()->undo(); }},
    {L("redo"), "", [](C& c) { c.doc()->undoStack()->redo(); }},
    // Keys and focus
    {L("focus"), "OBJECTNAME", focus},
    {L("type"), "TEXT",
     [](C& c) {
         for (QChar ch : c.args.join(' '))
             sendKeys(QKeySequence(QString(ch)));
     }},
    {L("key"), "SEQUENCE", key},
    // Long tasks
    {L("start-open-image"), "PATH",
     [](C& c) {
         need(c.w.fileActions()->startOpenImage(c.arg(0)), QStringLiteral("nothing started"));
     }},
    {L("start-compare"), "FILE",
     [](C& c) {
         settle(c.w);
         c.w.windowActions()->startCompare(c.arg(0));
     }},
    {L("start-match"), "REFERENCE", // the dialog opens when done: `dialogs` answers it
     [](C& c) {
         settle(c.w);
         c.w.windowActions()->startMatch(c.arg(0));
     }},
    {L("start-save-preview"), "PATH",
     [](C& c) {
         settle(c.w);
         c.noNewError(c.w.fileActions()->startSavePreview(c.arg(0)));
     }},
    {L("cancel"), "load|compare|match|save-preview", cancel},
    {L("wait-task"), "NAME", waitTask},
    {L("compare"), "FILE REPORT", compare},
    {L("check"), "[N]", check},
    // The session
    {L("probe"), "on|off", probe},
    {L("wait"), "", [](C& c) { settle(c.w); }},
    {L("sleep"), "MS", sleepMs},
    {L("close"), "", [](C& c) { c.w.close(); }},
    {L("dialogs"), "accept|reject|hold", dialogs},
    {L("match-drag"), "strength|luma|chroma PERCENT [MS]", matchDrag},
    {L("print"), "WHAT", [](C& c) { printState(c, c.arg(0)); }},
};

} // namespace

std::span<const ScriptCommand> scriptCommands() {
    return kCommands;
}

const ScriptCommand* findScriptCommand(const QString& name) {
    for (const ScriptCommand& c : kCommands)
        if (name == c.name)
            return &c;
    return nullptr;
}

} // namespace lut::gui
