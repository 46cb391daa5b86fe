// SPDX-License-Identifier: Apache-2.0
#include "MainWindow.h"

#include "AdjustmentsPanel.h"
#include "BackgroundTask.h"
#include "CheckModel.h"
#include "CheckPanel.h"
#include "CurvesPanel.h"
#include "Document.h"
#include "FileActions.h"
#include "FileLoader.h"
#include "LutView.h"
#include "PreviewView.h"
#include "ScopesView.h"
#include "ShortcutGuard.h"
#include "TaskStatus.h"
#include "WheelsPanel.h"
#include "WindowActions.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolButton>
#include <QUndoStack>
#include <QUndoView>
#include <QVBoxLayout>

#include <cstdio>

namespace lut::gui {

namespace {

QString fmt3(const float* p) {
    return QStringLiteral("%1 %2 %3")
        .arg(double(p[0]), 0, 'f', 4)
        .arg(double(p[1]), 0, 'f', 4)
        .arg(double(p[2]), 0, 'f', 4);
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_doc(new Document(this)), m_preview(new PreviewController(this)) {
    setObjectName("MainWindow");
    setAcceptDrops(true);
    m_preview->setDocument(m_doc); // the preview grades for the document's target
    buildCentre();
    buildDocks();
    m_loading = new TaskStatus(QStringLiteral("loading"), this); // FileActions connects to it
    const EditorContext context{m_doc, m_preview, this};
    m_files = new FileActions(context, this);
    // After the docks: the View menu lists them.
    m_actions = new WindowActions(this, context, m_files, m_view);
    buildStatusBar();
    // Ctrl+Z, Ctrl+E... from any widget, a spin box being typed in included.
    qApp->installEventFilter(new ShortcutGuard(this));

    connect(m_doc, &Document::effectiveLutChanged, this,
            [this] { m_preview->setSource(m_doc->lutSource()); });
    connect(m_doc, &Document::modifiedChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::pathChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::lutReplaced, this, [this] {
        m_lutView->setFileLayout(m_doc->lutLayout()); // a smush strip's slices as smush
        if (m_doc->lutNotes().isEmpty())
            m_notesBar->hide();
    });
    connect(m_doc, &Document::imageChanged, this, &MainWindow::onImageChanged);
    connect(m_preview, &PreviewController::imageChanged, this, [this] {
        const QSize size = m_preview->imageSize();
        if (size.isEmpty()) {
            m_view->clear();
            m_scopes->clear();
            m_timeLabel->setText(tr("No image"));
            return;
        }
        m_view->setImageSize(size);
        m_view->setBefore({});
        m_view->setAfter({});
        m_timeLabel->setText(tr("Preparing…"));
    });
    connect(m_preview, &PreviewController::beforeReady, m_view, &PreviewView::setBefore);
    connect(m_preview, &PreviewController::frameReady, this, &MainWindow::onFrame);
    connect(m_preview, &PreviewController::targetLutChanged, this, &MainWindow::onTargetLut);
    connect(m_preview, &PreviewController::optionsChanged, this, [this] { updateExportState(); });
    connect(m_doc, &Document::targetChanged, this, [this] { updateExportState(); });
    connect(m_view, &PreviewView::hoverPixel, this, &MainWindow::onHover);
    connect(m_view, &PreviewView::zoomChanged, this, [this](double s) {
        m_zoomLabel->setText(tr("Zoom %1 %%2")
                                 .arg(qRound(s * 100))
                                 .arg(m_view->fitMode() ? tr(" (fit)") : QString()));
    });
    connect(m_adjust, &AdjustmentsPanel::interactiveChanged, m_preview,
            &PreviewController::setInteractive);
    connect(m_curves, &CurvesPanel::interactiveChanged, m_preview,
            &PreviewController::setInteractive);
    connect(m_wheels, &WheelsPanel::interactiveChanged, m_preview,
            &PreviewController::setInteractive);

    m_preview->setSource(m_doc->lutSource());
    updateTitle();
    updateExportState();
    resize(1480, 920);
}

MainWindow::~MainWindow() = default;

void MainWindow::buildCentre() {
    auto* centre = new QWidget(this);
    auto* v = new QVBoxLayout(centre);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(0);
    // The notes bar: what readers and writers said (an ambiguous strip's layout, rounding...).
    m_notesBar = new QWidget(centre);
    m_notesBar->setObjectName("notesBar");
    m_notesBar->setAutoFillBackground(true);
    QPalette pal = m_notesBar->palette();
    pal.setColor(QPalette::Window, QColor(0x4a, 0x43, 0x2a));
    m_notesBar->setPalette(pal);
    auto* h = new QHBoxLayout(m_notesBar);
    h->setContentsMargins(8, 4, 4, 4);
    m_notesLabel = new QLabel(m_notesBar);
    m_notesLabel->setObjectName("notes");
    m_notesLabel->setWordWrap(true);
    m_notesLabel->setTextFormat(Qt::PlainText);
    m_notesLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* close = new QToolButton(m_notesBar);
    close->setAutoRaise(true);
    close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    close->setToolTip(tr("Hide the notes"));
    connect(close, &QToolButton::clicked, m_notesBar, &QWidget::hide);
    h->addWidget(m_notesLabel, 1);
    h->addWidget(close, 0, Qt::AlignTop);
    m_notesBar->hide();
    m_view = new PreviewView(centre);
    v->addWidget(m_notesBar);
    v->addWidget(m_view, 1);
    setCentralWidget(centre);
}

void MainWindow::buildDocks() {
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    auto makeDock = [this](QWidget* content, const QString& title, const char* name, bool scroll) {
        QWidget* w = content;
        if (scroll) {
            auto* area = new QScrollArea(this);
            area->setWidget(content);
            area->setWidgetResizable(true);
            area->setFrameShape(QFrame::NoFrame);
            w = area;
        }
        auto* dock = new QDockWidget(title, this);
        dock->setObjectName(QString::fromLatin1(name));
        dock->setWidget(w);
        return dock;
    };
    m_adjust = new AdjustmentsPanel(m_doc, this);
    m_curves = new CurvesPanel(m_doc, this);
    m_wheels = new WheelsPanel(m_doc, this);
    m_lutView = new LutView(this);
    m_scopes = new ScopesView(this);
    m_undoView = new QUndoView(m_doc->undoStack(), this);
    m_checkModel = new CheckModel(this);
    m_check = new CheckPanel(m_checkModel, this);
    connect(m_check, &CheckPanel::highlightChanged, m_view, &PreviewView::setHighlight);
    m_undoView->setEmptyLabel(tr("<original>"));

    QDockWidget* adjustDock = makeDock(m_adjust, tr("Adjustments"), "dock.adjustments", true);
    QDockWidget* curvesDock = makeDock(m_curves, tr("Curves"), "dock.curves", false);
    QDockWidget* wheelsDock = makeDock(m_wheels, tr("Colour wheels"), "dock.wheels", false);
    QDockWidget* lutDock = makeDock(m_lutView, tr("LUT"), "dock.lut", true);
    QDockWidget* scopesDock = makeDock(m_scopes, tr("Scopes"), "dock.scopes", false);
    QDockWidget* historyDock = makeDock(m_undoView, tr("History"), "dock.history", false);
    QDockWidget* checkDock = makeDock(m_check, tr("Check"), "dock.check", false);
    addDockWidget(Qt::RightDockWidgetArea, adjustDock);
    addDockWidget(Qt::RightDockWidgetArea, wheelsDock);
    addDockWidget(Qt::RightDockWidgetArea, curvesDock);
    tabifyDockWidget(curvesDock, wheelsDock);
    curvesDock->raise();
    addDockWidget(Qt::LeftDockWidgetArea, lutDock);
    addDockWidget(Qt::LeftDockWidgetArea, scopesDock);
    addDockWidget(Qt::LeftDockWidgetArea, historyDock);
    tabifyDockWidget(scopesDock, historyDock);
    tabifyDockWidget(scopesDock, checkDock);
    scopesDock->raise();
    resizeDocks({lutDock, adjustDock}, {330, 340}, Qt::Horizontal);
    resizeDocks({lutDock, scopesDock}, {340, 420}, Qt::Vertical); // room for the vectorscope
    resizeDocks({adjustDock, curvesDock}, {520, 300}, Qt::Vertical);
}

void MainWindow::buildStatusBar() {
    m_pixelLabel = new QLabel(this);
    m_pixelLabel->setObjectName("pixelReadout");
    m_pixelLabel->setMinimumWidth(420);
    m_pixelLabel->setTextFormat(Qt::PlainText);
    m_exportLabel = new QLabel(this);
    m_exportLabel->setObjectName("exportState");
    m_clipLabel = new QLabel(this);
    m_clipLabel->setObjectName("clipCount");
    m_timeLabel = new QLabel(tr("No image"), this);
    m_zoomLabel = new QLabel(this);
    statusBar()->addWidget(m_loading);
    statusBar()->addWidget(m_pixelLabel, 1);
    statusBar()->addPermanentWidget(m_exportLabel);
    statusBar()->addPermanentWidget(m_clipLabel);
    statusBar()->addPermanentWidget(m_timeLabel);
    statusBar()->addPermanentWidget(m_zoomLabel);
}

void MainWindow::updateTitle() {
    QString title = m_doc->displayName() + QStringLiteral("[*]");
    if (m_doc->hasImage())
        title += QStringLiteral(" — ") + QFileInfo(m_doc->imagePath()).fileName();
    setWindowTitle(title + QStringLiteral(" — lutkit editor"));
    setWindowModified(m_doc->isModified());
}

void MainWindow::updateExportState() {
    // Connects the picture with the file: what the preview shows is the target's export.
    const PreviewOptions& o = m_preview->options();
    const QString target = QString::fromStdString(exportTargetInfo(m_doc->target()).label);
    if (showsTheExport(o, m_doc->target())) {
        m_exportLabel->setText(tr("Shows the %1 export").arg(target));
        m_exportLabel->setStyleSheet(QString());
    } else {
        m_exportLabel->setText(tr("Inspection view: not what the %1 export gives").arg(target));
        m_exportLabel->setStyleSheet(QStringLiteral("color: #f0b040;"));
    }
}

QString MainWindow::clipText() const {
    return m_clipLabel->text();
}

void MainWindow::reportError(const QString& title, const QString& message) {
    m_lastError = message;
    if (m_interactiveErrors)
        QMessageBox::critical(this, title, message);
    else
        std::fprintf(stderr, "lutkit-editor: %s: %s\n", qPrintable(title), qPrintable(message));
}

void MainWindow::showNotes(const QStringList& notes) {
    if (notes.isEmpty())
        return;
    m_notesLabel->setText(notes.join('\n'));
    m_notesBar->show();
    if (!m_interactiveErrors)
        for (const QString& n : notes)
            std::fprintf(stderr, "lutkit-editor: %s\n", qPrintable(n));
}

QString MainWindow::notesText() const {
    return m_notesBar->isHidden() ? QString() : m_notesLabel->text();
}

void MainWindow::showStatus(const QString& message) {
    statusBar()->showMessage(message, 5000);
}

void MainWindow::setLoading(bool busy) {
    m_loading->setBusy(busy);
}

void MainWindow::setLoadingText(const QString& text) {
    m_loading->setText(text);
}

TaskStatus* MainWindow::watchTask(BackgroundTask* task, const QString& name) {
    auto* status = new TaskStatus(name, this);
    statusBar()->addWidget(status);
    connect(task, &BackgroundTask::busyChanged, status, [status, task](bool busy) {
        status->setText(task->label());
        status->setBusy(busy);
    });
    connect(task, &BackgroundTask::progressChanged, status, &TaskStatus::setFraction);
    connect(status, &TaskStatus::cancelRequested, task, &BackgroundTask::cancel);
    return status;
}

bool MainWindow::isLoading() const {
    return m_files->loader()->isBusy();
}

void MainWindow::waitForLoads() {
    QApplication::processEvents(); // a dropped LUT starts loading once the drop has returned
    m_files->loader()->waitForIdle();
}

// ---- files (FileActions) --------------------------------------------------------------------

bool MainWindow::openImageFile(const QString& path) {
    return m_files->openImage(path);
}

bool MainWindow::openLutFile(const QString& path, const FormatOptions& options) {
    return m_files->openLut(path, options);
}

bool MainWindow::openScreenshotLut(const QString& path) {
    return m_files->openScreenshotLut(path);
}

bool MainWindow::exportLut(const QString& path, const QString& format, const FormatOptions& options,
                           ExportTarget target, bool overwrite, const StrengthOptions& strength) {
    return m_files->exportLut(path, format, options, target, overwrite, strength);
}

bool MainWindow::savePreviewImage(const QString& path) {
    return m_files->savePreviewImage(path);
}

bool MainWindow::saveDocument() {
    return m_files->save();
}

bool MainWindow::saveDocumentAs(const QString& path) {
    return m_files->saveAs(path);
}

// ---- preview (PreviewController) ------------------------------------------------------------

PreviewOptions MainWindow::previewOptions() const {
    return m_preview->options();
}

void MainWindow::setPreviewOptions(const PreviewOptions& options) {
    m_preview->setOptions(options);
}

void MainWindow::waitForPreview() {
    m_preview->waitForFullResolution();
}

std::shared_ptr<const PreviewFrame> MainWindow::currentFrame() const {
    return m_preview->currentFrame();
}

const QList<double>& MainWindow::previewTimes() const {
    return m_preview->fullResolutionTimes();
}

void MainWindow::setInteractive(bool on) {
    m_preview->setInteractive(on);
}

void MainWindow::onImageChanged() {
    // The kind of picture decides the chain (screenshot or linear scene): detected from the
    // file's pixel type, shown in the toolbar, switchable there.
    PreviewOptions o = m_preview->options();
    o.input = detectSceneKind(m_doc->imageInfo().isFloat);
    m_preview->setOptions(o);
    m_preview->setImage(m_doc->storedImage(), m_doc->imageInfo().isFloat);
    m_checkModel->setPicture(m_doc->storedImage());
    updateTitle();
}

void MainWindow::onFrame(const std::shared_ptr<const PreviewFrame>& frame) {
    if (!frame->error.isEmpty()) {
        m_timeLabel->setText(tr("Preview failed"));
        statusBar()->showMessage(tr("Preview failed: %1").arg(frame->error), 10000);
        if (m_verbose)
            std::fprintf(stderr, "preview: error: %s\n", qPrintable(frame->error));
        return;
    }
    m_view->setAfter(frame->display, frame->clipOverlay);
    m_scopes->setScopes(frame->scopes);
    const QString res = frame->proxyFactor > 1
                            ? tr("proxy 1/%1, %2×%3")
                                  .arg(frame->proxyFactor)
                                  .arg(frame->image.width())
                                  .arg(frame->image.height())
                            : tr("%1×%2").arg(frame->image.width()).arg(frame->image.height());
    m_timeLabel->setText(
        tr("Preview %1 ms (%2)").arg(frame->totalMilliseconds, 0, 'f', 1).arg(res));
    if (m_verbose)
        std::fprintf(stderr,
                     "preview #%llu: export LUT %.1f ms, LUT stages %.1f ms, scopes %.1f ms, "
                     "total %.1f ms (%s%s)\n",
                     static_cast<unsigned long long>(frame->serial), frame->targetMilliseconds,
                     frame->milliseconds, frame->scopesMilliseconds, frame->totalMilliseconds,
                     qPrintable(res),
                     frame->reusedBeforeLut ? ", cached pre-LUT stages" : ", all stages");
}

void MainWindow::onTargetLut(const std::shared_ptr<const TargetLut>& target) {
    const ClipCount& c = target->clip;
    const QString count = tr("LUT entries outside 0..1: %1 of %2").arg(c.outside).arg(c.entries);
    m_clipLabel->setText(count);
    m_clipLabel->setStyleSheet(c.outside ? QStringLiteral("color: #f0b040;") : QString());
    m_clipLabel->setToolTip(tr("Entries of the exported LUT the file clamps to 0..1: %1 above, "
                               "%2 below, %3 not finite")
                                .arg(c.above)
                                .arg(c.below)
                                .arg(c.nonFinite));
    const ExportTargetInfo& info = exportTargetInfo(m_doc->target());
    QString extra = tr("<b>Export</b> %1, %2 as written and read back<br><b>Outside 0..1</b> %3")
                        .arg(QString::fromStdString(info.label).toHtmlEscaped())
                        .arg(QString::number(target->shown->size()) + QChar(0x00B3))
                        .arg(c.outside);
    if (!m_doc->lutNotes().isEmpty())
        extra += QStringLiteral("<br><b>Notes</b> ") + m_doc->lutNotes().join(' ').toHtmlEscaped();
    m_lutView->setLut(*target->shown, m_doc->lutOrigin(), extra);
    m_checkModel->setLut(target->shown, m_doc->target() == ExportTarget::Smash);
}

QStringList MainWindow::checkWarnings(ExportTarget target) const {
    return target == m_doc->target() ? m_checkModel->failingChecks() : QStringList();
}

void MainWindow::onHover(int x, int y) {
    const auto stored = m_doc->storedImage();
    if (x < 0 || !stored || x >= stored->width() || y >= stored->height()) {
        m_pixelLabel->clear();
        return;
    }
    QString text = tr("x %1  y %2   in %3").arg(x).arg(y).arg(fmt3(stored->pixel(x, y)));
    const auto frame = m_preview->currentFrame();
    if (frame && !frame->image.empty()) {
        const int f = frame->proxyFactor;
        const int fx = std::min(x / f, frame->image.width() - 1);
        const int fy = std::min(y / f, frame->image.height() - 1);
        const float* o = frame->image.pixel(fx, fy);
        const QRgb c = frame->display.pixel(fx, fy);
        text += tr("   out %1  (%2 %3 %4)").arg(fmt3(o)).arg(qRed(c)).arg(qGreen(c)).arg(qBlue(c));
    }
    m_pixelLabel->setText(text);
}

// ---- window events --------------------------------------------------------------------------

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!m_files->maybeSave()) {
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
    // Read on the worker: the drop returns at once, the files arrive when read. A LUT is opened
    // as File > Open LUT opens it (a 256x16 strip is asked its layout), after the drop has
    // returned, so the question never holds up the drag source.
    for (const QUrl& url : e->mimeData()->urls()) {
        if (!url.isLocalFile())
            continue;
        const QString path = url.toLocalFile();
        if (looksLikeLutFile(path))
            QMetaObject::invokeMethod(
                m_files, [this, path] { m_files->openLutAsking(path); }, Qt::QueuedConnection);
        else
            m_files->startOpenImage(path);
    }
    e->acceptProposedAction();
}

} // namespace lut::gui
