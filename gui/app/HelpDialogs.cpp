// SPDX-License-Identifier: Apache-2.0
#include "HelpDialogs.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <vector>

namespace lut::gui {

namespace {

QWidget* textWindow(QMainWindow* window, const char* name, const QString& title,
                    const QString& html) {
    const QString objectName = QString::fromLatin1(name);
    // One of each: asked again, the open one comes to the front.
    if (auto* open = window->findChild<QDialog*>(objectName)) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* dlg = new QDialog(window);
    dlg->setObjectName(objectName);
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(title);
    auto* layout = new QVBoxLayout(dlg);
    auto* text = new QTextBrowser(dlg);
    text->setObjectName(objectName + QStringLiteral(".text"));
    text->setOpenExternalLinks(true);
    text->setHtml(html);
    text->setMinimumSize(620, 460);
    layout->addWidget(text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dlg);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dlg, &QDialog::close);
    layout->addWidget(buttons);
    dlg->show();
    return dlg;
}

QString plainText(QString s) {
    return s.remove(QLatin1Char('&')).remove(QChar(0x2026)).trimmed();
}

} // namespace

QWidget* showQuickStart(QMainWindow* window) {
    const QString html = QDialog::tr(
        "<h3>Quick start</h3>"
        "<ol>"
        "<li><b>Open a picture</b>: File &gt; Open Image (Ctrl+O) or drop it on the window. An "
        "in-game screenshot (8/16-bit) or a linear render (float): detected, shown in the "
        "toolbar's <i>Picture</i>.</li>"
        "<li><b>Say where the LUT goes</b>: the toolbar's <i>Target</i>. <i>Smash Ultimate</i> "
        "writes color_grading_lut.nutexb, the game's LUT, and the preview runs the game's own "
        "chain; <i>engine strip</i> and <i>grading .cube</i> write an edit. The preview always "
        "shows what the exported file gives.</li>"
        "<li><b>Start from a LUT</b>: File &gt; Open LUT (Ctrl+L) (a .cube, a .nutexb, a strip "
        "such as Smush-LUT's), File &gt; Open Built-in LUT, File &gt; New from neutral, or "
        "Tools &gt; Match to Reference to take the look of another picture.</li>"
        "<li><b>Grade</b> in the docks: Adjustments (exposure, contrast, white balance, lift, "
        "gamma, gain), Curves, Colour wheels. Drag the divider of the split view; S, A and B "
        "show split, after and before. Every change is one step in History (Ctrl+Z).</li>"
        "<li><b>Check</b>: the Check dock runs lutkit check on the export; View &gt; Clipping "
        "Overlay (Ctrl+K) marks clipped pixels.</li>"
        "<li><b>Export</b>: File &gt; Export LUT (Ctrl+E). For Smash Ultimate put "
        "color_grading_lut.nutexb in the stage's folder of your mod (the suggestion is beside "
        "the opened LUT); other formats, strip layouts and atlases are in the list.</li>"
        "</ol>"
        "<p>The same work on the command line: <tt>lutkit preview</tt>, <tt>lutkit convert</tt>, "
        "<tt>lutkit match</tt> (<tt>lutkit --help</tt>). The editor's manual is docs/editor.md "
        "(installed in share/doc/lutkit/).</p>");
    return textWindow(window, "help.quickStart", QDialog::tr("Quick Start"), html);
}

QWidget* showShortcuts(QMainWindow* window) {
    struct Row {
        QString keys, what;
    };
    std::vector<Row> rows;
    // Every menu's actions with their keys, under the menu's name.
    for (QAction* top : window->menuBar()->actions()) {
        QMenu* menu = top->menu();
        if (!menu)
            continue;
        std::vector<QMenu*> menus = {menu};
        for (std::size_t i = 0; i < menus.size(); ++i)
            for (QAction* a : menus[i]->actions()) {
                if (a->menu())
                    menus.push_back(a->menu());
                QStringList keys;
                for (const QKeySequence& k : a->shortcuts())
                    keys << k.toString(QKeySequence::NativeText);
                if (!keys.isEmpty())
                    rows.push_back(
                        {keys.join(QStringLiteral(", ")),
                         plainText(top->text()) + QStringLiteral(" > ") + plainText(a->text())});
            }
    }
    rows.push_back({QDialog::tr("Wheel"), QDialog::tr("Moves a slider or number box once it has "
                                                      "the focus (click it first); else "
                                                      "scrolls the dock")});
    rows.push_back({QDialog::tr("Right-click"), QDialog::tr("An adjustment's slider back to its "
                                                            "default")});
    rows.push_back({QDialog::tr("Shift+drag"), QDialog::tr("A slider in fine steps")});
    rows.push_back({QDialog::tr("Drag"), QDialog::tr("The split view's divider")});
    QString html = QDialog::tr("<h3>Keyboard and mouse</h3><table cellspacing=4>");
    for (const Row& r : rows)
        html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(r.keys.toHtmlEscaped(), r.what.toHtmlEscaped());
    html += QStringLiteral("</table>");
    return textWindow(window, "help.shortcuts", QDialog::tr("Keyboard Shortcuts"), html);
}

} // namespace lut::gui
