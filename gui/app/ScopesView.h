#pragma once
// The scopes of the preview (gui/model/Scopes.h, computed on the worker with every frame): the
// histogram of R, G, B and luma above, the RGB parade below, and the clipped pixels counted.
#include "Scopes.h"

#include <QWidget>

class QLabel;

namespace lut::gui {

class ScopesView : public QWidget {
    Q_OBJECT
public:
    explicit ScopesView(QWidget* parent = nullptr);
    void setScopes(const Scopes& scopes);
    void clear();
    const Scopes& scopes() const { return m_scopes; }
    QString clipText() const;

    QSize sizeHint() const override { return {320, 300}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    Scopes m_scopes;
};

} // namespace lut::gui
