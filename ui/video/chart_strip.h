// SPDX-License-Identifier: MIT
// The charts beside the 3D view in a clip: the window's charts (ui/charts/motion_chart.h), as
// many as fit one above the other (each at least 220 pixels tall, or drawn that tall and
// scaled down), of the whole clip, drawn once; each frame adds only the time cursor at its
// moment, in the chart's own cursor pen, so a long clip does not redraw Qt Charts 1,800
// times. Must live on the GUI thread (Qt Charts are graphics items).
#pragma once

#include "ui/charts/motion_chart.h"

#include "core/simulation.h"

#include <QImage>
#include <QPen>
#include <QRect>

#include <vector>

class QPainter;

namespace ab::ui {

// The charts the window shows for the scene (every one that applies), in its order.
std::vector<ChartKind> chartsFor(const RunSpec& spec);

class ChartStrip {
public:
    // The first of `kinds` that fit, stacked top to bottom in `size`, drawn from `track` of ball `ball` of the
    // run `sim`, the time axis spanning [0, tEnd].
    ChartStrip(const Simulation& sim, int ball, const std::vector<ChartKind>& kinds, const MotionTrack& track,
               double tEnd, QSize size);

    // The charts at `origin`, each with its cursor at time t.
    void paint(QPainter& p, QPoint origin, double t) const;

private:
    struct Panel {
        QImage image;
        QRect rect;            // within the strip
        double t0 = 0, x0 = 0; // the time axis: pixel x0 at time t0,
        double t1 = 1, x1 = 1; // x1 at t1 (linear)
        double top = 0, bottom = 0;
        QPen pen;
    };
    static constexpr int kMinHeight = 220; // pixels a chart takes at the least, for the window's fonts
    // `need`: the height at which the chart reads whole; a smaller slot scales it down.
    static Panel drawPanel(const Simulation& sim, int ball, ChartKind kind, const MotionTrack& track, double tEnd,
                           QRect rect, int need);

    std::vector<Panel> panels_;
};

} // namespace ab::ui
