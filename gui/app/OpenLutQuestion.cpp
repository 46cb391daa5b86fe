// SPDX-License-Identifier: Apache-2.0
#include "OpenLutQuestion.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace lut::gui {

std::optional<OpenLutAnswer> askOpenLut(QWidget* parent, const QString& fileName,
                                        const QStringList& layouts, bool askPurpose,
                                        const QString& gameEvidence) {
    QDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("openLut"));
    dialog.setWindowTitle(QDialog::tr("Open LUT"));
    auto* column = new QVBoxLayout(&dialog);
    auto* question = new QLabel(
        QDialog::tr("%1 fits several strip layouts. Read it as:").arg(fileName), &dialog);
    question->setObjectName(QStringLiteral("openLut.question"));
    question->setWordWrap(true);
    column->addWidget(question);
    auto* layout = new QComboBox(&dialog);
    layout->setObjectName(QStringLiteral("openLut.layout"));
    layout->addItems(layouts);
    column->addWidget(layout);
    QRadioButton* edit = nullptr;
    QRadioButton* game = nullptr;
    if (askPurpose) {
        auto* what = new QLabel(
            QDialog::tr("It does not say what it is for. Is it an edit, the look itself (a graded "
                        "neutral strip), or the game's LUT, already made for Smash Ultimate (what "
                        "goes into color_grading_lut.nutexb: Smush-LUT's output, a .nutexb "
                        "converted to a strip)? The game's LUT is not compensated again when "
                        "exported.") +
                (gameEvidence.isEmpty()
                     ? QString()
                     : QDialog::tr("\n\nIts content says it is the game's LUT: %1.")
                           .arg(gameEvidence)),
            &dialog);
        what->setWordWrap(true);
        column->addWidget(what);
        edit = new QRadioButton(QDialog::tr("An edit (the look)"), &dialog);
        game = new QRadioButton(QDialog::tr("The game's LUT"), &dialog);
        edit->setObjectName(QStringLiteral("purpose.raw"));
        game->setObjectName(QStringLiteral("purpose.smash"));
        auto* group = new QButtonGroup(&dialog);
        group->addButton(edit);
        group->addButton(game);
        (gameEvidence.isEmpty() ? edit : game)->setChecked(true);
        column->addWidget(edit);
        column->addWidget(game);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    column->addWidget(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    OpenLutAnswer answer;
    answer.layout = layout->currentText();
    if (askPurpose)
        answer.purpose = game->isChecked() ? LutPurpose::Smash : LutPurpose::Raw;
    return answer;
}

std::optional<LutPurpose> askLutPurpose(QWidget* parent, const QString& fileName,
                                        const QString& gameEvidence) {
    QMessageBox box(
        QMessageBox::Question, QDialog::tr("What is this LUT for?"),
        QDialog::tr("\"%1\" does not say what it is for. Is it an edit, the look "
                    "itself (a graded neutral strip, a .cube from a grading app), or "
                    "the game's LUT, already made for Smash Ultimate (what goes into "
                    "color_grading_lut.nutexb: Smush-LUT's output, a .nutexb "
                    "converted to a strip)?\n\nThe game's LUT is not compensated "
                    "again when exported.")
                .arg(fileName) +
            (gameEvidence.isEmpty()
                 ? QString()
                 : QDialog::tr("\n\nIts content says it is the game's LUT: %1.").arg(gameEvidence)),
        QMessageBox::NoButton, parent);
    QPushButton* edit = box.addButton(QDialog::tr("An Edit (the Look)"), QMessageBox::AcceptRole);
    QPushButton* game = box.addButton(QDialog::tr("The Game's LUT"), QMessageBox::AcceptRole);
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    edit->setObjectName(QStringLiteral("purpose.raw"));
    game->setObjectName(QStringLiteral("purpose.smash"));
    box.setDefaultButton(gameEvidence.isEmpty() ? edit : game);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() != edit && box.clickedButton() != game)
        return std::nullopt;
    return box.clickedButton() == game ? LutPurpose::Smash : LutPurpose::Raw;
}

} // namespace lut::gui
