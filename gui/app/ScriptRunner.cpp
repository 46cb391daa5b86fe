// SPDX-License-Identifier: Apache-2.0
#include "ScriptRunner.h"

#include "AdjustmentsPanel.h"
#include "BackgroundTask.h"
#include "CheckModel.h"
#include "CheckPanel.h"
#include "CompareDialog.h"
#include "CurveEditor.h"
#include "CurvesPanel.h"
#include "DialogResponder.h"
#include "Document.h"
#include "ExportDialog.h"
#include "FileActions.h"
#include "FileLoader.h"
#include "HueRanges.h"
#include "MainWindow.h"
#include "PlotDialog.h"
#include "PreviewController.h"
#include "PreviewView.h"
#include "RepaintProbe.h"
#include "TaskStatus.h"
#include "WindowActions.h"

#include "lut/io/Layout.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QListWidget>
#include <QMessageBox>
#include <QMimeData>
#include <QMouseEvent>
#include <QPushButton>
#include <QSaveFile>
#include <QSlider>
#include <QStatusBar>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QThread>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include <cstdio>
#include <stdexcept>

namespace lut::gui {

namespace {

DialogResponder* g_responder = nullptr;
RepaintProbe* g_probe = nullptr;

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void need(bool ok, const QString& why) {
    if (!ok)
        throw Failure(why.toStdString());
}

bool onOff(const QString& v) {
    if (v == QLatin1String("on"))
        return true;
    if (v == QLatin1String("off"))
        return false;
    throw Failure("expected on or off, got '" + v.toStdString() + "'");
}

void settle(MainWindow& w) {
    w.waitForLoads();
    w.windowActions()->compareTask()->waitForIdle();
    w.windowActions()->matchTask()->waitForIdle();
    w.fileActions()->saveTask()->waitForIdle();
    w.waitForPreview();
    QApplication::processEvents();
}

// The long tasks by the names scripts use: load, compare, match, save-preview.
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
    throw Failure("unknown adjustment '" + key.toStdString() + "'");
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
    throw Failure("unknown curve '" + n.toStdString() + "'");
}

QWidget* widgetByName(MainWindow& w, const QString& name) {
    for (QWidget* c : w.findChildren<QWidget*>(name))
        if (c->isVisible() || c->isVisibleTo(&w))
            return c;
    throw Failure("no widget named '" + name.toStdString() + "'");
}

// A key press and release sent as the window system would: the focused widget is offered the
// shortcut first (ShortcutOverride), then the window's shortcuts, then the widget.
void sendKeys(const QKeySequence& seq) {
    for (int i = 0; i < seq.count(); ++i) {
        const QKeyCombination k = seq[i];
        QWidget* target = QApplication::focusWidget();
        need(target != nullptr, QStringLiteral("no widget has the keyboard focus"));
        QString text;
        if (!(k.keyboardModifiers() & (Qt::ControlModifier | Qt::AltModifier)) &&
            k.key() < 0x01000000)
            text = QKeySequence(k.key()).toString().toLower();
        QKeyEvent press(QEvent::KeyPress, k.key(), k.keyboardModifiers(), text);
        QApplication::sendEvent(target, &press);
        QKeyEvent release(QEvent::KeyRelease, k.key(), k.keyboardModifiers(), text);
        if (QWidget* now = QApplication::focusWidget())
            QApplication::sendEvent(now, &release);
        QApplication::processEvents();
    }
}

// Drags a slider's handle with the mouse to the position of `value`, in a few moves.
void dragSlider(QSlider* s, int position) {
    QStyleOptionSlider opt;
    opt.initFrom(s);
    opt.orientation = s->orientation();
    opt.minimum = s->minimum();
    opt.maximum = s->maximum();
    opt.sliderPosition = s->value();
    opt.sliderValue = s->value();
    const QRect handle =
        s->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, s);
    const int span = s->width() - handle.width();
    const auto xOf = [&](int v) {
        return QStyle::sliderPositionFromValue(s->minimum(), s->maximum(), v, span) +
               handle.width() / 2;
    };
    QPointF at(xOf(s->value()), s->height() / 2.0);
    auto send = [&](QEvent::Type type, QPointF p, Qt::MouseButtons buttons) {
        QMouseEvent e(type, p, s->mapToGlobal(p), Qt::LeftButton, buttons, Qt::NoModifier);
        QApplication::sendEvent(s, &e);
        QApplication::processEvents();
    };
    send(QEvent::MouseButtonPress, at, Qt::LeftButton);
    const double target = xOf(position);
    for (int i = 1; i <= 5; ++i)
        send(QEvent::MouseMove, QPointF(at.x() + (target - at.x()) * i / 5, at.y()),
             Qt::LeftButton);
    send(QEvent::MouseButtonRelease, QPointF(target, at.y()), Qt::NoButton);
}

QString onOffText(bool v) {
    return v ? QStringLiteral("on") : QStringLiteral("off");
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

void runLine(MainWindow& w, const QString& cmd, QStringList args, QTextStream& out) {
    Document* doc = w.document();
    PreviewController* preview = w.preview();
    auto arg = [&](int i) {
        need(i < args.size(), QStringLiteral("missing argument %1").arg(i + 1));
        return args[i];
    };
    auto setOptions = [&](auto change) {
        PreviewOptions o = preview->options();
        change(o);
        preview->setOptions(o);
    };
    const QString error0 = w.lastError();
    auto noNewError = [&](bool ok) {
        need(ok, w.lastError().isEmpty() || w.lastError() == error0 ? QStringLiteral("failed")
                                                                    : w.lastError());
    };
    if (cmd == "open-image") {
        noNewError(w.openImageFile(arg(0)));
    } else if (cmd == "open-lut") {
        FormatOptions o;
        if (args.size() > 1)
            o.layout = parseOptionalLayout(args[1].toStdString());
        noNewError(w.openLutFile(arg(0), o));
    } else if (cmd == "drop") {
        need(!args.isEmpty(), QStringLiteral("drop needs files"));
        QMimeData mime;
        QList<QUrl> urls;
        for (const QString& a : args)
            urls << QUrl::fromLocalFile(QFileInfo(a).absoluteFilePath());
        mime.setUrls(urls);
        const QPoint at = w.rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        need(enter.isAccepted(), QStringLiteral("the window refused the drag"));
        QDropEvent drop(QPointF(at), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QApplication::processEvents(); // a LUT opens once the drop has returned
        w.waitForLoads();
        noNewError(drop.isAccepted());
    } else if (cmd == "lut-target") { // what LUTs that do not say are for (raw, smash, ask)
        const QString v = arg(0);
        w.setLutPurposeAnswer(v == "ask"
                                  ? std::nullopt
                                  : std::optional<LutPurpose>(parseLutPurpose(v.toStdString())));
    } else if (cmd == "new-neutral") {
        w.fileActions()->newNeutral(arg(0).toInt());
    } else if (cmd == "target") {
        doc->setTarget(parseExportTarget(arg(0).toStdString()));
    } else if (cmd == "input") {
        const SceneKind k = parseSceneKind(arg(0).toStdString());
        setOptions([&](PreviewOptions& o) { o.input = k; });
    } else if (cmd == "chain") {
        const QString n = arg(0);
        const Preset p = n == "filmic"      ? Preset::Pilot
                         : n == "cinematic" ? Preset::Lecture
                                            : parsePreset(n.toStdString());
        setOptions([&](PreviewOptions& o) { o.preset = p; });
    } else if (cmd == "bloom") {
        const bool on = onOff(arg(0));
        setOptions([&](PreviewOptions& o) { o.bloom = on; });
    } else if (cmd == "lut") {
        const bool on = onOff(arg(0));
        setOptions([&](PreviewOptions& o) { o.lutEnabled = on; });
    } else if (cmd == "brighten") {
        const bool on = onOff(arg(0));
        setOptions([&](PreviewOptions& o) { o.brighten = on; });
    } else if (cmd == "interp") {
        const Interpolation m = parseInterpolation(arg(0).toStdString());
        setOptions([&](PreviewOptions& o) { o.interpolation = m; });
    } else if (cmd == "clipping") {
        w.windowActions()->clippingAction()->setChecked(onOff(arg(0)));
    } else if (cmd == "set") {
        const AdjustParamInfo& p = paramByKey(arg(0));
        bool ok = false;
        const double v = arg(1).toDouble(&ok);
        need(ok && v >= p.min && v <= p.max,
             QStringLiteral("%1 takes a number from %2 to %3").arg(arg(0)).arg(p.min).arg(p.max));
        doc->editParam(p.id, v);
        doc->endGesture();
    } else if (cmd == "drag") {
        const AdjustParamInfo& p = paramByKey(arg(0));
        QSlider* s = w.adjustmentsPanel()->slider(p.id);
        need(s->isVisible(), QStringLiteral("the %1 slider is not visible").arg(arg(0)));
        dragSlider(s, paramToSlider(p, arg(1).toDouble(), AdjustmentsPanel::kSteps));
    } else if (cmd == "curve") {
        const CurveId id = curveByName(arg(0));
        std::vector<glm::dvec2> pts;
        for (int i = 1; i < args.size(); ++i) {
            const QStringList xy = args[i].split(',');
            need(xy.size() == 2, QStringLiteral("expected X,Y, got '%1'").arg(args[i]));
            pts.push_back({xy[0].toDouble(), xy[1].toDouble()});
        }
        const bool hue =
            id == CurveId::HueVsHue || id == CurveId::HueVsSat || id == CurveId::HueVsLum;
        doc->editCurve(id, Curve(hue ? CurveKind::Hue : CurveKind::Tone, pts));
        doc->endGesture();
    } else if (cmd == "hue-range") {
        // As a user does: the curve's button, the range's button, a value typed in Amount.
        const CurveId id = curveByName(arg(0));
        need(id == CurveId::HueVsHue || id == CurveId::HueVsSat || id == CurveId::HueVsLum,
             QStringLiteral("hue-range takes hue.hue, hue.sat or hue.lum"));
        const HueRange* range = hueRangeByKey(arg(1).toLatin1().constData());
        need(range != nullptr, QStringLiteral("unknown hue range '%1' (reds yellows greens cyans "
                                              "blues magentas)")
                                   .arg(arg(1)));
        bool ok = false;
        const double amount = arg(2).toDouble(&ok);
        need(ok, QStringLiteral("expected an amount, got '%1'").arg(arg(2)));
        CurvesPanel* panel = w.curvesPanel();
        panel->curveButton(id)->click();
        panel->rangeButton(range->key)->click();
        need(panel->amountBox()->isEnabled(), QStringLiteral("no point selected"));
        panel->amountBox()->setValue(amount);
    } else if (cmd == "start-open-image") {
        need(w.fileActions()->startOpenImage(arg(0)), QStringLiteral("nothing started"));
    } else if (cmd == "start-compare") {
        settle(w);
        w.windowActions()->startCompare(arg(0));
    } else if (cmd == "start-match") { // the dialog opens when done: `dialogs` answers it
        settle(w);
        w.windowActions()->startMatch(arg(0));
    } else if (cmd == "start-save-preview") {
        settle(w);
        noNewError(w.fileActions()->startSavePreview(arg(0)));
    } else if (cmd == "cancel") {
        // The status bar's Cancel button of that task, clicked.
        const QString name =
            arg(0) == "load"
                ? QStringLiteral("loading")
                : QStringLiteral("task.") +
                      (arg(0) == "save-preview" ? QStringLiteral("savePreview") : arg(0));
        auto* status = w.statusBar()->findChild<TaskStatus*>(name);
        need(status != nullptr, QStringLiteral("unknown task '%1'").arg(arg(0)));
        need(status->isVisible(), QStringLiteral("%1 is not running").arg(arg(0)));
        status->cancelButton()->click();
        QApplication::processEvents();
    } else if (cmd == "wait-task") {
        // Processes events until the task is done (the window stays live meanwhile).
        if (arg(0) == "load")
            w.waitForLoads();
        else
            taskByName(w, arg(0))->waitForIdle();
    } else if (cmd == "probe") {
        if (onOff(arg(0))) {
            if (!g_probe) {
                g_probe = new RepaintProbe(w.statusBar());
                w.statusBar()->addPermanentWidget(g_probe);
            }
            g_probe->start();
        } else {
            need(g_probe != nullptr, QStringLiteral("probe on first"));
            g_probe->stop();
            out << "probe longest-gap " << QString::number(g_probe->longestGapMs(), 'f', 1)
                << " ms own " << QString::number(g_probe->longestOwnGapMs(), 'f', 1) << " ms over "
                << g_probe->paints() << " paints\n";
        }
    } else if (cmd == "focus") {
        QWidget* target = widgetByName(w, arg(0));
        // As a click does: the window becomes the active one (there may be no window manager to
        // do it), and a spin box takes the focus into its line edit.
        w.activateWindow();
        QApplication::setActiveWindow(target->window());
        target->setFocus(Qt::MouseFocusReason);
        QApplication::processEvents();
    } else if (cmd == "type") {
        const QString text = args.join(' ');
        for (QChar c : text)
            sendKeys(QKeySequence(QString(c)));
    } else if (cmd == "key") {
        const QKeySequence seq = QKeySequence::fromString(arg(0), QKeySequence::PortableText);
        need(!seq.isEmpty(), QStringLiteral("unknown key '%1'").arg(arg(0)));
        sendKeys(seq);
    } else if (cmd == "undo") {
        doc->undoStack()->undo();
    } else if (cmd == "redo") {
        doc->undoStack()->redo();
    } else if (cmd == "save") {
        noNewError(w.saveDocument());
    } else if (cmd == "save-as") {
        noNewError(w.saveDocumentAs(arg(0)));
    } else if (cmd == "adjustments-save") {
        noNewError(w.fileActions()->saveAdjustments(arg(0)));
    } else if (cmd == "adjustments-load") {
        noNewError(w.fileActions()->loadAdjustments(arg(0)));
    } else if (cmd == "export") {
        const bool overwrite = args.removeAll(QStringLiteral("overwrite")) > 0;
        // strength=T, luma=T, chroma=T: the export dialog's strength (lutkit --strength ...).
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
        ExportChoice choice;
        QString path = suggestedExport(w, &choice);
        FormatOptions o = targetFormatOptions(doc->target());
        if (!args.isEmpty()) {
            path = args[0];
            choice.format = args.size() > 1 ? args[1] : QString();
            o = FormatOptions{};
            if (args.size() > 2)
                o.layout = parseOptionalLayout(args[2].toStdString());
            // By extension; the target's own file type takes the target's settings.
            const ExportTargetInfo& t = exportTargetInfo(doc->target());
            if (choice.format.isEmpty() && path.endsWith(QString::fromStdString(t.extension)))
                o = targetFormatOptions(doc->target());
        }
        out << "exported " << path << "\n";
        noNewError(w.exportLut(path, choice.format, o, doc->target(), overwrite, strength));
    } else if (cmd == "save-preview") {
        settle(w);
        noNewError(w.savePreviewImage(arg(0)));
    } else if (cmd == "plot-save") {
        settle(w);
        const Image plot = plotExportedLut(*doc, doc->target());
        noNewError(w.fileActions()->savePicture(arg(0), plot));
    } else if (cmd == "compare") {
        // Through Tools > Compare's worker, as the menu runs it; the report also opens.
        settle(w);
        w.windowActions()->startCompare(arg(0));
        w.windowActions()->compareTask()->waitForIdle();
        need(w.windowActions()->compareTask()->lastOutcome() == BackgroundTask::Outcome::Done &&
                 w.windowActions()->lastComparison(),
             w.lastError().isEmpty() ? QStringLiteral("the comparison failed") : w.lastError());
        const Comparison& c = *w.windowActions()->lastComparison();
        char exact[40];
        std::snprintf(exact, sizeof exact, "%.9g", c.report.maxDeltaE);
        const QString text =
            comparisonText(c) + QStringLiteral("max-delta-e2000 ") + QString::fromLatin1(exact);
        QSaveFile f(arg(1));
        need(f.open(QIODevice::WriteOnly) && f.write(text.toUtf8() + '\n') >= 0 && f.commit(),
             QStringLiteral("cannot write %1").arg(arg(1)));
        out << "compared " << arg(0) << ": max ΔE2000 " << exact << "\n";
    } else if (cmd == "check") {
        // The Check panel raised and current; with N, finding N clicked (highlighted).
        settle(w);
        auto* dock = w.findChild<QDockWidget*>(QStringLiteral("dock.check"));
        dock->show();
        dock->raise();
        CheckPanel* panel = w.checkPanel();
        panel->model()->waitForIdle();
        QApplication::processEvents();
        if (!args.isEmpty()) {
            QListWidget* list = panel->findingsList();
            const int n = arg(0).toInt();
            const int findings = panel->model()->report()
                                     ? static_cast<int>(panel->model()->report()->findings.size())
                                     : 0;
            need(n >= 1 && n <= findings,
                 QStringLiteral("check: no finding %1 (%2 listed)").arg(arg(0)).arg(findings));
            list->setCurrentRow(n - 1);
            emit list->itemClicked(list->item(n - 1));
            panel->model()->waitForIdle();
            QApplication::processEvents();
        }
        out << "check " << panel->verdictText() << "\n";
    } else if (cmd == "screenshot") {
        settle(w);
        const QImage shot = w.grab().toImage();
        QSaveFile f(arg(0));
        need(f.open(QIODevice::WriteOnly) && shot.save(&f, "PNG") && f.commit(),
             QStringLiteral("cannot write %1").arg(arg(0)));
    } else if (cmd == "wait") {
        settle(w);
    } else if (cmd == "sleep") {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < arg(0).toInt()) {
            QApplication::processEvents(QEventLoop::AllEvents, 10);
            QThread::msleep(2);
        }
    } else if (cmd == "close") {
        w.close();
    } else if (cmd == "dialogs") {
        const QString how = arg(0);
        need(how == "accept" || how == "reject", QStringLiteral("dialogs takes accept or reject"));
        g_responder->accept = how == "accept";
    } else if (cmd == "print") {
        const QString what = arg(0);
        const PreviewOptions& o = preview->options();
        out << what << " ";
        if (what == "target")
            out << QString::fromStdString(exportTargetInfo(doc->target()).key);
        else if (what == "purpose")
            out << toString(doc->lutPurpose());
        else if (what == "input")
            out << toString(o.input);
        else if (what == "chain")
            out << toString(effectivePreset(o, doc->target()));
        else if (what == "bloom")
            out << onOffText(bloomApplied(o, doc->target()));
        else if (what.startsWith("param:"))
            out << doc->param(paramByKey(what.mid(6)).id);
        else if (what == "undo-count")
            out << doc->undoStack()->count() << " index " << doc->undoStack()->index();
        else if (what == "modified")
            out << (doc->isModified() ? "yes" : "no");
        else if (what == "notes")
            out << w.notesText().replace('\n', " | ");
        else if (what == "error")
            out << w.lastError();
        else if (what == "clip")
            out << w.clipText();
        else if (what == "title")
            out << w.windowTitle();
        else if (what == "export-path") {
            ExportChoice c;
            out << suggestedExport(w, &c);
        } else if (what == "dialogs") {
            out << (g_responder->seen.isEmpty() ? QStringLiteral("(none)")
                                                : g_responder->seen.join(QStringLiteral(" | ")));
            g_responder->seen.clear();
        } else if (what == "zoom") {
            out << QString::number(w.previewView()->zoom() * 100, 'f', 1) << " %";
        } else if (what.startsWith("task:")) {
            out << taskState(w, what.mid(5));
        } else if (what.startsWith("curve:")) {
            const Curve& c = curveOf(doc->adjustments(), curveByName(what.mid(6)));
            QStringList pts;
            for (const auto& p : c.points())
                pts << QStringLiteral("%1,%2").arg(p.x).arg(p.y);
            out << (pts.isEmpty() ? QStringLiteral("(neutral)") : pts.join(' '));
        } else if (what == "focus")
            out << (QApplication::focusWidget() ? QApplication::focusWidget()->objectName()
                                                : QStringLiteral("(none)"));
        else
            throw Failure("print: unknown '" + what.toStdString() + "'");
        out << "\n";
    } else {
        throw Failure("unknown command '" + cmd.toStdString() + "'");
    }
    out.flush();
}

} // namespace

int runScript(MainWindow& w, const QString& path, QTextStream& out) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) {
        out << "script: cannot read " << path << ": " << f.errorString() << "\n";
        return 1;
    }
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
    DialogResponder responder(&w);
    g_responder = &responder;
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (const int hash = line.indexOf('#'); hash >= 0)
            line.truncate(hash);
        QStringList words = line.split(' ', Qt::SkipEmptyParts);
        if (words.isEmpty())
            continue;
        const QString cmd = words.takeFirst();
        try {
            runLine(w, cmd, words, out);
            QApplication::processEvents();
        } catch (const std::exception& e) {
            out << "script:" << (i + 1) << ": " << cmd << ": " << e.what() << "\n";
            out.flush();
            g_responder = nullptr;
            g_probe = nullptr;
            return 1;
        }
    }
    g_responder = nullptr;
    g_probe = nullptr; // a child of the window: it goes with it
    return 0;
}

} // namespace lut::gui
