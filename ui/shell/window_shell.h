// SPDX-License-Identifier: MIT
// The program's window with what surrounds it: the View menu's lecture mode, themes and
// colour-blind-safe palette, and the Language menu.
//
// A language switch builds the window anew in the new language (every text is set
// where it is built) and goes on with the same run (MainWindow::takeRunOf: every stage's
// setup, the run's time, recording, comparison, speed and selection, the moment looked
// back at, the camera), the window's geometry, lecture mode and the looks.
#pragma once

#include "ui/i18n/language.h"
#include "ui/lecture/lecture_mode.h"
#include "ui/theme/appearance.h"

#include <QObject>

#include <memory>

class QMenu;

namespace ab::ui {

class MainWindow;

class WindowShell : public QObject {
    Q_OBJECT
public:
    explicit WindowShell(QObject* parent = nullptr);
    ~WindowShell() override;

    MainWindow& window() const { return *window_; }
    LectureMode& lecture() { return lecture_; }
    const Appearance& appearance() const { return appearance_; }

public slots:
    void setTheme(ab::ui::Theme theme);
    void setColourBlindSafe(bool on);
    void setLanguage(ab::ui::Language language);

signals:
    void windowReplaced(ab::ui::MainWindow* window);

private:
    void decorate();
    QMenu* buildLanguageMenu();
    void addViewItems(QMenu* view);
    void applyAppearance();
    void recolourBalls();

    std::unique_ptr<MainWindow> window_;
    LectureMode lecture_;
    Appearance appearance_;
};

} // namespace ab::ui
