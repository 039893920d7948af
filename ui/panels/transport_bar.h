// SPDX-License-Identifier: MIT
// Play/pause, one step, reset, the speed (0.1x to 10x real time, logarithmic) and a
// time slider over the recorded run: dragging it shows an earlier moment (the 3D view
// and the charts' cursor follow); at its right end the view is live again. Play or Step
// while looking back forks the run there (MainWindow::resumeFromLookedBackMoment).
#pragma once

#include <QWidget>

#include <optional>

class QLabel;
class QPushButton;
class QSlider;

namespace ab::ui {

class TransportBar : public QWidget {
    Q_OBJECT
public:
    explicit TransportBar(QWidget* parent = nullptr);

    void setPlaying(bool playing);
    void setSpeed(double factor);
    // The speed the run keeps while it plays, as a multiple of real time (nothing: unknown, or
    // paused). Below 0.8 of the speed asked the label says so: "1×, plays at 0.3×" (the
    // street's 10,000 balls on a slow machine), or the room takes slow motion for real time.
    void setKeptSpeed(std::optional<double> kept);
    // The recorded run spans [start, end]; `unit` is the scene's time unit.
    void setRecorded(double start, double end, const QString& unit);
    // The moment shown: nothing when live.
    std::optional<double> viewTime() const { return viewTime_; }
    void goLive();
    // Shows the recorded moment `t` (clamped to the record), as a drag of the slider does.
    void lookAt(double t);
    // The time of the recorded state shown for the moment looked at (the kept frame at or
    // before it): the label reads it, as the status bar does, not the slider's position.
    void setShownTime(double t);
    // While looking back: the shown state's time where it is known, else the slider's.
    std::optional<double> shownTime() const { return viewTime_ ? shownTime_.value_or(*viewTime_) : viewTime_; }

    QPushButton* playButton() const { return play_; }
    QPushButton* stepButton() const { return step_; }
    QPushButton* resetButton() const { return reset_; }
    QSlider* speedSlider() const { return speed_; }
    QString speedText() const;
    QSlider* timeSlider() const { return time_; }

    static double speedFromSlider(int value);
    static int sliderFromSpeed(double factor);

signals:
    void playToggled();
    void stepRequested();
    void resetRequested();
    void speedRequested(double factor);
    // The user moved the time slider: a moment to show, or nothing for live.
    void viewTimeChanged(std::optional<double> t);

protected:
    // A style set after the bar was built (the theme's, with its own media icons): the icons
    // are taken from it again.
    void changeEvent(QEvent* event) override;

private:
    void setIcons();
    void scrubbed(int value);
    void fitTimeLabel();
    void updateLabel();

    QPushButton* play_;
    bool playing_ = false;
    QPushButton* step_;
    QPushButton* reset_;
    QSlider* speed_;
    QLabel* speedLabel_;
    QSlider* time_;
    QLabel* timeLabel_;
    double start_ = 0.0, end_ = 0.0;
    QString unit_;
    std::optional<double> viewTime_;
    std::optional<double> shownTime_; // setShownTime, while looking back
    bool updating_ = false;
    double factor_ = 1.0;        // the speed asked (setSpeed)
    std::optional<double> kept_; // the speed kept (setKeptSpeed)
    void showSpeed();
};

} // namespace ab::ui
