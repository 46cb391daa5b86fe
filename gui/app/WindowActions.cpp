// SPDX-License-Identifier: Apache-2.0
#include "WindowActions.h"

#include "BackgroundTask.h"
#include "BuiltinNames.h"
#include "CompareDialog.h"
#include "Document.h"
#include "ErrorText.h"
#include "FileActions.h"
#include "HelpDialogs.h"
#include "MatchDialog.h"
#include "PlotDialog.h"
#include "PreviewController.h"
#include "PreviewView.h"
#include "Prompts.h"

#include "lut/interp/Sampler.h"
#include "lut/io/BuiltinLut.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QStandardItemModel>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

namespace lut::gui {

namespace {

// Export: a LUT tile with an arrow leaving it (the standard arrows are taken by undo and redo).
QIcon exportIcon(const QPalette& palette) {
    QPixmap pm(32, 32);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor ink = palette.color(QPalette::WindowText);
    const QColor cells[4] = {QColor(220, 90, 70), QColor(90, 190, 90), QColor(80, 120, 230),
                             QColor(230, 200, 80)};
    for (int i = 0; i < 4; ++i)
        p.fillRect(QRectF(3 + (i % 2) * 9, 11 + (i / 2) * 9, 9, 9), cells[i]);
    p.setPen(QPen(ink, 1.5));
    p.drawRect(QRectF(3, 11, 18, 18));
    QPainterPath arrow;
    arrow.moveTo(14, 18);
    arrow.lineTo(27, 5);
    p.setPen(QPen(ink, 2.5, Qt::SolidLine, Qt::RoundCap));
    p.drawPath(arrow);
    p.drawLine(QPointF(19, 5), QPointF(27, 5));
    p.drawLine(QPointF(27, 5), QPointF(27, 13));
    return QIcon(pm);
}

void setItemEnabled(QComboBox* box, int index, bool on) {
    if (auto* model = qobject_cast<QStandardItemModel*>(box->model()))
        if (QStandardItem* item = model->item(index))
            item->setEnabled(on);
}

} // namespace

WindowActions::WindowActions(QMainWindow* window, const EditorContext& context, FileActions* files,
                             PreviewView* view)
    : QObject(window), m_window(window), m_doc(context.document), m_preview(context.preview),
      m_prompts(context.prompts), m_files(files), m_view(view),
      m_compareTask(new BackgroundTask(this)), m_matchTask(new BackgroundTask(this)) {
    m_prompts->watchTask(m_compareTask, QStringLiteral("task.compare"));
    m_prompts->watchTask(m_matchTask, QStringLiteral("task.match"));
    // A match is of the picture that was open when it started.
    connect(m_doc, &Document::imageChanged, m_matchTask, &BackgroundTask::cancel);
    buildFileMenu();
    buildEditMenu();
    buildViewMenu();
    buildPreviewMenu();
    buildToolsMenu();
    buildHelpMenu();
    buildToolbars();
    // Shortcuts work in every window of the editor (floating docks too); modal dialogs still
    // block them.
    for (QAction* a : m_window->findChildren<QAction*>())
        if (!a->shortcuts().isEmpty())
            a->setShortcutContext(Qt::ApplicationShortcut);
    showOptions(m_preview->options());
    connect(m_preview, &PreviewController::optionsChanged, this, &WindowActions::showOptions);
    // The target is the document's: a script or the command line may change it too.
    connect(m_doc, &Document::targetChanged, this, [this] { showOptions(m_preview->options()); });
}

void WindowActions::buildFileMenu() {
    FileActions* files = m_files;
    QStyle* st = m_window->style();
    QMenu* file = m_window->menuBar()->addMenu(tr("&File"));
    QMenu* newMenu = file->addMenu(tr("&New from neutral"));
    for (int size : {16, 17, 32, 33, 64, 65}) {
        QAction* a = newMenu->addAction(QString::number(size) + QChar(0x00B3) +
                                        (size == 16 ? tr(" (Smash)") : QString()));
        connect(a, &QAction::triggered, files, [files, size] { files->newNeutral(size); });
    }
    m_openImage = file->addAction(st->standardIcon(QStyle::SP_DirOpenIcon), tr("Open &Image…"),
                                  QKeySequence::Open, files, &FileActions::openImageDialog);
    m_openLut =
        file->addAction(st->standardIcon(QStyle::SP_FileDialogDetailedView), tr("Open &LUT…"),
                        QKeySequence(tr("Ctrl+L")), files, &FileActions::openLutDialog);
    QMenu* builtins = file->addMenu(tr("Open &Built-in LUT"));
    for (const BuiltinLutInfo& b : builtinLuts()) {
        const QString name = QString::fromLatin1(kBuiltinLutPrefix.data(),
                                                 static_cast<int>(kBuiltinLutPrefix.size())) +
                             QString::fromStdString(b.name);
        QAction* a = builtins->addAction(builtinLutTitle(name));
        a->setObjectName(QStringLiteral("open.") + name);
        a->setToolTip(name + QStringLiteral(": ") + QString::fromStdString(b.description));
        a->setStatusTip(QString::fromStdString(b.description));
        connect(a, &QAction::triggered, files, [files, name] { files->startOpenLut(name); });
    }
    file->addAction(tr("LUT from &Edited Screenshot…"), files, &FileActions::openScreenshotDialog)
        ->setToolTip(tr("Extract the LUT from a screenshot with an embedded patch (lutkit embed)"));
    QMenu* recentImages = file->addMenu(tr("Recent Images"));
    QMenu* recentLuts = file->addMenu(tr("Recent LUTs"));
    files->setRecentMenus(recentImages, recentLuts);
    file->addSeparator();
    m_save = file->addAction(st->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save LUT"),
                             QKeySequence::Save, files, [files] { files->save(); });
    m_save->setObjectName("action.save");
    file->addAction(tr("Save LUT &As…"), QKeySequence::SaveAs, files, &FileActions::saveAsDialog);
    m_export = file->addAction(exportIcon(m_window->palette()), tr("&Export LUT…"),
                               QKeySequence(tr("Ctrl+E")), files, &FileActions::exportDialog);
    m_export->setObjectName("action.export");
    m_export->setToolTip(tr("Write the LUT for the target (Ctrl+E): what the preview shows"));
    file->addAction(tr("Save &Preview Image…"), QKeySequence(tr("Ctrl+Shift+P")), files,
                    &FileActions::savePreviewDialog);
    file->addSeparator();
    file->addAction(tr("Save A&djustments…"), files, &FileActions::saveAdjustmentsDialog)
        ->setToolTip(tr("The adjustment list: lutkit applies the same list to a LUT"));
    file->addAction(tr("Load Adj&ustments…"), files, &FileActions::loadAdjustmentsDialog);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, m_window, &QWidget::close);
}

void WindowActions::buildEditMenu() {
    QStyle* st = m_window->style();
    Document* doc = m_doc;
    QMenu* edit = m_window->menuBar()->addMenu(tr("&Edit"));
    m_undo = doc->undoStack()->createUndoAction(m_window, tr("&Undo"));
    m_undo->setObjectName("action.undo");
    m_undo->setShortcut(QKeySequence::Undo);
    m_undo->setIcon(st->standardIcon(QStyle::SP_ArrowBack));
    m_undo->setIconText(tr("Undo")); // the toolbar keeps a short label; the menu names the step
    m_redo = doc->undoStack()->createRedoAction(m_window, tr("&Redo"));
    m_redo->setObjectName("action.redo");
    // Ctrl+Shift+Z everywhere, and Ctrl+Y, which Linux desktops do not bind to redo.
    m_redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    m_redo->setIcon(st->standardIcon(QStyle::SP_ArrowForward));
    m_redo->setIconText(tr("Redo"));
    edit->addAction(m_undo);
    edit->addAction(m_redo);
    edit->addSeparator();
    edit->addAction(tr("Reset &Adjustments"), doc, &Document::resetAdjustments);
}

void WindowActions::buildViewMenu() {
    PreviewView* view = m_view;
    QMenu* menu = m_window->menuBar()->addMenu(tr("&View"));
    m_fit = menu->addAction(tr("Zoom to &Fit"), QKeySequence(tr("Ctrl+0")), view,
                            &PreviewView::zoomToFit);
    m_actualSize = menu->addAction(tr("&100 %"), QKeySequence(tr("Ctrl+1")), view,
                                   [view] { view->zoomTo(1.0); });
    // Ctrl++ needs Shift on most keyboards: Ctrl+= (the same key unshifted) zooms in too.
    QAction* zoomIn = menu->addAction(tr("Zoom &In"), view, [view] { view->zoomBy(1.25); });
    zoomIn->setObjectName("action.zoomIn");
    zoomIn->setShortcuts({QKeySequence(QKeySequence::ZoomIn), QKeySequence(tr("Ctrl+="))});
    QAction* zoomOut = menu->addAction(tr("Zoom &Out"), view, [view] { view->zoomBy(0.8); });
    zoomOut->setObjectName("action.zoomOut");
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    menu->addSeparator();
    auto* group = new QActionGroup(this);
    const std::pair<QString, PreviewView::Mode> modes[] = {
        {tr("Before / After &Split"), PreviewView::Mode::Split},
        {tr("&After Only"), PreviewView::Mode::After},
        {tr("&Before Only"), PreviewView::Mode::Before}};
    const char* keys[] = {"S", "A", "B"};
    for (int i = 0; i < 3; ++i) {
        const auto mode = modes[i].second;
        m_modes[i] = menu->addAction(modes[i].first, view, [view, mode] { view->setMode(mode); });
        m_modes[i]->setCheckable(true);
        m_modes[i]->setShortcut(QKeySequence(QString::fromLatin1(keys[i])));
        group->addAction(m_modes[i]);
    }
    m_modes[0]->setChecked(true);
    connect(view, &PreviewView::modeChanged, this, [this](PreviewView::Mode m) {
        m_modes[static_cast<int>(m)]->setChecked(true); // Mode order = action order
    });
    menu->addSeparator();
    m_clipping = menu->addAction(tr("&Clipping Overlay"));
    m_clipping->setObjectName("action.clipping");
    m_clipping->setCheckable(true);
    m_clipping->setShortcut(QKeySequence(tr("Ctrl+K")));
    m_clipping->setToolTip(tr("Mark the preview's clipped pixels: red where a channel is at 255, "
                              "blue where one is at 0"));
    connect(m_clipping, &QAction::toggled, view, &PreviewView::setShowClipping);
    menu->addSeparator();
    for (QDockWidget* d : m_window->findChildren<QDockWidget*>())
        menu->addAction(d->toggleViewAction());
}

void WindowActions::buildPreviewMenu() {
    QMenu* menu = m_window->menuBar()->addMenu(tr("&Preview"));
    m_target = new QComboBox(m_window);
    m_target->setObjectName("target");
    for (const ExportTargetInfo& t : exportTargets())
        m_target->addItem(QString::fromStdString(t.label), int(t.id));
    m_target->setToolTip(tr("What the LUT is for: the preview shows what this export gives, and "
                            "Export writes it"));
    m_input = new QComboBox(m_window);
    m_input->setObjectName("input");
    m_input->addItem(tr("In-game screenshot"), int(SceneKind::Screenshot));
    m_input->addItem(tr("Linear scene"), int(SceneKind::Scene));
    m_input->setToolTip(tr("What the picture holds: detected when it opens (8/16-bit files are "
                           "screenshots, float files linear scenes); change it if that is wrong"));
    m_chain = new QComboBox(m_window);
    m_chain->setObjectName("chain");
    m_chain->addItem(tr("Smash Ultimate"), int(Preset::Smash));
    m_chain->addItem(tr("Filmic (tone map, soft bloom)"), int(Preset::Pilot));
    m_chain->addItem(tr("Cinematic (bloom, vignette, grain)"), int(Preset::Lecture));
    m_chain->addItem(tr("Display only"), int(Preset::None));
    m_chain->setToolTip(tr("The post-processing the LUT runs in. Smash: the game's own chain. "
                           "Engine and grading targets on a linear scene: choose the chain; on "
                           "a screenshot the LUT applies to the picture as it is"));
    m_interp = new QComboBox(m_window);
    m_interp->setObjectName("interpolation");
    for (Interpolation i :
         {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest})
        m_interp->addItem(QString::fromLatin1(toString(i)), int(i));
    m_interp->setToolTip(tr("LUT interpolation (the game and most engines: trilinear)"));
    m_bloom = menu->addAction(tr("&Bloom"));
    m_bloom->setObjectName("bloom");
    m_bloom->setToolTip(tr("The chain's bloom on a linear scene (a screenshot has its bloom)"));
    m_lut = menu->addAction(tr("&LUT"));
    m_lut->setObjectName("lut");
    m_lut->setToolTip(tr("Apply the LUT (off: the neutral LUT's export, as Before)"));
    menu->addSeparator();
    m_brighten = menu->addAction(tr("Game's B&righten Step"));
    m_brighten->setObjectName("brighten");
    m_brighten->setToolTip(tr("Smash Ultimate brightens after its LUT (about 2x in linear light). "
                              "Off is an inspection view of the LUT alone: not what the game "
                              "shows."));
    for (QAction* a : {m_bloom, m_lut, m_brighten}) {
        a->setCheckable(true);
        connect(a, &QAction::triggered, this, &WindowActions::applyWidgets);
    }
    connect(m_target, &QComboBox::activated, this, [this] {
        m_doc->setTarget(static_cast<ExportTarget>(m_target->currentData().toInt()));
    });
    for (QComboBox* box : {m_input, m_chain, m_interp})
        connect(box, &QComboBox::activated, this, &WindowActions::applyWidgets);
}

void WindowActions::buildToolsMenu() {
    QMenu* menu = m_window->menuBar()->addMenu(tr("&Tools"));
    QAction* plot = menu->addAction(tr("&Plot LUT…"), this, &WindowActions::showPlot);
    plot->setObjectName("plotLut");
    plot->setToolTip(tr("Draw the LUT the export writes for the target, as lutkit plot does"));
    QAction* compare =
        menu->addAction(tr("&Compare with LUT File…"), this, &WindowActions::compareWithFile);
    compare->setObjectName("compareLut");
    compare->setToolTip(tr("How the export differs from a LUT file (ΔE2000, 8-bit steps, where), "
                           "over the open image's colours or the lattice, as lutkit diff does"));
    menu->addSeparator();
    QAction* match =
        menu->addAction(tr("&Match to Reference…"), this, &WindowActions::matchToReference);
    match->setObjectName("matchReference");
    match->setToolTip(tr("A LUT that gives the open picture the look of another picture, as "
                         "lutkit match makes it, with its strength shown live"));
}

void WindowActions::matchToReference() {
    Document* doc = m_doc;
    if (!doc->hasImage()) {
        m_prompts->reportError(tr("Cannot match"),
                               tr("Open a picture first: its look is matched to the reference."));
        return;
    }
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Match to Reference"),
                                                      QFileInfo(doc->imagePath()).absolutePath(),
                                                      FileActions::imageFilter());
    if (!path.isEmpty())
        startMatch(path);
}

MatchDialog* WindowActions::matchDialog() const {
    return m_matchDialog;
}

void WindowActions::startMatch(const QString& path) {
    // Reading the reference and fitting take seconds at 1080p: on a worker, the window live, the
    // status bar showing the progress with Cancel; the dialog opens when the fit is done.
    if (!m_doc->hasImage()) {
        m_prompts->reportError(tr("Cannot match"),
                               tr("Open a picture first: its look is matched to the reference."));
        return;
    }
    const std::shared_ptr<const Image> image = m_doc->storedImage();
    const bool isFloat = m_doc->imageInfo().isFloat;
    m_matchTask->start(
        tr("Matching to %1…").arg(QFileInfo(path).fileName()),
        [this, image, isFloat, path](const Progress& progress) -> BackgroundTask::Delivery {
            auto session = std::make_shared<std::unique_ptr<MatchSession>>(
                std::make_unique<MatchSession>(image, isFloat, path, MatchOptions{}, &progress));
            return [this, session] {
                auto* dlg = new MatchDialog(m_window, EditorContext{m_doc, m_preview, m_prompts},
                                            std::move(*session));
                dlg->setAttribute(Qt::WA_DeleteOnClose);
                m_matchDialog = dlg;
                dlg->open(); // window-modal; returns at once
            };
        },
        [this](const QString& message) { m_prompts->reportError(tr("Cannot match"), message); });
}

void WindowActions::showPlot() {
    try {
        PlotDialog dlg(m_window, *m_doc, m_doc->target(), m_files);
        dlg.exec();
    } catch (const std::exception& e) {
        m_prompts->reportError(tr("Cannot plot the LUT"),
                               QString::fromStdString(humanErrorText(e)));
    }
}

void WindowActions::compareWithFile() {
    Document* doc = m_doc;
    const QString from = !doc->lutPath().isEmpty() ? doc->lutPath() : doc->imagePath();
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Compare with LUT File"),
        from.isEmpty() ? QString() : QFileInfo(from).absolutePath(), FileActions::lutFilter());
    if (!path.isEmpty())
        startCompare(path);
}

CompareDialog* WindowActions::compareDialog() const {
    return m_compareDialog;
}

void WindowActions::startCompare(const QString& path) {
    // The comparison runs on a worker (over a 4K picture it takes seconds): the window stays
    // live, the status bar shows its progress with Cancel, and the report opens when it is done.
    const CompareInput input = compareInput(*m_doc, m_doc->target(), path);
    m_compareTask->start(
        tr("Comparing %1…").arg(QFileInfo(path).fileName()),
        [this, input](const Progress& progress) -> BackgroundTask::Delivery {
            auto c = std::make_shared<const Comparison>(compareLuts(input, &progress));
            return [this, c] {
                m_lastComparison = c;
                auto* dlg = new CompareDialog(m_window, *c, m_files);
                dlg->setAttribute(Qt::WA_DeleteOnClose);
                dlg->show(); // not modal: the window stays usable beside the report
                m_compareDialog = dlg;
            };
        },
        [this](const QString& message) {
            m_prompts->reportError(tr("Cannot compare the LUTs"), message);
        });
}

void WindowActions::buildHelpMenu() {
    QMenu* help = m_window->menuBar()->addMenu(tr("&Help"));
    QMainWindow* window = m_window;
    QAction* quick =
        help->addAction(tr("&Quick Start"), this, [window] { showQuickStart(window); });
    quick->setObjectName("help.quickStartAction");
    quick->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&Keyboard Shortcuts"), this, [window] { showShortcuts(window); })
        ->setObjectName("help.shortcutsAction");
    help->addSeparator();
    help->addAction(tr("&About lutkit editor"), this, [this] {
        QMessageBox::about(m_window, tr("About lutkit editor"),
                           tr("<b>lutkit editor</b><br>Preview colour grading LUTs on screenshots "
                              "exactly as the game or engine shows the exported file, adjust "
                              "and export them.<br>Sampler kernels: %1")
                               .arg(QString::fromLatin1(samplerIsa())));
    });
}

void WindowActions::buildToolbars() {
    QToolBar* tb = m_window->addToolBar(tr("File"));
    tb->setObjectName("toolbar.file");
    tb->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    for (QAction* a : {m_openImage, m_openLut, m_save, m_export})
        tb->addAction(a);
    tb->addSeparator();
    tb->addAction(m_undo);
    tb->addAction(m_redo);
    QToolBar* vt = m_window->addToolBar(tr("View"));
    vt->setObjectName("toolbar.view");
    m_window->addToolBarBreak(); // the preview's choices get a row of their own
    QToolBar* pv = m_window->addToolBar(tr("Preview"));
    pv->setObjectName("toolbar.preview");
    pv->addWidget(new QLabel(tr(" Target "), pv));
    pv->addWidget(m_target);
    pv->addWidget(new QLabel(tr(" Picture "), pv));
    pv->addWidget(m_input);
    pv->addWidget(new QLabel(tr(" Chain "), pv));
    pv->addWidget(m_chain);
    pv->addSeparator();
    for (QAction* a : {m_bloom, m_lut})
        pv->addAction(a);
    pv->addSeparator();
    pv->addWidget(new QLabel(tr(" Interpolation "), pv));
    pv->addWidget(m_interp);
    vt->addAction(m_fit);
    vt->addAction(m_actualSize);
    vt->addSeparator();
    for (QAction* a : m_modes)
        vt->addAction(a);
    vt->addAction(m_clipping);
    m_modes[0]->setText(tr("Split"));
    m_modes[1]->setText(tr("After"));
    m_modes[2]->setText(tr("Before"));
    m_clipping->setText(tr("Clipping"));
}

void WindowActions::applyWidgets() {
    m_preview->setOptions(optionsFromWidgets());
}

PreviewOptions WindowActions::optionsFromWidgets() const {
    PreviewOptions o = m_preview->options();
    o.input = static_cast<SceneKind>(m_input->currentData().toInt());
    if (m_chain->isEnabled()) // disabled, it shows the target's fact, not the user's choice
        o.preset = static_cast<Preset>(m_chain->currentData().toInt());
    o.interpolation = static_cast<Interpolation>(m_interp->currentData().toInt());
    if (m_bloom->isEnabled())
        o.bloom = m_bloom->isChecked();
    o.lutEnabled = m_lut->isChecked();
    if (m_brighten->isEnabled())
        o.brighten = m_brighten->isChecked();
    return o;
}

void WindowActions::showOptions(const PreviewOptions& o) {
    const ExportTarget target = m_doc->target();
    m_target->setCurrentIndex(m_target->findData(int(target)));
    m_input->setCurrentIndex(m_input->findData(int(o.input)));
    // The chain is a choice for engine and grading targets on a linear scene only.
    const bool chooseChain =
        exportTargetInfo(target).purpose == LutPurpose::Raw && o.input == SceneKind::Scene;
    m_chain->setEnabled(chooseChain);
    setItemEnabled(m_chain, m_chain->findData(int(Preset::Smash)), !chooseChain);
    m_chain->setCurrentIndex(m_chain->findData(int(effectivePreset(o, target))));
    m_interp->setCurrentIndex(m_interp->findData(int(o.interpolation)));
    m_bloom->setEnabled(bloomSwitchable(o, target));
    m_bloom->setChecked(bloomApplied(o, target));
    m_lut->setChecked(o.lutEnabled);
    m_brighten->setEnabled(brightenSwitchable(o, target));
    m_brighten->setChecked(brightenApplied(o, target));
}

} // namespace lut::gui
