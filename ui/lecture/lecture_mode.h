// SPDX-License-Identifier: MIT
// Lecture mode: full screen, fonts and chart lines enlarged to read from the back of a
// hall, and the stage navigator's walk driven by the keys a presenter's clicker sends.
// While it is on, an application-wide event filter takes these keys before any shortcut
// of the window sees them:
//   Space, Right, PageDown: next (the next equation, then the next stage)
//   Left, PageUp:           previous
//   F11: full screen on / off; Esc: leave full screen.
// Space, Left and Right stay with a text field that has the focus (typing a value).
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>

class QKeyEvent;
class QMainWindow;
class QSplitter;

namespace ab::ui {

class StageNavigator;

class LectureMode : public QObject {
    Q_OBJECT
public:
    // Fonts and chart lines in lecture mode, relative to the desktop's.
    static constexpr double scale = 1.75;

    explicit LectureMode(QObject* parent = nullptr);
    ~LectureMode() override;

    // The window and navigator it drives; a rebuilt window is attached again.
    void attach(QMainWindow* window, StageNavigator* navigator);
    bool active() const { return active_; }

public slots:
    void setActive(bool on);
    void next();
    void previous();
    void setFullScreen(bool on);

signals:
    void activeChanged(bool on);
    void fullScreenChanged(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class Command { None, Next, Previous, FullScreen, LeaveFullScreen };
    Command commandFor(const QKeyEvent& key) const;
    void arrangePanels(bool lecture);
    void applyShares();
    QSplitter* columnSplitter() const;
    QSplitter* leftSplitter() const;

    QPointer<QMainWindow> window_;
    QPointer<StageNavigator> navigator_;
    bool active_ = false;
    QList<int> desktopColumns_, desktopLeft_; // the splitters' sizes before lecture mode
};

} // namespace ab::ui
