// SPDX-License-Identifier: MIT
// The report's four stages in order: one button each, the stage's title, where it is in
// the report, a short explanation, its numbered equations and the notes on the report's
// typos and choices, with Previous and Next.
//
// The walk (lecture mode): the stage opens with its equations hidden; each step forward
// reveals the next one, and after the last the next stage opens. A step back hides the
// newest equation, and before the first the previous stage opens with all of its shown,
// so that backward retraces forward exactly.
#pragma once

#include "core/scene.h"

#include <QWidget>

class QButtonGroup;
class QLabel;
class QPushButton;
class QTextBrowser;

namespace ab::ui {

class StageNavigator : public QWidget {
    Q_OBJECT
public:
    explicit StageNavigator(QWidget* parent = nullptr);

    // Shows `scene` without emitting sceneRequested; in the walk, with no equation shown.
    void setCurrent(SceneId scene);
    SceneId current() const { return current_; }
    QString text() const; // the shown description, as plain text

    // The description of a stage as rich text: title, report reference, summary, the
    // first `revealed` equations with their numbers (all when negative), and the notes
    // once every equation is shown. Core texts pass through the translator.
    static QString describe(const SceneInfo& scene, int revealed = -1);

    // A preset's name and explanation in its own words (English for the built-in ones),
    // shown translated above the stage's own text while its stage is shown, so a language
    // chosen later applies to them too; an empty name clears it (the lecturer chose a stage).
    void setPreset(SceneId scene, const QString& name, const QString& description);
    QString presetName() const { return presetName_; }
    QString presetDescription() const { return presetDescription_; }
    // HTML shown after the stage's equations, of the run rather than the stage (the
    // rotation of a physical run, SpinEquations); empty: none.
    void setRunSection(const QString& html);

    void setWalking(bool on);
    bool walking() const { return walking_; }
    int revealed() const; // equations shown
    // In the walk, shows the first `count` equations (clamped to the stage's), as that many
    // steps forward from the start would: the walk goes on where a rebuilt window left it.
    void setRevealed(int count);
    int equationCount() const; // of the current stage

signals:
    void sceneRequested(SceneId scene);

public slots:
    void previous();
    void next();
    // The walk's steps; outside the walk they move by whole stages.
    void stepForward();
    void stepBack();

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void request(int index);
    void retranslate();
    void showText();
    void keepInSight(); // in the walk: the newest equation at the top, or the title

    QButtonGroup* buttons_;
    QTextBrowser* text_;
    QLabel* progress_;
    QPushButton* previous_;
    QPushButton* next_;
    SceneId current_ = SceneId::Bounce1d;
    bool walking_ = false;
    int revealed_ = 0;
    SceneId presetScene_ = SceneId::Bounce1d;
    QString presetName_, presetDescription_;
    QString runSection_;
};

} // namespace ab::ui
