// SPDX-License-Identifier: Apache-2.0
#pragma once
// The scopes of the preview (gui/model/Scopes.h, computed on the worker with every frame): the
// histogram of R, G, B and luma, the RGB parade, the luma waveform (with 0, 25, 50, 75 and 100 %
// lines) and the vectorscope (the 75 % primary and secondary targets, the skin-tone line), any of
// them chosen with the buttons on top (the waveform and the vectorscope by default); the clipped
// pixels are counted below.
#include "Scopes.h"

#include <QWidget>

class QToolButton;

namespace lut::gui {

class ScopesView : public QWidget {
    Q_OBJECT
public:
    enum class Kind { Histogram, Parade, Waveform, Vectorscope };

    explicit ScopesView(QWidget* parent = nullptr);
    void setScopes(const Scopes& scopes);
    void clear();
    const Scopes& scopes() const { return m_scopes; }
    QString clipText() const;
    // Which scopes are shown (default: the waveform and the vectorscope).
    void setShown(Kind kind, bool on);
    bool isShown(Kind kind) const;
    // Where each shown scope is drawn (widget coordinates; empty when hidden). The vectorscope's
    // rectangle is its square: Cb from -0.5 (left) to 0.5, Cr from 0.5 (top) to -0.5.
    QRectF scopeRect(Kind kind) const;
    // A point of the vectorscope (Cb, Cr) in widget coordinates.
    QPointF vectorscopePoint(double cb, double cr) const;

    QSize sizeHint() const override { return {320, 300}; }

protected:
    void paintEvent(QPaintEvent*) override;
    void resizeEvent(QResizeEvent*) override;

private:
    QRectF canvas() const;
    void drawHistogram(QPainter& p, const QRectF& r) const;
    void drawParade(QPainter& p, const QRectF& r) const;
    void drawWaveform(QPainter& p, const QRectF& r) const;
    void drawVectorscope(QPainter& p, const QRectF& r) const;

    Scopes m_scopes;
    QToolButton* m_buttons[4] = {};
};

} // namespace lut::gui
