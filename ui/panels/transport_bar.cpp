// SPDX-License-Identifier: MIT
#include "transport_bar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

constexpr int timeSteps = 2000; // slider positions over the recorded run

} // namespace

// The speed slider runs over -100..100: 10^(value/100), 0.1x to 10x.
double TransportBar::speedFromSlider(int value)
{
    return std::pow(10.0, value / 100.0);
}
int TransportBar::sliderFromSpeed(double factor)
{
    return int(std::lround(100.0 * std::log10(factor)));
}

TransportBar::TransportBar(QWidget* parent) : QWidget(parent)
{
    setObjectName("transportBar");
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    play_ = new QPushButton;
    play_->setObjectName("playButton");
    step_ = new QPushButton(tr("Step"));
    step_->setObjectName("stepButton");
    step_->setToolTip(tr("One step (Right arrow)"));
    reset_ = new QPushButton(tr("Reset"));
    reset_->setObjectName("resetButton");
    reset_->setToolTip(tr("Back to the start (R)"));
    for (QPushButton* b : {play_, step_, reset_}) {
        b->setFocusPolicy(Qt::NoFocus);
        row->addWidget(b);
    }
    row->addSpacing(12);
    row->addWidget(new QLabel(tr("Speed")));
    speed_ = new QSlider(Qt::Horizontal);
    speed_->setObjectName("speedSlider");
    speed_->setRange(-100, 100);
    speed_->setFixedWidth(130);
    speed_->setFocusPolicy(Qt::NoFocus);
    speed_->setToolTip(tr("Simulated time per real second: 0.1x to 10x real time"));
    row->addWidget(speed_);
    speedLabel_ = new QLabel;
    speedLabel_->setObjectName("speedLabel");
    speedLabel_->setMinimumWidth(44);
    row->addWidget(speedLabel_);
    row->addSpacing(12);
    time_ = new QSlider(Qt::Horizontal);
    time_->setObjectName("timeSlider");
    time_->setRange(0, timeSteps);
    time_->setFocusPolicy(Qt::NoFocus);
    time_->setToolTip(tr("Drag to look back through the recorded run; the right end is live. Play or Step "
                         "there goes on from the moment shown: the run forks, and what came after is dropped"));
    row->addWidget(time_, 1);
    timeLabel_ = new QLabel;
    timeLabel_->setObjectName("timeLabel");
    row->addWidget(timeLabel_);

    connect(play_, &QPushButton::clicked, this, &TransportBar::playToggled);
    connect(step_, &QPushButton::clicked, this, &TransportBar::stepRequested);
    connect(reset_, &QPushButton::clicked, this, &TransportBar::resetRequested);
    connect(speed_, &QSlider::valueChanged, this, [this](int v) {
        if (!updating_)
            emit speedRequested(speedFromSlider(v));
    });
    connect(time_, &QSlider::valueChanged, this, &TransportBar::scrubbed);
    // While the slider is held, its length must not change under the pointer: the label keeps
    // its width and reads the short form; the whole form, and its room, come on release.
    connect(time_, &QSlider::sliderPressed, this, [this] { timeLabel_->setFixedWidth(timeLabel_->width()); });
    connect(time_, &QSlider::sliderReleased, this, [this] {
        timeLabel_->setMaximumWidth(QWIDGETSIZE_MAX);
        fitTimeLabel();
        updateLabel();
    });
    setPlaying(false);
    setSpeed(1.0);
    setRecorded(0.0, 0.0, QString());
    fitTimeLabel();
}

void TransportBar::setIcons()
{
    play_->setIcon(style()->standardIcon(playing_ ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    step_->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    reset_->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
}

void TransportBar::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    // The bar is built before the theme's style is set on the application: Fusion's icons,
    // dark grey, stayed on Step and Reset (and Play until the first press) on a black theme.
    if (event->type() == QEvent::StyleChange)
        setIcons();
    if (event->type() == QEvent::FontChange) // lecture mode's text: the time label's room with it
        fitTimeLabel();
}

void TransportBar::setPlaying(bool playing)
{
    playing_ = playing;
    setIcons();
    play_->setText(playing ? tr("Pause") : tr("Play"));
    play_->setToolTip(tr("Play or pause (Space)"));
}

void TransportBar::setSpeed(double factor)
{
    updating_ = true;
    speed_->setValue(sliderFromSpeed(factor));
    updating_ = false;
    factor_ = factor;
    showSpeed();
}

void TransportBar::setKeptSpeed(std::optional<double> kept)
{
    if (kept == kept_)
        return;
    kept_ = kept;
    showSpeed();
}

void TransportBar::showSpeed()
{
    // In words, so the room knows what it is watching: "10× real time", or what the machine
    // keeps of it.
    if (kept_ && *kept_ < 0.8 * factor_) {
        speedLabel_->setText(tr("%1×, plays at %2×").arg(factor_, 0, 'g', 2).arg(*kept_, 0, 'g', 1));
        speedLabel_->setToolTip(tr("The run's steps take longer to compute than the time they show: it plays at "
                                   "%1× real time, in slow motion")
                                    .arg(*kept_, 0, 'g', 2));
    } else {
        speedLabel_->setText(tr("%1× real time").arg(factor_, 0, 'g', 2));
        speedLabel_->setToolTip({});
    }
}

QString TransportBar::speedText() const
{
    return speedLabel_->text();
}

void TransportBar::setRecorded(double start, double end, const QString& unit)
{
    start_ = start;
    end_ = std::max(end, start);
    if (unit != unit_) {
        unit_ = unit;
        fitTimeLabel();
    }
    if (!viewTime_) {
        updating_ = true;
        time_->setValue(timeSteps);
        updating_ = false;
    } else if (*viewTime_ > end_) {
        viewTime_ = end_;
    }
    time_->setEnabled(end_ > start_);
    updateLabel();
}

void TransportBar::goLive()
{
    if (!viewTime_)
        return;
    viewTime_.reset();
    shownTime_.reset();
    updating_ = true;
    time_->setValue(timeSteps);
    updating_ = false;
    updateLabel();
    emit viewTimeChanged(viewTime_);
}

void TransportBar::lookAt(double t)
{
    if (!(end_ > start_))
        return;
    viewTime_ = std::clamp(t, start_, end_);
    shownTime_.reset();
    updating_ = true;
    time_->setValue(int(std::lround((*viewTime_ - start_) / (end_ - start_) * timeSteps)));
    updating_ = false;
    updateLabel();
    emit viewTimeChanged(viewTime_);
}

void TransportBar::scrubbed(int value)
{
    if (updating_)
        return;
    if (value >= timeSteps)
        viewTime_.reset();
    else
        viewTime_ = start_ + (end_ - start_) * value / timeSteps;
    shownTime_.reset();
    updateLabel();
    emit viewTimeChanged(viewTime_);
}

void TransportBar::setShownTime(double t)
{
    if (!viewTime_ || shownTime_ == t)
        return;
    shownTime_ = t;
    updateLabel();
}

void TransportBar::fitTimeLabel()
{
    // Room for the live time up to 9999.99 from the start: as the digits grow while playing
    // the label, and the speed slider beside it, stay put (they moved by a digit's width). It
    // depends on the font and the unit only; while the slider is held the width stays fixed.
    if (time_->isSliderDown())
        return;
    const QString widest = tr("t = %1 %2 (live)").arg(QStringLiteral("0000.00"), unit_);
    timeLabel_->setMinimumWidth(std::max(200, timeLabel_->fontMetrics().horizontalAdvance(widest) + 4));
}

void TransportBar::updateLabel()
{
    const auto fmt = [](double t) { return QString::number(t, 'f', t < 100 ? 2 : 1); };
    if (viewTime_ && time_->isSliderDown())
        timeLabel_->setText(tr("t = %1 of %2 %3").arg(fmt(shownTime_.value_or(*viewTime_)), fmt(end_), unit_));
    else if (viewTime_)
        timeLabel_->setText(tr("t = %1 of %2 %3 (looking back: Play goes on from here)")
                                .arg(fmt(shownTime_.value_or(*viewTime_)), fmt(end_), unit_));
    else
        timeLabel_->setText(tr("t = %1 %2 (live)").arg(fmt(end_), unit_));
}

} // namespace ab::ui
