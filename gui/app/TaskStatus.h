// SPDX-License-Identifier: Apache-2.0
#pragma once
// A long task in the status bar: what runs ("Opening shot.png…"), how far it is (a percentage
// once the task reports one, else a busy bar) and a Cancel button. Hidden while nothing runs.
#include <QString>
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace lut::gui {

class TaskStatus : public QWidget {
    Q_OBJECT
public:
    // `name` is the object name of the widget (its Cancel button is `name` + ".cancel").
    TaskStatus(const QString& name, QWidget* parent = nullptr);
    void setBusy(bool busy);
    void setText(const QString& text);
    void setFraction(double fraction); // 0..1; 0 shows a busy bar
    QString text() const;
    QToolButton* cancelButton() const { return m_cancel; }

signals:
    void cancelRequested();

private:
    QLabel* m_label;
    QProgressBar* m_bar;
    QToolButton* m_cancel;
    QString m_text;
};

} // namespace lut::gui
