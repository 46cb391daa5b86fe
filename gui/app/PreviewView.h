// SPDX-License-Identifier: Apache-2.0
#pragma once
// The image view: before (left of the divider) and after (right), a draggable divider, zoom
// (fit, 100 %, wheel about the cursor) and pan (drag with the left button away from the divider,
// or the middle button). Images may be proxies: each is drawn over the full image rectangle. The
// clipping overlay, when on, marks the after picture's clipped pixels.
#include <QImage>
#include <QWidget>

namespace lut::gui {

class PreviewView : public QWidget {
    Q_OBJECT
public:
    enum class Mode { Split, After, Before };

    explicit PreviewView(QWidget* parent = nullptr);

    // Full image size in pixels (the coordinate system of hover reports).
    void setImageSize(QSize size);
    void setBefore(const QImage& image);
    // The after picture and its clipping overlay (Scopes.h clipOverlay; may be null).
    void setAfter(const QImage& image, const QImage& clipOverlay = {});
    // Marks the clipped pixels of the after picture (red: a channel at 255, blue: at 0).
    void setShowClipping(bool on);
    bool showsClipping() const { return m_showClipping; }
    // An overlay drawn over the whole picture, both sides (the Check panel's highlighted
    // colours); null: none.
    void setHighlight(const QImage& overlay);
    const QImage& highlight() const { return m_highlight; }
    void clear();

    void setMode(Mode mode);
    Mode mode() const { return m_mode; }
    double split() const { return m_split; } // divider position, 0..1 of the image width
    void setSplit(double fraction);

    bool fitMode() const { return m_fit; }
    double zoom() const; // current scale (screen px per image px)
    void zoomToFit();
    void zoomTo(double scale, QPointF anchorWidget = QPointF(-1, -1));
    void zoomBy(double factor);

    QSize sizeHint() const override { return {960, 600}; }

signals:
    void hoverPixel(int x, int y); // image coordinates, (-1, -1) when outside
    void zoomChanged(double scale);
    void modeChanged(lut::gui::PreviewView::Mode mode);

protected:
    void paintEvent(QPaintEvent*) override;
    void resizeEvent(QResizeEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void leaveEvent(QEvent*) override;

private:
    QRectF imageRect() const; // where the full image lands in widget coordinates
    double dividerX() const;  // widget x of the divider
    bool nearDivider(QPointF p) const;
    void clampOffset();

    QSize m_imageSize;
    QImage m_before;
    QImage m_after;
    QImage m_clip;
    QImage m_highlight;
    bool m_showClipping = false;
    Mode m_mode = Mode::Split;
    double m_split = 0.5;
    bool m_fit = true;
    double m_scale = 1.0;
    QPointF m_offset; // top-left of the image in widget coordinates (non-fit)
    enum class Drag { None, Divider, Pan } m_drag = Drag::None;
    QPointF m_dragStart;
    QPointF m_offsetStart;
};

} // namespace lut::gui
