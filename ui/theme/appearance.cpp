// SPDX-License-Identifier: MIT
#include "appearance.h"

#include "theme_style.h"

#include "ui/charts/chart_style.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QXYSeries>

namespace ab::ui {

namespace {

// The value a property had the first time it was styled, kept on the object.
template <typename T, typename Get> T base(QObject* object, const char* name, Get current)
{
    QVariant stored = object->property(name);
    if (!stored.isValid()) {
        stored = QVariant::fromValue(current());
        object->setProperty(name, stored);
    }
    return stored.value<T>();
}

QFont scaled(QFont font, double scale)
{
    if (font.pointSizeF() > 0)
        font.setPointSizeF(font.pointSizeF() * scale);
    else
        font.setPixelSize(int(font.pixelSize() * scale + 0.5));
    return font;
}

void styleSeries(QXYSeries* series, const Appearance& a, const QColor& plotArea)
{
    QPen pen = base<QPen>(series, "ab_basePen", [series] { return series->pen(); });
    const bool projector = isHighContrast(a.theme);
    pen.setWidthF(pen.widthF() * a.scale * (projector ? 1.5 : 1.0)); // as the axis lines
    QColor colour = pen.color();
    const QVariant shadows = series->property(comparisonOfProperty);
    if (shadows.isValid() && isDark(a.theme))
        colour = comparisonOnDark(shadows.value<QColor>());
    if (a.colourBlindSafe)
        colour = colourBlindSafe(colour);
    if (colour.hsvSaturationF() < 0.2f) // the grey time cursor follows the text colour
        colour = surfaceColours(a.theme).text;
    else if (isDark(a.theme) && colour.lightnessF() < 0.45f)
        colour = colour.lighter(150); // dark blues and purples vanish on a dark background
    // Every line 3:1 against the plot (WCAG 1.4.11): orange and light green on white,
    // red and purple on the dark plot, would be below it. A high-contrast theme's lines, for a
    // projector, ask text's 4.5:1: the total energy's purple (3.6:1) and the rotation's red
    // (3.9:1) sank into the black plot as thin lines.
    pen.setColor(withContrast(colour, plotArea, projector ? 4.5 : 3.0));
    series->setPen(pen);
}

void styleAxis(QAbstractAxis* axis, const Appearance& a, const SurfaceColours& c)
{
    const double f = chartFontScale(a);
    axis->setLabelsFont(scaled(base<QFont>(axis, "ab_baseLabelsFont", [axis] { return axis->labelsFont(); }), f));
    axis->setTitleFont(scaled(base<QFont>(axis, "ab_baseTitleFont", [axis] { return axis->titleFont(); }), f));
    axis->setLabelsColor(c.text);
    axis->setTitleBrush(c.text);
    axis->setGridLineColor(c.grid);
    axis->setMinorGridLineColor(c.grid);
    QPen line(c.axisLine, a.scale * (isHighContrast(a.theme) ? 1.5 : 1.0));
    axis->setLinePen(line);
}

} // namespace

double chartFontScale(const Appearance& a)
{
    return 1.0 + 0.6 * (a.scale - 1.0);
}

void applyToApplication(const Appearance& a)
{
    auto* app = qobject_cast<QApplication*>(QCoreApplication::instance());
    if (!app)
        return;
    const QFont font = base<QFont>(app, "ab_baseFont", [] { return QApplication::font(); });
    auto* style = qobject_cast<ThemeStyle*>(QApplication::style());
    if (!style) {
        style = new ThemeStyle; // the application owns it
        QApplication::setStyle(style);
    }
    style->setFieldBorder(fieldBorder(a.theme));
    QApplication::setPalette(themePalette(a.theme));
    QApplication::setFont(scaled(font, a.scale));
}

void applyToChart(QChart* chart, const Appearance& a)
{
    const SurfaceColours c = surfaceColours(a.theme);
    chart->setBackgroundBrush(c.background);
    chart->setBackgroundPen(Qt::NoPen);
    chart->setPlotAreaBackgroundBrush(c.plotArea);
    chart->setPlotAreaBackgroundVisible(true);
    chart->setTitleBrush(c.text);
    const double f = chartFontScale(a);
    chart->setTitleFont(scaled(base<QFont>(chart, "ab_baseTitleFont", [chart] { return chart->titleFont(); }), f));
    QLegend* legend = chart->legend();
    legend->setFont(scaled(base<QFont>(legend, "ab_baseFont", [legend] { return legend->font(); }), f));
    legend->setLabelColor(c.text);
    for (QAbstractAxis* axis : chart->axes())
        styleAxis(axis, a, c);
    for (QAbstractSeries* series : chart->series())
        if (auto* xy = qobject_cast<QXYSeries*>(series))
            styleSeries(xy, a, c.plotArea);
}

void applyToCharts(QWidget* root, const Appearance& a)
{
    for (QChartView* view : root->findChildren<QChartView*>()) {
        view->setBackgroundBrush(surfaceColours(a.theme).background);
        if (view->chart())
            applyToChart(view->chart(), a);
    }
}

} // namespace ab::ui
