// SPDX-License-Identifier: MIT
#include "work_precision_chart.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ab::ui {

namespace {

QColor colourOf(Integrator i)
{
    switch (i) {
    case Integrator::Euler:
        return QColor(0xd6, 0x27, 0x28);
    case Integrator::SymplecticEuler:
        return QColor(0xff, 0x7f, 0x0e);
    case Integrator::Verlet:
        return QColor(0x2c, 0xa0, 0x2c);
    case Integrator::Rk4:
        return QColor(0x1f, 0x77, 0xb4);
    case Integrator::Event:
        return QColor(0x11, 0x11, 0x11);
    case Integrator::ImplicitEuler:
    case Integrator::ImplicitMidpoint:
        break;
    }
    return QColor(0x7f, 0x7f, 0x7f);
}

QLogValueAxis* logAxis(const QString& title, double lo, double hi)
{
    auto* axis = new QLogValueAxis;
    axis->setTitleText(title);
    axis->setBase(10.0);
    axis->setLabelFormat("%g");
    axis->setMinorTickCount(-1);
    // Whole decades around the data, so the ticks fall on powers of ten.
    axis->setRange(std::pow(10.0, std::floor(std::log10(lo))), std::pow(10.0, std::ceil(std::log10(hi))));
    return axis;
}

} // namespace

std::unique_ptr<QChart> makeWorkPrecisionChart(const study::Result& result)
{
    auto chart = std::make_unique<QChart>();
    chart->setTitle(QString::fromStdString("Work-precision: " + result.scene + " (physical model), t = 0 to " +
                                           formatNumber(result.tEnd) + " " + result.timeUnit));
    chart->legend()->setAlignment(Qt::AlignRight);
    chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries); // dashed step-end lines stay dashed

    std::vector<study::Method> methods;
    for (const study::Row& row : result.rows)
        if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
            methods.push_back(row.method);

    double xLo = std::numeric_limits<double>::infinity(), xHi = 0.0, yLo = xLo, yHi = 0.0;
    std::vector<QLineSeries*> lines;
    for (const study::Method& m : methods) {
        QList<QPointF> points;
        for (const study::Row& row : result.rows) {
            // Log axes cannot show zero (an exact result) or a value that is not finite.
            if (!(row.method == m) || !(row.relativeError > 0.0) || !(row.cpuSeconds > 0.0) ||
                !std::isfinite(row.relativeError))
                continue;
            points.append(QPointF(row.cpuSeconds, row.relativeError));
            xLo = std::min(xLo, row.cpuSeconds);
            xHi = std::max(xHi, row.cpuSeconds);
            yLo = std::min(yLo, row.relativeError);
            yHi = std::max(yHi, row.relativeError);
        }
        if (points.isEmpty())
            continue;
        auto* line = new QLineSeries;
        line->setName(QString::fromStdString(m.label()));
        QPen pen(colourOf(m.integrator));
        pen.setWidthF(m.exact() ? 2.5 : 2.0);
        if (m.impacts == ImpactMode::StepEnd && !m.exact())
            pen.setStyle(Qt::DashLine);
        line->setPen(pen);
        line->setPointsVisible(true);
        line->replace(points); // one call: append() per point is quadratic in Qt 6.4
        chart->addSeries(line);
        lines.push_back(line);
    }
    if (lines.empty())
        return chart;
    auto* x = logAxis("CPU time per run (s)", xLo, xHi);
    auto* y = logAxis(QString::fromStdString("largest position error / " + formatNumber(result.lengthScale) + " " +
                                             result.lengthUnit),
                      yLo, yHi);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QLineSeries* line : lines) {
        line->attachAxis(x);
        line->attachAxis(y);
    }
    return chart;
}

} // namespace ab::ui
