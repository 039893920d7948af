// SPDX-License-Identifier: MIT
#include "window_shell.h"

#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/view/ball_view.h"

#include <QActionGroup>
#include <QMenuBar>
#include <QTabBar>

namespace ab::ui {

namespace {

QMenu* menuNamed(QMainWindow& window, const char* name)
{
    return window.menuBar()->findChild<QMenu*>(QString::fromLatin1(name), Qt::FindDirectChildrenOnly);
}

} // namespace

WindowShell::WindowShell(QObject* parent) : QObject(parent), window_(std::make_unique<MainWindow>())
{
    connect(&lecture_, &LectureMode::activeChanged, this, [this](bool on) {
        appearance_.scale = on ? LectureMode::scale : 1.0;
        applyAppearance();
    });
    decorate();
}

WindowShell::~WindowShell() = default;

void WindowShell::decorate()
{
    MainWindow& w = *window_;
    if (QMenu* view = menuNamed(w, "viewMenu"))
        addViewItems(view);
    QMenu* language = buildLanguageMenu();
    QMenu* help = menuNamed(w, "helpMenu");
    w.menuBar()->insertMenu(help ? help->menuAction() : nullptr, language);
    lecture_.attach(&w, w.navigator());
    w.setLectureKeys(lecture_.active());
    connect(&lecture_, &LectureMode::activeChanged, &w, &MainWindow::setLectureKeys);
    // After the window's own handler (connected first), which sets the run's colours.
    connect(&w.controller(), &RunController::runReplaced, this, &WindowShell::recolourBalls);
    applyAppearance();
}

void WindowShell::addViewItems(QMenu* view)
{
    view->addSeparator();
    QAction* lecture =
        view->addAction(tr("Lecture mode"), QKeySequence(tr("Ctrl+L")), &lecture_, &LectureMode::setActive);
    lecture->setObjectName("lectureModeAction");
    lecture->setCheckable(true);
    lecture->setChecked(lecture_.active());
    connect(&lecture_, &LectureMode::activeChanged, lecture, &QAction::setChecked);
    QAction* full = view->addAction(tr("Full screen"), &lecture_, &LectureMode::setFullScreen);
    full->setObjectName("fullScreenAction");
    full->setShortcut(QKeySequence(Qt::Key_F11)); // taken by the lecture filter; shown here
    full->setCheckable(true);
    full->setChecked(window_->isFullScreen());
    connect(&lecture_, &LectureMode::fullScreenChanged, full, &QAction::setChecked);

    QMenu* themes = view->addMenu(tr("Theme"));
    themes->setObjectName("themeMenu");
    auto* group = new QActionGroup(themes);
    for (Theme theme : allThemes()) {
        QAction* a = themes->addAction(themeTitle(theme), this, [this, theme] { setTheme(theme); });
        a->setObjectName("theme-" + themeKey(theme));
        a->setCheckable(true);
        a->setChecked(theme == appearance_.theme);
        group->addAction(a);
    }
    QAction* safe = view->addAction(tr("Colour-blind-safe palette"), this, &WindowShell::setColourBlindSafe);
    safe->setObjectName("colourBlindSafeAction");
    safe->setCheckable(true);
    safe->setChecked(appearance_.colourBlindSafe);
}

QMenu* WindowShell::buildLanguageMenu()
{
    auto* menu = new QMenu(tr("&Language"), window_->menuBar());
    menu->setObjectName("languageMenu");
    auto* group = new QActionGroup(menu);
    for (Language language : allLanguages()) {
        QAction* a = menu->addAction(nativeName(language));
        a->setObjectName("language-" + languageCode(language));
        a->setCheckable(true);
        a->setChecked(language == installedLanguage());
        group->addAction(a);
        // Queued: the menu that sent this is part of the window being replaced.
        connect(
            a, &QAction::triggered, this, [this, language] { setLanguage(language); }, Qt::QueuedConnection);
    }
    return menu;
}

void WindowShell::setTheme(Theme theme)
{
    appearance_.theme = theme;
    if (auto* a = window_->findChild<QAction*>("theme-" + themeKey(theme)))
        a->setChecked(true);
    applyAppearance();
}

void WindowShell::setColourBlindSafe(bool on)
{
    appearance_.colourBlindSafe = on;
    if (auto* a = window_->findChild<QAction*>("colourBlindSafeAction"))
        a->setChecked(on);
    applyAppearance();
}

void WindowShell::applyAppearance()
{
    applyToApplication(appearance_);
    applyToCharts(window_.get(), appearance_);
    if (BallView* view = window_->view()) {
        view->setBackground(surfaceColours(appearance_.theme).background);
        view->setPresentationScale(appearance_.scale);
    }
    recolourBalls();
}

void WindowShell::recolourBalls()
{
    BallView* view = window_->view();
    if (!view || !window_->controller().hasRun())
        return;
    const int balls = window_->controller().layout().balls;
    view->setColours(appearance_.colourBlindSafe ? okabeItoBallColours(balls, appearance_.theme)
                                                 : ballColours(window_->controller().spec(), balls));
}

void WindowShell::setLanguage(Language language)
{
    if (language == installedLanguage())
        return;
    installLanguage(language);
    std::unique_ptr<MainWindow> old = std::move(window_);
    window_ = std::make_unique<MainWindow>();
    MainWindow& w = *window_;
    w.takeRunOf(*old); // the run goes on: its time, recording, selection, camera and comparison
    w.setGeometry(old->geometry());
    const bool full = old->isFullScreen(), visible = old->isVisible();
    // The lecture's place: the equations shown so far and the page of charts.
    const int revealed = old->navigator()->revealed(), page = old->charts()->pages()->currentIndex();
    old->hide();
    old.reset();
    decorate();
    w.navigator()->setRevealed(revealed);
    if (full)
        w.showFullScreen();
    else if (visible)
        w.show();
    if (page >= 0 && page < w.charts()->pages()->count())
        w.charts()->pages()->setCurrentIndex(page);
    emit windowReplaced(&w);
}

} // namespace ab::ui
