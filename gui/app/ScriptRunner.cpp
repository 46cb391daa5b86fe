// SPDX-License-Identifier: Apache-2.0
#include "ScriptRunner.h"

#include "DialogResponder.h"
#include "MainWindow.h"
#include "ScriptCommands.h"
#include "ScriptContext.h"

#include <QApplication>
#include <QFile>

#include <stdexcept>

namespace lut::gui {

int runScript(MainWindow& w, const QString& path, QTextStream& out) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) {
        out << "script: cannot read " << path << ": " << f.errorString() << "\n";
        return 1;
    }
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
    DialogResponder responder(&w);
    ScriptSession session{w, out, responder};
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (const int hash = line.indexOf('#'); hash >= 0)
            line.truncate(hash);
        QStringList words = line.split(' ', Qt::SkipEmptyParts);
        if (words.isEmpty())
            continue;
        const QString cmd = words.takeFirst();
        try {
            const ScriptCommand* command = findScriptCommand(cmd);
            if (!command)
                throw ScriptFailure("unknown command '" + cmd.toStdString() + "'");
            ScriptContext context(session, words);
            command->run(context);
            out.flush();
            QApplication::processEvents();
        } catch (const std::exception& e) {
            out << "script:" << (i + 1) << ": " << cmd << ": " << e.what() << "\n";
            out.flush();
            return 1;
        }
    }
    return 0; // the probe, if any, is a child of the window: it goes with it
}

} // namespace lut::gui
