// SPDX-License-Identifier: Apache-2.0
#pragma once
// The LUT panel: the N slices of the LUT the export writes (the target's file, read back) as a
// strip in a chosen layout (lut::lutToImage), scaled with nearest-neighbour so every entry stays
// a visible square, and the LUT's facts (size, domain, title, neutral or not, value range) with
// what the window adds (the target, entries outside [0, 1]).
#include "lut/Lut3D.h"
#include "lut/io/Layout.h"

#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;

namespace lut::gui {

class StripWidget;

class LutView : public QWidget {
    Q_OBJECT
public:
    explicit LutView(QWidget* parent = nullptr);
    void setLut(const Lut3D& lut, const QString& origin, const QString& extraHtml = {});
    LutLayout layout() const;
    // Shows the slices in the layout the LUT's strip file has (Document::lutLayout; reshade and
    // unity-32 as the unreal and unity placements they are); none keeps the current choice.
    void setFileLayout(std::optional<LutLayout> layout);
    const QImage& stripImage() const;
    // Strip layouts (N^2 x N) shown as a grid of their N slices, so a dock can show them large;
    // the layout itself (slice order, orientation within a slice) is unchanged.
    static QImage wrapSlices(const QImage& strip, int size);

private:
    void refresh();

    QComboBox* m_layout;
    QCheckBox* m_wrap;
    StripWidget* m_strip;
    QLabel* m_info;
    Lut3D m_lut;
    QString m_origin;
    QString m_extra;
};

} // namespace lut::gui
