// SPDX-License-Identifier: Apache-2.0
#include "ScriptPrint.h"

#include "DialogResponder.h"
#include "ExportDialog.h"
#include "MainWindow.h"
#include "PreviewView.h"
#include "ScriptContext.h"

#include <QApplication>
#include <QUndoStack>

namespace lut::gui {

namespace {

// A row: the name (a prefix when it ends with ':', its rest given to the row) and what it writes.
struct Printable {
    QLatin1StringView name;
    void (*print)(ScriptContext& c, const QString& rest);
};

void printCurve(ScriptContext& c, const QString& name) {
    const Curve& curve = curveOf(c.doc()->adjustments(), curveByName(name));
    QStringList pts;
    for (const auto& p : curve.points())
        pts << QStringLiteral("%1,%2").arg(p.x).arg(p.y);
    c.out << (pts.isEmpty() ? QStringLiteral("(neutral)") : pts.join(' '));
}

void printDialogs(ScriptContext& c) {
    QStringList& seen = c.session.responder.seen;
    c.out << (seen.isEmpty() ? QStringLiteral("(none)") : seen.join(QStringLiteral(" | ")));
    seen.clear();
}

using C = ScriptContext;
using S = const QString&;
using L = QLatin1StringView;

const Printable kPrintables[] = {
    {L("target"),
     [](C& c, S) { c.out << QString::fromStdString(exportTargetInfo(c.doc()->target()).key); }},
    {L("purpose"), [](C& c, S) { c.out << toString(c.doc()->lutPurpose()); }},
    {L("input"), [](C& c, S) { c.out << toString(c.preview()->options().input); }},
    {L("chain"),
     [](C& c, S) {
         c.out << toString(effectivePreset(c.preview()->options(), c.doc()->target()));
     }},
    {L("bloom"),
     [](C& c, S) { c.out << onOffText(bloomApplied(c.preview()->options(), c.doc()->target())); }},
    {L("param:"), [](C& c, S key) { c.out << c.doc()->param(paramByKey(key).id); }},
    {L("undo-count"),
     [](C& c, S) {
         c.out << c.doc()->undoStack()->count() << " index " << c.doc()->undoStack()->index();
     }},
    {L("modified"), [](C& c, S) { c.out << (c.doc()->isModified() ? "yes" : "no"); }},
    {L("notes"), [](C& c, S) { c.out << c.w.notesText().replace('\n', " | "); }},
    {L("error"), [](C& c, S) { c.out << c.w.lastError(); }},
    {L("clip"), [](C& c, S) { c.out << c.w.clipText(); }},
    {L("title"), [](C& c, S) { c.out << c.w.windowTitle(); }},
    {L("export-path"),
     [](C& c, S) {
         ExportChoice choice;
         c.out << suggestedExport(c.w, &choice);
     }},
    {L("dialogs"), [](C& c, S) { printDialogs(c); }},
    {L("zoom"),
     [](C& c, S) { c.out << QString::number(c.w.previewView()->zoom() * 100, 'f', 1) << " %"; }},
    {L("task:"), [](C& c, S name) { c.out << taskState(c.w, name); }},
    {L("curve:"), [](C& c, S name) { printCurve(c, name); }},
    {L("focus"),
     [](C& c, S) {
         c.out << (QApplication::focusWidget() ? QApplication::focusWidget()->objectName()
                                               : QStringLiteral("(none)"));
     }},
};

} // namespace

void printState(ScriptContext& c, const QString& what) {
    c.out << what << " ";
    for (const Printable& p : kPrintables) {
        const bool prefix = p.name.endsWith(QLatin1Char(':'));
        if (prefix ? what.startsWith(p.name) : what == p.name) {
            p.print(c, prefix ? what.mid(p.name.size()) : QString());
            c.out << "\n";
            return;
        }
    }
    throw ScriptFailure("print: unknown '" + what.toStdString() + "'");
}

} // namespace lut::gui
