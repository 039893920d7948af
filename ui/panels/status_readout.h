// SPDX-License-Identifier: MIT
// The status bar's readings: simulated time, the cost of one step, frames per second,
// the energy, and any warning from the run (a stopped run or a failed health check in
// red, a notice from the model such as the report's bounce limit or a health warning in
// amber).
#pragma once

#include "ui/sim/run_engine.h"

#include <QObject>
#include <QString>

class QLabel;
class QStatusBar;

namespace ab::ui {

class StatusReadout : public QObject {
    Q_OBJECT
public:
    explicit StatusReadout(QStatusBar* bar);

    void setUnits(const QString& time, const QString& length);
    void show(const EngineStatus& status);
    void setFrameRate(double fps); // negative: no 3D view
    QString warningText() const;
    QString timeText() const;

private:
    QLabel* time_;
    QLabel* step_;
    QLabel* fps_;
    QLabel* energy_;
    QLabel* warning_;
    QString timeUnit_, lengthUnit_;
};

// "0.8 us", "12 ms", "1.3 s".
QString formatDuration(double seconds);

} // namespace ab::ui
