#include "MainWindow.h"

#include "AdjustmentsPanel.h"
#include "Document.h"
#include "ExportDialog.h"
#include "LutView.h"
#include "PreviewView.h"
#include "RecentFiles.h"

#include "lut/Error.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/interp/Sampler.h"
#include "lut/io/Format.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoStack>
#include <QUndoView>

#include <cstdio>

namespace lut::gui {

namespace {

const char* kRecentImagesKey = "recent/images";
const char* kRecentLutsKey = "recent/luts";

QString imageFilter() {
    return QObject::tr("Images (*.png *.exr *.tif *.tiff *.jpg *.jpeg *.bmp *.tga *.hdr *.webp);;"
                       "All files (*)");
}

QString lutFilter() {
    formats::registerBuiltinFormats();
    QStringList patterns;
    for (const Format* f : FormatRegistry::instance().all()) {
        if (!f->canRead())
            continue;
        for (const auto& e : f->extensions()) {
            const QString p = QStringLiteral("*") + QString::fromStdString(e);
            if (!patterns.contains(p))
                patterns << p;
        }
    }
    return QObject::tr("LUT files (%1);;All files (*)").arg(patterns.join(' '));
}

QString fmt3(const float* p) {
    return QStringLiteral("%1 %2 %3")
        .arg(double(p[0]), 0, 'f', 4)
        .arg(double(p[1]), 0, 'f', 4)
        .arg(double(p[2]), 0, 'f', 4);
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_doc(new Document(this)), m_scheduler(new PreviewScheduler(this)) {
    setObjectName("MainWindow");
    setAcceptDrops(true);
    m_view = new PreviewView(this);
    setCentralWidget(m_view);

    buildDocks();
    buildActions();
    buildStatusBar();

    connect(m_doc, &Document::effectiveLutChanged, this, [this] {
        requestPreview(); // first, so the worker starts while the LUT view redraws
        m_lutView->setLut(m_doc->effectiveLut(), m_doc->lutOrigin());
    });
    connect(m_doc, &Document::modifiedChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::pathChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::imageChanged, this, [this] {
        rebuildProxyAndBefore();
        updateTitle();
        requestPreview();
    });
    connect(m_scheduler, &PreviewScheduler::frameReady, this, &MainWindow::onFrame);
    connect(m_view, &PreviewView::hoverPixel, this, &MainWindow::onHover);
    connect(m_view, &PreviewView::zoomChanged, this, [this](double s) {
        m_zoomLabel->setText(tr("Zoom %1 %%2")
                                 .arg(qRound(s * 100))
                                 .arg(m_view->fitMode() ? tr(" (fit)") : QString()));
    });
    connect(m_adjust, &AdjustmentsPanel::interactiveChanged, this, &MainWindow::setInteractive);

    m_lutView->setLut(m_doc->effectiveLut(), m_doc->lutOrigin());
    updateTitle();
    updateRecentMenus();
    resize(1480, 920);
}

MainWindow::~MainWindow() = default;

// ---- construction --------------------------------------------------------------------------

void MainWindow::buildDocks() {
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    m_adjust = new AdjustmentsPanel(m_doc, this);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_adjust);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* adjustDock = new QDockWidget(tr("Adjustments"), this);
    adjustDock->setObjectName("dock.adjustments");
    adjustDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, adjustDock);

    m_lutView = new LutView(this);
    auto* lutDock = new QDockWidget(tr("LUT"), this);
    lutDock->setObjectName("dock.lut");
    lutDock->setWidget(m_lutView);
    addDockWidget(Qt::LeftDockWidgetArea, lutDock);

    m_undoView = new QUndoView(m_doc->undoStack(), this);
    m_undoView->setEmptyLabel(tr("<original>"));
    auto* historyDock = new QDockWidget(tr("History"), this);
    historyDock->setObjectName("dock.history");
    historyDock->setWidget(m_undoView);
    addDockWidget(Qt::LeftDockWidgetArea, historyDock);
    resizeDocks({lutDock, adjustDock}, {330, 330}, Qt::Horizontal);
    resizeDocks({lutDock, historyDock}, {520, 200}, Qt::Vertical);
}

void MainWindow::buildActions() {
    QStyle* st = style();
    // File
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* newMenu = file->addMenu(tr("&New from neutral"));
    for (int size : {16, 17, 32, 33, 64, 65}) {
        QAction* a = newMenu->addAction(QString::number(size) + QChar(0x00B3) +
                                        (size == 16 ? tr(" (Smash)") : QString()));
        connect(a, &QAction::triggered, this, [this, size] { newNeutral(size); });
    }
    QAction* openImage =
        file->addAction(st->standardIcon(QStyle::SP_DirOpenIcon), tr("Open &Image…"),
                        QKeySequence::Open, this, &MainWindow::openImageDialog);
    QAction* openLut =
        file->addAction(st->standardIcon(QStyle::SP_FileDialogDetailedView), tr("Open &LUT…"),
                        QKeySequence(tr("Ctrl+L")), this, &MainWindow::openLutDialog);
    file->addAction(tr("LUT from &Edited Screenshot…"), this, &MainWindow::openScreenshotDialog)
        ->setToolTip(tr("Extract the LUT from a screenshot with an embedded patch (lutkit embed)"));
    m_recentImages = file->addMenu(tr("Recent Images"));
    m_recentLuts = file->addMenu(tr("Recent LUTs"));
    file->addSeparator();
    QAction* save = file->addAction(st->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save LUT"),
                                    QKeySequence::Save, this, [this] { saveDocument(); });
    file->addAction(tr("Save LUT &As…"), QKeySequence::SaveAs, this, &MainWindow::saveAsDialog);
    QAction* exportAct =
        file->addAction(st->standardIcon(QStyle::SP_ArrowForward), tr("&Export LUT…"),
                        QKeySequence(tr("Ctrl+E")), this, &MainWindow::exportDialog);
    file->addAction(tr("Save &Preview Image…"), QKeySequence(tr("Ctrl+Shift+P")), this,
                    &MainWindow::savePreviewDialog);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    // Edit
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_doc->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setIcon(st->standardIcon(QStyle::SP_ArrowBack));
    undo->setIconText(tr("Undo")); // the toolbar keeps a short label; the menu names the step
    QAction* redo = m_doc->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setIcon(st->standardIcon(QStyle::SP_ArrowForward));
    redo->setIconText(tr("Redo"));
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(tr("Reset &Adjustments"), m_doc, &Document::resetAdjustments);

    // View
    m_viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* fit = m_viewMenu->addAction(tr("Zoom to &Fit"), QKeySequence(tr("Ctrl+0")), m_view,
                                         &PreviewView::zoomToFit);
    QAction* actual = m_viewMenu->addAction(tr("&100 %"), QKeySequence(tr("Ctrl+1")), this,
                                            [this] { m_view->zoomTo(1.0); });
    m_viewMenu->addAction(tr("Zoom &In"), QKeySequence::ZoomIn, this,
                          [this] { m_view->zoomBy(1.25); });
    m_viewMenu->addAction(tr("Zoom &Out"), QKeySequence::ZoomOut, this,
                          [this] { m_view->zoomBy(0.8); });
    m_viewMenu->addSeparator();
    auto* modes = new QActionGroup(this);
    QAction* modeActs[3];
    const std::pair<QString, PreviewView::Mode> modeList[] = {
        {tr("Before / After &Split"), PreviewView::Mode::Split},
        {tr("&After Only"), PreviewView::Mode::After},
        {tr("&Before Only"), PreviewView::Mode::Before}};
    for (int i = 0; i < 3; ++i) {
        const auto mode = modeList[i].second;
        modeActs[i] =
            m_viewMenu->addAction(modeList[i].first, this, [this, mode] { m_view->setMode(mode); });
        modeActs[i]->setCheckable(true);
        modes->addAction(modeActs[i]);
    }
    modeActs[0]->setChecked(true);
    connect(m_view, &PreviewView::modeChanged, this,
            [modeActs = std::vector<QAction*>(modeActs, modeActs + 3)](PreviewView::Mode m) {
                modeActs[static_cast<std::size_t>(m)]->setChecked(
                    true); // Mode order = action order
            });
    modeActs[0]->setShortcut(QKeySequence(tr("S")));
    modeActs[1]->setShortcut(QKeySequence(tr("A")));
    modeActs[2]->setShortcut(QKeySequence(tr("B")));
    m_viewMenu->addSeparator();
    for (QDockWidget* d : findChildren<QDockWidget*>())
        m_viewMenu->addAction(d->toggleViewAction());

    // Preview
    QMenu* preview = menuBar()->addMenu(tr("&Preview"));
    m_preset = new QComboBox(this);
    m_preset->setObjectName("preset");
    m_preset->addItem(tr("Smash"), int(Preset::Smash));
    m_preset->addItem(tr("Pilot"), int(Preset::Pilot));
    m_preset->addItem(tr("Lecture"), int(Preset::Lecture));
    m_preset->addItem(tr("None"), int(Preset::None));
    m_preset->setToolTip(
        tr("Post-processing chain the preview runs (the same as lutkit preview --preset)"));
    m_interp = new QComboBox(this);
    m_interp->setObjectName("interpolation");
    for (Interpolation i :
         {Interpolation::Trilinear, Interpolation::Tetrahedral, Interpolation::Nearest})
        m_interp->addItem(QString::fromLatin1(toString(i)), int(i));
    m_interp->setToolTip(tr("LUT interpolation"));
    m_bloomAct = preview->addAction(tr("&Bloom"));
    m_lutAct = preview->addAction(tr("&LUT"));
    m_brightenAct = preview->addAction(tr("B&righten"));
    preview->addSeparator();
    QAction* shotAct = preview->addAction(tr("Input Is an In-Game &Screenshot"));
    shotAct->setObjectName("fromScreenshot");
    shotAct->setCheckable(true);
    shotAct->setToolTip(tr("Undo the game's grading (neutral LUT) before previewing, as "
                           "lutkit preview --from-screenshot; bloom in the image stays"));
    connect(shotAct, &QAction::toggled, this, [this](bool on) {
        QApplication::setOverrideCursor(Qt::WaitCursor);
        m_doc->setFromScreenshot(on);
        QApplication::restoreOverrideCursor();
    });
    for (QAction* a : {m_bloomAct, m_lutAct, m_brightenAct}) {
        a->setCheckable(true);
        a->setChecked(true);
        connect(a, &QAction::toggled, this, [this] { requestPreview(); });
    }
    m_bloomAct->setToolTip(tr("Bloom stage of the preset"));
    m_lutAct->setToolTip(tr("Apply the LUT (off: neutral LUT)"));
    m_brightenAct->setToolTip(tr("Smash brighten pass (x2 in linear light); needs the smash preset "
                                 "and trilinear or tetrahedral interpolation"));
    auto updateBrighten = [this] {
        m_brightenAct->setEnabled(
            m_preset->currentData().toInt() == int(Preset::Smash) &&
            brightenToggleWorks(static_cast<Interpolation>(m_interp->currentData().toInt())));
    };
    connect(m_preset, &QComboBox::currentIndexChanged, this, [this, updateBrighten] {
        updateBrighten();
        requestPreview();
    });
    connect(m_interp, &QComboBox::currentIndexChanged, this, [this, updateBrighten] {
        updateBrighten();
        requestPreview();
    });

    // Help
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About lutkit editor"), this, [this] {
        QMessageBox::about(this, tr("About lutkit editor"),
                           tr("<b>lutkit editor</b><br>Preview colour grading LUTs on screenshots "
                              "through the same pipeline as <tt>lutkit preview</tt>, adjust and "
                              "export them.<br>Sampler kernels: %1")
                               .arg(QString::fromLatin1(samplerIsa())));
    });

    // Toolbars
    QToolBar* tb = addToolBar(tr("File"));
    tb->setObjectName("toolbar.file");
    tb->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    tb->addAction(openImage);
    tb->addAction(openLut);
    tb->addAction(save);
    tb->addAction(exportAct);
    tb->addSeparator();
    tb->addAction(undo);
    tb->addAction(redo);
    QToolBar* pv = addToolBar(tr("Preview"));
    pv->setObjectName("toolbar.preview");
    pv->addWidget(new QLabel(tr(" Preset "), pv));
    pv->addWidget(m_preset);
    pv->addSeparator();
    pv->addAction(m_bloomAct);
    pv->addAction(m_lutAct);
    pv->addAction(m_brightenAct);
    pv->addSeparator();
    pv->addWidget(new QLabel(tr(" Interpolation "), pv));
    pv->addWidget(m_interp);
    QToolBar* vt = addToolBar(tr("View"));
    vt->setObjectName("toolbar.view");
    vt->addAction(fit);
    vt->addAction(actual);
    vt->addSeparator();
    for (QAction* a : modeActs)
        vt->addAction(a);
    modeActs[0]->setText(tr("Split"));
    modeActs[1]->setText(tr("After"));
    modeActs[2]->setText(tr("Before"));
}

void MainWindow::buildStatusBar() {
    m_pixelLabel = new QLabel(this);
    m_pixelLabel->setObjectName("pixelReadout");
    m_pixelLabel->setMinimumWidth(520);
    m_pixelLabel->setTextFormat(Qt::PlainText);
    m_timeLabel = new QLabel(tr("No image"), this);
    m_zoomLabel = new QLabel(this);
    statusBar()->addWidget(m_pixelLabel, 1);
    statusBar()->addPermanentWidget(m_timeLabel);
    statusBar()->addPermanentWidget(m_zoomLabel);
}

// ---- state -> widgets ------------------------------------------------------------------------

void MainWindow::updateTitle() {
    QString title = m_doc->displayName() + QStringLiteral("[*]");
    if (m_doc->hasImage())
        title += QStringLiteral(" — ") + QFileInfo(m_doc->imagePath()).fileName();
    setWindowTitle(title + QStringLiteral(" — lutkit editor"));
    setWindowModified(m_doc->isModified());
}

void MainWindow::reportError(const QString& title, const QString& message) {
    m_lastError = message;
    if (m_interactiveErrors)
        QMessageBox::critical(this, title, message);
    else
        std::fprintf(stderr, "lutkit-editor: %s: %s\n", qPrintable(title), qPrintable(message));
}

void MainWindow::addRecent(const QString& key, const QString& path) {
    if (!m_interactiveErrors)
        return; // headless runs (tests, --screenshot) leave settings alone
    QSettings settings;
    settings.setValue(key, addRecentFile(settings.value(key).toStringList(), path));
    updateRecentMenus();
}

void MainWindow::updateRecentMenus() {
    QSettings settings;
    auto fill = [&](QMenu* menu, const char* key, bool lut) {
        menu->clear();
        const QStringList list = settings.value(key).toStringList();
        for (const QString& p : list) {
            menu->addAction(
                QFileInfo(p).fileName() + QStringLiteral("  (") + QFileInfo(p).path() + ')', this,
                [this, p, lut] { lut ? (void)openLutFile(p) : (void)openImageFile(p); });
        }
        menu->setEnabled(!list.isEmpty());
    };
    fill(m_recentImages, kRecentImagesKey, false);
    fill(m_recentLuts, kRecentLutsKey, true);
}

// ---- files ---------------------------------------------------------------------------------

bool MainWindow::openImageFile(const QString& path) {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        m_doc->openImage(path);
    } catch (const std::exception& e) {
        QApplication::restoreOverrideCursor();
        reportError(tr("Cannot open image"), QString::fromUtf8(e.what()));
        return false;
    }
    QApplication::restoreOverrideCursor();
    addRecent(kRecentImagesKey, path);
    return true;
}

bool MainWindow::openLutFile(const QString& path) {
    if (!maybeSave())
        return false;
    try {
        m_doc->openLut(path);
    } catch (const std::exception& e) {
        reportError(tr("Cannot open LUT"), QString::fromUtf8(e.what()));
        return false;
    }
    addRecent(kRecentLutsKey, path);
    return true;
}

bool MainWindow::openScreenshotLut(const QString& path) {
    if (!maybeSave())
        return false;
    QStringList notes;
    try {
        notes = m_doc->startFromScreenshot(path);
    } catch (const std::exception& e) {
        reportError(tr("Cannot extract a LUT"), QString::fromUtf8(e.what()));
        return false;
    }
    if (!notes.isEmpty()) {
        if (m_interactiveErrors)
            QMessageBox::information(this, tr("LUT extracted"), notes.join('\n'));
        else
            std::fprintf(stderr, "%s\n", qPrintable(notes.join('\n')));
    }
    return true;
}

void MainWindow::newNeutral(int size) {
    if (!maybeSave())
        return;
    m_doc->newNeutral(size);
}

bool MainWindow::exportLut(const QString& path, const QString& format, const FormatOptions& options,
                           bool smashCompensate) {
    try {
        const Diagnostics d = m_doc->exportLut(path, format, options, smashCompensate);
        QStringList lines;
        for (const auto& x : d)
            lines << QString::fromStdString(x.str());
        statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).fileName()), 5000);
        if (!lines.isEmpty() && m_interactiveErrors)
            QMessageBox::information(this, tr("Exported with notes"), lines.join('\n'));
    } catch (const std::exception& e) {
        reportError(tr("Export failed"), QString::fromUtf8(e.what()));
        return false;
    }
    return true;
}

bool MainWindow::saveDocumentAs(const QString& path) {
    try {
        m_doc->saveAs(path);
    } catch (const std::exception& e) {
        reportError(tr("Save failed"), QString::fromUtf8(e.what()));
        return false;
    }
    addRecent(kRecentLutsKey, path);
    statusBar()->showMessage(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

bool MainWindow::saveDocument() {
    const QString path = m_doc->lutPath();
    bool writable = false;
    if (!path.isEmpty()) {
        for (const Format* f : FormatRegistry::instance().forExtension(path.toStdString()))
            writable = writable || f->canWrite();
    }
    if (!writable) {
        saveAsDialog();
        return !m_doc->isModified();
    }
    return saveDocumentAs(path);
}

void MainWindow::saveAsDialog() {
    QString base = m_doc->lutPath();
    if (base.isEmpty())
        base = QStringLiteral("grade.cube");
    const QString path = QFileDialog::getSaveFileName(this, tr("Save LUT"), base,
                                                      tr("Cube LUT (*.cube);;All files (*)"));
    if (!path.isEmpty())
        saveDocumentAs(path);
}

bool MainWindow::maybeSave() {
    if (!m_doc->isModified())
        return true;
    if (!m_interactiveErrors)
        return true; // headless: never block on a question
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("The LUT \"%1\" has unsaved changes. Save them?").arg(m_doc->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return saveDocument();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    if (m_interactiveErrors) {
        QSettings settings;
        settings.setValue("window/geometry", saveGeometry());
        settings.setValue("window/state", saveState());
    }
    e->accept();
}

void MainWindow::restoreWindowState() {
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (e->mimeData()->hasUrls())
        e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    for (const QUrl& url : e->mimeData()->urls()) {
        if (!url.isLocalFile())
            continue;
        const QString path = url.toLocalFile();
        if (looksLikeLutFile(path))
            openLutFile(path);
        else
            openImageFile(path);
    }
    e->acceptProposedAction();
}

void MainWindow::openImageDialog() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Image"), QString(), imageFilter());
    if (!path.isEmpty())
        openImageFile(path);
}

void MainWindow::openLutDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open LUT"), QString(), lutFilter());
    if (!path.isEmpty())
        openLutFile(path);
}

void MainWindow::openScreenshotDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("LUT from Edited Screenshot"),
                                                      QString(), imageFilter());
    if (!path.isEmpty())
        openScreenshotLut(path);
}

void MainWindow::exportDialog() {
    QString base = m_doc->lutPath();
    base = base.isEmpty() ? QStringLiteral("grade")
                          : QFileInfo(base).path() + '/' + QFileInfo(base).completeBaseName();
    ExportDialog dlg(base, this);
    if (dlg.exec() != QDialog::Accepted || dlg.path().isEmpty())
        return;
    exportLut(dlg.path(), dlg.choice().format, dlg.options(), dlg.smashCompensate());
}

void MainWindow::savePreviewDialog() {
    if (!m_doc->hasImage()) {
        reportError(tr("Save preview image"), tr("Open an image first."));
        return;
    }
    const QString base = QFileInfo(m_doc->imagePath()).path() + '/' +
                         QFileInfo(m_doc->imagePath()).completeBaseName() +
                         QStringLiteral("_preview.png");
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save Preview Image"), base, imageFilter());
    if (!path.isEmpty())
        savePreviewImage(path);
}

bool MainWindow::savePreviewImage(const QString& path) {
    if (!m_doc->hasImage()) {
        reportError(tr("Save preview image"), tr("No image is open."));
        return false;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        // Always a fresh full-resolution render: the view may show a proxy.
        PreviewResult r =
            renderPreview(*m_doc->sceneImage(), previewOptions(), m_doc->effectiveLutShared());
        const formats::ImageWriteOptions o =
            formats::renderedImageWriteOptions(m_doc->imageInfo(), path.toStdString());
        formats::writeImage(path.toStdString(), r.image, o);
    } catch (const std::exception& e) {
        QApplication::restoreOverrideCursor();
        reportError(tr("Cannot save the preview"), QString::fromUtf8(e.what()));
        return false;
    }
    QApplication::restoreOverrideCursor();
    statusBar()->showMessage(tr("Saved preview %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

// ---- preview -------------------------------------------------------------------------------

PreviewOptions MainWindow::previewOptions() const {
    PreviewOptions o;
    o.preset = static_cast<Preset>(m_preset->currentData().toInt());
    o.interpolation = static_cast<Interpolation>(m_interp->currentData().toInt());
    o.bloom = m_bloomAct->isChecked();
    o.lutEnabled = m_lutAct->isChecked();
    o.brighten = m_brightenAct->isChecked();
    return o;
}

void MainWindow::setPreviewOptions(const PreviewOptions& o) {
    QSignalBlocker b1(m_preset), b2(m_interp), b3(m_bloomAct), b4(m_lutAct), b5(m_brightenAct);
    m_preset->setCurrentIndex(m_preset->findData(int(o.preset)));
    m_interp->setCurrentIndex(m_interp->findData(int(o.interpolation)));
    m_bloomAct->setChecked(o.bloom);
    m_lutAct->setChecked(o.lutEnabled);
    m_brightenAct->setChecked(o.brighten);
    m_brightenAct->setEnabled(o.preset == Preset::Smash && brightenToggleWorks(o.interpolation));
    requestPreview();
}

void MainWindow::rebuildProxyAndBefore() {
    const auto scene = m_doc->sceneImage();
    m_frame.reset();
    m_beforeLutSource[0].reset();
    m_beforeLutSource[1].reset();
    if (!scene)
        return;
    // Proxy: at most ~1000 pixels wide, what a drag needs to feel live on a 1080p frame.
    m_proxyFactor = std::max(1, (scene->width() + 999) / 1000);
    m_proxyScene =
        m_proxyFactor > 1 ? std::make_shared<const Image>(downscale(*scene, m_proxyFactor)) : scene;
    // "Before" is the same pipeline with nothing but its display encoding.
    PreviewOptions none;
    none.preset = Preset::None;
    none.lutEnabled = false;
    none.bloom = false;
    m_view->setImageSize(QSize(scene->width(), scene->height()));
    m_view->setBefore(toDisplayImage(renderPreview(*scene, none, nullptr).image));
    m_view->setAfter({});
}

void MainWindow::setInteractive(bool on) {
    if (m_interactive == on)
        return;
    m_interactive = on;
    if (!on)
        requestPreview(); // the full-resolution frame after the drag
}

void MainWindow::requestPreview() {
    if (!m_doc->hasImage())
        return;
    auto job = [this](bool proxy) {
        PreviewJob j;
        j.scene = proxy ? m_proxyScene : m_doc->sceneImage();
        j.proxyFactor = proxy ? m_proxyFactor : 1;
        j.lut = m_doc->effectiveLutShared();
        j.options = previewOptions();
        const auto& cached = m_beforeLutSource[proxy ? 1 : 0];
        if (cached && cached->scene == j.scene && sameBeforeLut(cached->options, j.options))
            j.beforeLut = cached->beforeLut;
        return j;
    };
    if (m_proxyFactor > 1 && (m_interactive || !m_scheduler->isBusy()))
        // The proxy first, so a change shows within a proxy render; then (unless a slider is
        // still held) the full frame, which a newer request may replace before it starts.
        m_scheduler->request(job(true));
    if (!m_interactive || m_proxyFactor == 1)
        m_scheduler->request(job(false));
}

void MainWindow::onFrame(std::shared_ptr<const PreviewFrame> frame) {
    if (!frame->error.isEmpty()) {
        m_timeLabel->setText(tr("Preview failed"));
        statusBar()->showMessage(tr("Preview failed: %1").arg(frame->error), 10000);
        if (m_verbose)
            std::fprintf(stderr, "preview: error: %s\n", qPrintable(frame->error));
        return;
    }
    m_frame = frame;
    m_view->setAfter(frame->display);
    if (frame->beforeLut && !frame->reusedBeforeLut)
        m_beforeLutSource[frame->proxyFactor > 1 ? 1 : 0] = frame;
    const QString res = frame->proxyFactor > 1
                            ? tr("proxy 1/%1, %2×%3")
                                  .arg(frame->proxyFactor)
                                  .arg(frame->image.width())
                                  .arg(frame->image.height())
                            : tr("%1×%2").arg(frame->image.width()).arg(frame->image.height());
    m_timeLabel->setText(
        tr("Preview %1 ms (%2)").arg(frame->totalMilliseconds, 0, 'f', 1).arg(res));
    if (frame->proxyFactor == 1) {
        m_times.append(frame->totalMilliseconds);
        if (m_times.size() > 1000)
            m_times.removeFirst();
    }
    if (m_verbose)
        std::fprintf(stderr, "preview #%llu: LUT stages %.1f ms, total %.1f ms (%s%s)\n",
                     static_cast<unsigned long long>(frame->serial), frame->milliseconds,
                     frame->totalMilliseconds, qPrintable(res),
                     frame->reusedBeforeLut ? ", cached pre-LUT stages" : ", all stages");
}

void MainWindow::waitForPreview() {
    if (!m_doc->hasImage())
        return;
    m_scheduler->waitForIdle();
    if (!m_frame || m_frame->proxyFactor != 1 || m_frame->serial != m_scheduler->lastRequested()) {
        // The latest frame was a proxy, or failed: ask for (and wait for) a full-resolution one.
        m_interactive = false;
        requestPreview();
        m_scheduler->waitForIdle();
    }
}

void MainWindow::onHover(int x, int y) {
    const auto stored = m_doc->storedImage();
    if (x < 0 || !stored || x >= stored->width() || y >= stored->height()) {
        m_pixelLabel->clear();
        return;
    }
    QString text = tr("x %1  y %2   in %3").arg(x).arg(y).arg(fmt3(stored->pixel(x, y)));
    if (m_frame && !m_frame->image.empty()) {
        const int f = m_frame->proxyFactor;
        const int fx = std::min(x / f, m_frame->image.width() - 1);
        const int fy = std::min(y / f, m_frame->image.height() - 1);
        const float* o = m_frame->image.pixel(fx, fy);
        const QRgb c = m_frame->display.pixel(fx, fy);
        text += tr("   out %1  (%2 %3 %4)").arg(fmt3(o)).arg(qRed(c)).arg(qGreen(c)).arg(qBlue(c));
    }
    m_pixelLabel->setText(text);
}

} // namespace lut::gui
