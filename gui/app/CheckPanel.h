// SPDX-License-Identifier: Apache-2.0
#pragma once
// The "Check" panel: lutkit check of the LUT the export writes (gui/model/CheckModel), kept
// current as the LUT changes: the verdict, one line per check, the findings worst first. Clicking
// a finding highlights its colours on the picture (highlightChanged, drawn by the preview); a
// second click or "Clear" removes it. "Over the picture's colours" weighs the check by the
// picture instead of the whole cube.
#include <QImage>
#include <QWidget>

class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace lut::gui {

class CheckModel;

class CheckPanel : public QWidget {
    Q_OBJECT
public:
    CheckPanel(CheckModel* model, QWidget* parent = nullptr);

    CheckModel* model() const { return m_model; }
    QListWidget* findingsList() const { return m_list; }
    QString verdictText() const;

    QSize sizeHint() const override { return {330, 300}; }

signals:
    // The overlay to draw over the picture (null: none).
    void highlightChanged(const QImage& overlay);

private:
    void showReport();
    void showHighlight();
    void onClicked(int row);

    CheckModel* m_model;
    QLabel* m_verdict = nullptr;
    QLabel* m_checks = nullptr;
    QListWidget* m_list = nullptr;
    QLabel* m_highlightText = nullptr;
    QPushButton* m_clear = nullptr;
    QCheckBox* m_overPicture = nullptr;
};

} // namespace lut::gui
