// SPDX-License-Identifier: MIT
#include "status_readout.h"

#include <QLabel>
#include <QStatusBar>

#include <cmath>

namespace ab::ui {

QString formatDuration(double seconds)
{
    if (!std::isfinite(seconds) || seconds <= 0.0)
        return QStringLiteral("-");
    if (seconds < 1e-3)
        return QStringLiteral("%1 \u00b5s").arg(seconds * 1e6, 0, 'g', 3);
    if (seconds < 1.0)
        return QStringLiteral("%1 ms").arg(seconds * 1e3, 0, 'g', 3);
    return QStringLiteral("%1 s").arg(seconds, 0, 'g', 3);
}

StatusReadout::StatusReadout(QStatusBar* bar) : QObject(bar)
{
    auto label = [bar](const char* name, int width) {
        auto* l = new QLabel;
        l->setObjectName(QString::fromLatin1(name));
        l->setMinimumWidth(width);
        bar->addPermanentWidget(l);
        return l;
    };
    warning_ = new QLabel;
    warning_->setObjectName("statusWarning");
    // A long finding is cut at the bar's edge (the tooltip holds it whole) rather than
    // widening the window.
    warning_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    warning_->setMinimumWidth(120);
    bar->addWidget(warning_, 1);
    time_ = label("statusTime", 130);
    step_ = label("statusStep", 120);
    fps_ = label("statusFps", 70);
    energy_ = label("statusEnergy", 190);
    step_->setToolTip(tr("Wall time of one simulation step"));
    fps_->setToolTip(tr("Frames drawn per second by the 3D view"));
    energy_->setToolTip(tr("Kinetic plus potential energy, summed over the balls, with the height measured "
                           "from the floor: per unit mass in the report model, with the masses in the physical one"));
}

void StatusReadout::setUnits(const QString& time, const QString& length)
{
    timeUnit_ = time;
    lengthUnit_ = length;
}

void StatusReadout::show(const EngineStatus& s)
{
    time_->setText(tr("t = %1 %2").arg(QString::number(s.t, 'f', s.t < 100 ? 2 : 1), timeUnit_));
    step_->setText(tr("step %1").arg(formatDuration(s.stepSeconds)));
    const QString sq = QString::fromUtf8("\u00b2");
    const QString value = QString::number(s.energy, 'g', 5);
    if (!s.energyPerUnitMass) // the physical model's masses are in kg
        energy_->setText(std::isfinite(s.energy) ? tr("E = %1 kg %2%3/%4%3").arg(value, lengthUnit_, sq, timeUnit_)
                                                 : tr("E = -"));
    else
        energy_->setText(std::isfinite(s.energy) ? tr("E/m = %1 %2%3/%4%3").arg(value, lengthUnit_, sq, timeUnit_)
                                                 : tr("E/m = -"));
    // The most serious first: a run that stopped, a failure the health check found (the
    // run paused on it), the model's own notice, then a warning of the health check.
    const QString health = QString::fromStdString(s.healthLine);
    QString text, style;
    if (!s.warning.empty()) {
        text = tr("Stopped: %1").arg(QString::fromStdString(s.warning));
        style = "color: #b03020; font-weight: bold;";
    } else if (s.health == diagnostics::Health::Failed) {
        text = s.pausedOnHealth ? tr("Paused: %1").arg(health) : health;
        style = "color: #b03020; font-weight: bold;";
    } else if (!s.notice.empty()) {
        text = QString::fromStdString(s.notice);
        style = "color: #9a6700;";
    } else if (s.health == diagnostics::Health::Warning) {
        text = health;
        style = "color: #9a6700;";
    } else if (s.finished) {
        text = tr("The run is complete; Play starts it again");
    }
    warning_->setText(text);
    warning_->setStyleSheet(style);
    // The line can be longer than the bar: the tooltip holds all of it, and the health
    // check's finding stays readable there when a notice takes the bar.
    QString tip = text;
    if (!health.isEmpty() && !text.contains(health))
        tip += (tip.isEmpty() ? QString() : QStringLiteral("\n")) + health;
    warning_->setToolTip(tip);
}

void StatusReadout::setFrameRate(double fps)
{
    fps_->setText(fps < 0.0 ? tr("no 3D view") : fps == 0.0 ? tr("- fps") : tr("%1 fps").arg(fps, 0, 'f', 0));
}

QString StatusReadout::warningText() const
{
    return warning_->text();
}

QString StatusReadout::timeText() const
{
    return time_->text();
}

} // namespace ab::ui
