#include "MainWindow.h"

#include "AdjustmentsPanel.h"
#include "Document.h"
#include "FileActions.h"
#include "LutView.h"
#include "PreviewView.h"
#include "WindowActions.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QUndoView>

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
    m_view = new PreviewView(this);
    setCentralWidget(m_view);

    buildDocks();
    m_files = new FileActions(this);
    m_actions = new WindowActions(this); // after the docks: the View menu lists them
    buildStatusBar();

    connect(m_doc, &Document::effectiveLutChanged, this, [this] {
        m_preview->setLut(m_doc->effectiveLutShared()); // first: the worker starts meanwhile
        m_lutView->setLut(m_doc->effectiveLut(), m_doc->lutOrigin());
    });
    connect(m_doc, &Document::modifiedChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::pathChanged, this, [this] { updateTitle(); });
    connect(m_doc, &Document::imageChanged, this, [this] {
        m_preview->setScene(m_doc->sceneImage());
        updateTitle();
    });
    connect(m_preview, &PreviewController::sceneChanged, this, &MainWindow::onSceneChanged);
    connect(m_preview, &PreviewController::beforeReady, m_view, &PreviewView::setBefore);
    connect(m_preview, &PreviewController::frameReady, this, &MainWindow::onFrame);
    connect(m_view, &PreviewView::hoverPixel, this, &MainWindow::onHover);
    connect(m_view, &PreviewView::zoomChanged, this, [this](double s) {
        m_zoomLabel->setText(tr("Zoom %1 %%2")
                                 .arg(qRound(s * 100))
                                 .arg(m_view->fitMode() ? tr(" (fit)") : QString()));
    });
    connect(m_adjust, &AdjustmentsPanel::interactiveChanged, m_preview,
            &PreviewController::setInteractive);

    m_preview->setLut(m_doc->effectiveLutShared());
    m_lutView->setLut(m_doc->effectiveLut(), m_doc->lutOrigin());
    updateTitle();
    resize(1480, 920);
}

MainWindow::~MainWindow() = default;

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

// ---- files (FileActions) --------------------------------------------------------------------

bool MainWindow::openImageFile(const QString& path) {
    return m_files->openImage(path);
}

bool MainWindow::openLutFile(const QString& path) {
    return m_files->openLut(path);
}

bool MainWindow::openScreenshotLut(const QString& path) {
    return m_files->openScreenshotLut(path);
}

bool MainWindow::exportLut(const QString& path, const QString& format, const FormatOptions& options,
                           bool smashCompensate) {
    return m_files->exportLut(path, format, options, smashCompensate);
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

void MainWindow::onSceneChanged() {
    const auto scene = m_preview->scene();
    if (!scene) {
        m_view->clear();
        m_timeLabel->setText(tr("No image"));
        return;
    }
    m_view->setImageSize(QSize(scene->width(), scene->height()));
    m_view->setBefore(m_preview->beforeImage()); // null until the worker made it
    m_view->setAfter({});
    m_timeLabel->setText(tr("Rendering…"));
}

void MainWindow::onFrame(const std::shared_ptr<const PreviewFrame>& frame) {
    if (!frame->error.isEmpty()) {
        m_timeLabel->setText(tr("Preview failed"));
        statusBar()->showMessage(tr("Preview failed: %1").arg(frame->error), 10000);
        if (m_verbose)
            std::fprintf(stderr, "preview: error: %s\n", qPrintable(frame->error));
        return;
    }
    m_view->setAfter(frame->display);
    const QString res = frame->proxyFactor > 1
                            ? tr("proxy 1/%1, %2×%3")
                                  .arg(frame->proxyFactor)
                                  .arg(frame->image.width())
                                  .arg(frame->image.height())
                            : tr("%1×%2").arg(frame->image.width()).arg(frame->image.height());
    m_timeLabel->setText(
        tr("Preview %1 ms (%2)").arg(frame->totalMilliseconds, 0, 'f', 1).arg(res));
    if (m_verbose)
        std::fprintf(stderr, "preview #%llu: LUT stages %.1f ms, total %.1f ms (%s%s)\n",
                     static_cast<unsigned long long>(frame->serial), frame->milliseconds,
                     frame->totalMilliseconds, qPrintable(res),
                     frame->reusedBeforeLut ? ", cached pre-LUT stages" : ", all stages");
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
    for (const QUrl& url : e->mimeData()->urls()) {
        if (!url.isLocalFile())
            continue;
        const QString path = url.toLocalFile();
        if (looksLikeLutFile(path))
            m_files->openLut(path);
        else
            m_files->openImage(path);
    }
    e->acceptProposedAction();
}

} // namespace lut::gui
