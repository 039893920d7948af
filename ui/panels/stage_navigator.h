// SPDX-License-Identifier: MIT
// The report's four stages in order: one button each, the stage's title, where it is in
// the report, a short explanation, its numbered equations and the notes on the report's
// typos and choices, with Previous and Next.
#pragma once

#include "core/scene.h"

#include <QWidget>

class QButtonGroup;
class QPushButton;
class QTextBrowser;

namespace ab::ui {

class StageNavigator : public QWidget {
    Q_OBJECT
public:
    explicit StageNavigator(QWidget* parent = nullptr);

    // Shows `scene` without emitting sceneRequested.
    void setCurrent(SceneId scene);
    SceneId current() const { return current_; }
    QString text() const; // the shown description, as plain text

    // The description of a stage as rich text: title, report reference, summary,
    // equations with their numbers, notes.
    static QString describe(const SceneInfo& scene);

signals:
    void sceneRequested(SceneId scene);

public slots:
    void previous();
    void next();

private:
    void request(int index);

    QButtonGroup* buttons_;
    QTextBrowser* text_;
    QPushButton* previous_;
    QPushButton* next_;
    SceneId current_ = SceneId::Bounce1d;
};

} // namespace ab::ui
