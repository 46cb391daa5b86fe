// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tools > Match to Reference…: the match of the open picture to a reference picture
// (MatchSession, fitted on a worker before the dialog opens: WindowActions), shown live in the
// window while its sliders move: strength, lightness and colour amounts (each with its value in
// a number box beside it), what to keep. Lightness and Colour share follow Strength (lutkit
// match's rule: unset, they are the strength) until one is moved on its own; from then on it
// keeps its value. Every move re-bakes the LUT on a worker (MatchBaker: latest wins), never on
// the window's thread: while a slider is dragged the preview shows the last table baked, and the
// table of the values the slider rests on replaces it. OK keeps the matched LUT of the values
// shown as the document's LUT in one undo step (exported through the same target choice as
// every other edit; pressed while a bake runs, it waits for that bake, the window live); Cancel
// puts the LUT back as it was and drops what is still baking.
#include "MatchBaker.h"
#include "MatchSession.h"

#include <QDialog>

#include <memory>

class QCheckBox;
class QFormLayout;
class QPlainTextEdit;
class QPushButton;
class QSlider;
class QSpinBox;

namespace lut::gui {

class Document;
class PreviewController;
class Prompts;
struct EditorContext;

class MatchDialog : public QDialog {
    Q_OBJECT
public:
    // Takes the fitted session; shows its result in the context's preview at once, bakes it into
    // the context's document on OK, and reports errors through its prompts.
    MatchDialog(QWidget* parent, const EditorContext& context,
                std::unique_ptr<MatchSession> session);

    const MatchSession& session() const { return *m_session; }
    // A bake runs or waits (the preview does not show the sliders' values yet).
    bool isBaking() const;
    // Processes events until the sliders' table is baked and shown (tests, scripts).
    void waitForBake();
    MatchBaker* baker() const { return m_baker; }

public slots:
    void accept() override; // the match becomes the document's LUT, one undo step
    void reject() override;

private:
    void apply(); // the sliders' options, asked of the worker
    void showBaked(std::shared_ptr<const Lut3D> table, bool exact); // delivered
    void commit(const Lut3D& table);                                // OK's part once baked

    Document* m_doc;
    PreviewController* m_preview;
    Prompts* m_prompts;
    std::unique_ptr<MatchSession> m_session;
    MatchBaker* m_baker = nullptr;
    bool m_acceptWanted = false; // OK pressed while the sliders' table was baking
    QPushButton* m_ok = nullptr;
    QSlider* addAmount(QFormLayout* form, const QString& label, const char* name);
    void keepAmount(QSlider* slider); // moved on its own: no longer follows Strength

    QSlider* m_strength = nullptr;
    QSlider* m_luma = nullptr;
    QSlider* m_chroma = nullptr;
    bool m_lumaOwn = false, m_chromaOwn = false; // moved on their own
    QCheckBox* m_preserve[3] = {nullptr, nullptr, nullptr};
    QPlainTextEdit* m_report = nullptr;
};

} // namespace lut::gui
