#include "WindowActions.h"

#include "Document.h"
#include "FileActions.h"
#include "MainWindow.h"
#include "PreviewController.h"
#include "PreviewView.h"

#include "lut/interp/Sampler.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>

namespace lut::gui {

WindowActions::WindowActions(MainWindow* window) : QObject(window), m_window(window) {
    buildFileMenu();
    buildEditMenu();
    buildViewMenu();
    buildPreviewMenu();
    buildHelpMenu();
    buildToolbars();
    showOptions(m_window->preview()->options());
    connect(m_window->preview(), &PreviewController::optionsChanged, this,
            &WindowActions::showOptions);
}

void WindowActions::buildFileMenu() {
    FileActions* files = m_window->fileActions();
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
    file->addAction(tr("LUT from &Edited Screenshot…"), files, &FileActions::openScreenshotDialog)
        ->setToolTip(tr("Extract the LUT from a screenshot with an embedded patch (lutkit embed)"));
    QMenu* recentImages = file->addMenu(tr("Recent Images"));
    QMenu* recentLuts = file->addMenu(tr("Recent LUTs"));
    files->setRecentMenus(recentImages, recentLuts);
    file->addSeparator();
    m_save = file->addAction(st->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save LUT"),
                             QKeySequence::Save, files, [files] { files->save(); });
    file->addAction(tr("Save LUT &As…"), QKeySequence::SaveAs, files, &FileActions::saveAsDialog);
    m_export = file->addAction(st->standardIcon(QStyle::SP_ArrowForward), tr("&Export LUT…"),
                               QKeySequence(tr("Ctrl+E")), files, &FileActions::exportDialog);
    file->addAction(tr("Save &Preview Image…"), QKeySequence(tr("Ctrl+Shift+P")), files,
                    &FileActions::savePreviewDialog);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, m_window, &QWidget::close);
}

void WindowActions::buildEditMenu() {
    QStyle* st = m_window->style();
    Document* doc = m_window->document();
    QMenu* edit = m_window->menuBar()->addMenu(tr("&Edit"));
    m_undo = doc->undoStack()->createUndoAction(m_window, tr("&Undo"));
    m_undo->setShortcut(QKeySequence::Undo);
    m_undo->setIcon(st->standardIcon(QStyle::SP_ArrowBack));
    m_undo->setIconText(tr("Undo")); // the toolbar keeps a short label; the menu names the step
    m_redo = doc->undoStack()->createRedoAction(m_window, tr("&Redo"));
    m_redo->setShortcut(QKeySequence::Redo);
    m_redo->setIcon(st->standardIcon(QStyle::SP_ArrowForward));
    m_redo->setIconText(tr("Redo"));
    edit->addAction(m_undo);
    edit->addAction(m_redo);
    edit->addSeparator();
    edit->addAction(tr("Reset &Adjustments"), doc, &Document::resetAdjustments);
}

void WindowActions::buildViewMenu() {
    PreviewView* view = m_window->previewView();
    QMenu* menu = m_window->menuBar()->addMenu(tr("&View"));
    m_fit = menu->addAction(tr("Zoom to &Fit"), QKeySequence(tr("Ctrl+0")), view,
                            &PreviewView::zoomToFit);
    m_actualSize = menu->addAction(tr("&100 %"), QKeySequence(tr("Ctrl+1")), view,
                                   [view] { view->zoomTo(1.0); });
    menu->addAction(tr("Zoom &In"), QKeySequence::ZoomIn, view, [view] { view->zoomBy(1.25); });
    menu->addAction(tr("Zoom &Out"), QKeySequence::ZoomOut, view, [view] { view->zoomBy(0.8); });
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
    for (QDockWidget* d : m_window->findChildren<QDockWidget*>())
        menu->addAction(d->toggleViewAction());
}

void WindowActions::buildPreviewMenu() {
    QMenu* menu = m_window->menuBar()->addMenu(tr("&Preview"));
    m_preset = new QComboBox(m_window);
    m_preset->setObjectName("preset");
    m_preset->addItem(tr("Smash"), int(Preset::Smash));
    m_preset->addItem(tr("Pilot"), int(Preset::Pilot));
    m_preset->addItem(tr("Lecture"), int(Preset::Lecture));
    m_preset->addItem(tr("None"), int(Preset::None));
    m_preset->setToolTip(
        tr("Post-processing chain the preview runs (the same as lutkit preview --preset)"));
    m_interp = new QComboBox(m_window);
    m_interp->setObjectName("interpolation");
    for (Interpolation i :
         {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest})
        m_interp->addItem(QString::fromLatin1(toString(i)), int(i));
    m_interp->setToolTip(tr("LUT interpolation"));
    m_bloom = menu->addAction(tr("&Bloom"));
    m_bloom->setObjectName("bloom");
    m_bloom->setToolTip(tr("Bloom stage of the preset"));
    m_lut = menu->addAction(tr("&LUT"));
    m_lut->setObjectName("lut");
    m_lut->setToolTip(tr("Apply the LUT (off: neutral LUT)"));
    m_brighten = menu->addAction(tr("B&righten"));
    m_brighten->setObjectName("brighten");
    m_brighten->setToolTip(tr("The game's brighten step (about 2x in linear light) after the "
                              "LUT; off shows the LUT alone. Only the Smash preset has one."));
    for (QAction* a : {m_bloom, m_lut, m_brighten}) {
        a->setCheckable(true);
        connect(a, &QAction::triggered, this,
                [this] { m_window->preview()->setOptions(optionsFromWidgets()); });
    }
    for (QComboBox* box : {m_preset, m_interp})
        connect(box, &QComboBox::activated, this,
                [this] { m_window->preview()->setOptions(optionsFromWidgets()); });

    menu->addSeparator();
    m_fromScreenshot = menu->addAction(tr("Input Is an In-Game &Screenshot"));
    m_fromScreenshot->setObjectName("fromScreenshot");
    m_fromScreenshot->setCheckable(true);
    m_fromScreenshot->setToolTip(tr("Undo the game's grading (neutral LUT) before previewing, as "
                                    "lutkit preview --from-screenshot; bloom in the image stays"));
    connect(m_fromScreenshot, &QAction::toggled, this, [this](bool on) {
        QApplication::setOverrideCursor(Qt::WaitCursor);
        m_window->document()->setFromScreenshot(on);
        QApplication::restoreOverrideCursor();
    });
}

void WindowActions::buildHelpMenu() {
    QMenu* help = m_window->menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About lutkit editor"), this, [this] {
        QMessageBox::about(m_window, tr("About lutkit editor"),
                           tr("<b>lutkit editor</b><br>Preview colour grading LUTs on screenshots "
                              "through the same pipeline as <tt>lutkit preview</tt>, adjust and "
                              "export them.<br>Sampler kernels: %1")
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
    QToolBar* pv = m_window->addToolBar(tr("Preview"));
    pv->setObjectName("toolbar.preview");
    pv->addWidget(new QLabel(tr(" Preset "), pv));
    pv->addWidget(m_preset);
    pv->addSeparator();
    for (QAction* a : {m_bloom, m_lut, m_brighten})
        pv->addAction(a);
    pv->addSeparator();
    pv->addWidget(new QLabel(tr(" Interpolation "), pv));
    pv->addWidget(m_interp);
    QToolBar* vt = m_window->addToolBar(tr("View"));
    vt->setObjectName("toolbar.view");
    vt->addAction(m_fit);
    vt->addAction(m_actualSize);
    vt->addSeparator();
    for (QAction* a : m_modes)
        vt->addAction(a);
    m_modes[0]->setText(tr("Split"));
    m_modes[1]->setText(tr("After"));
    m_modes[2]->setText(tr("Before"));
}

PreviewOptions WindowActions::optionsFromWidgets() const {
    PreviewOptions o = m_window->preview()->options();
    o.preset = static_cast<Preset>(m_preset->currentData().toInt());
    o.interpolation = static_cast<Interpolation>(m_interp->currentData().toInt());
    o.bloom = m_bloom->isChecked();
    o.lutEnabled = m_lut->isChecked();
    if (m_brighten->isEnabled()) // disabled, it shows the preset's fact, not the user's choice
        o.brighten = m_brighten->isChecked();
    return o;
}

void WindowActions::showOptions(const PreviewOptions& o) {
    m_preset->setCurrentIndex(m_preset->findData(int(o.preset)));
    m_interp->setCurrentIndex(m_interp->findData(int(o.interpolation)));
    m_bloom->setChecked(o.bloom);
    m_lut->setChecked(o.lutEnabled);
    // Checked = the preview has the brighten step; only the smash preset can switch it.
    m_brighten->setEnabled(brightenSwitchable(o));
    m_brighten->setChecked(brightenApplied(o));
}

} // namespace lut::gui
