#pragma once
// Export settings: one entry per (writable format, layout) so every strip layout is a choice,
// plus size, bit depth, dither and the Smash game compensation, and the target file.
#include "lut/io/Format.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;

namespace lut::gui {

struct ExportChoice {
    QString format; // registry name
    QString layout; // "" unless the format is an image layout
    QString label;
    QString extension; // with dot
};

// Every (format, layout) the registry can write. Image formats are offered once per layout.
QList<ExportChoice> exportChoices();

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    ExportDialog(const QString& suggestedBase, QWidget* parent = nullptr);

    QString path() const;
    ExportChoice choice() const;
    FormatOptions options() const;
    bool smashCompensate() const;

private:
    void choiceChanged();
    void browse();

    QList<ExportChoice> m_choices;
    QComboBox* m_format;
    QLineEdit* m_path;
    QSpinBox* m_size;
    QComboBox* m_bitDepth;
    QCheckBox* m_dither;
    QCheckBox* m_compensate;
    QString m_base;
};

} // namespace lut::gui
