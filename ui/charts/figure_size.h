// SPDX-License-Identifier: MIT
// Where a figure goes, and so how large it is: a column of a report (85 mm wide), the
// full text width (170 mm), a 16:9 slide (1920 x 1080 px) or a custom size in pixels
// ("1200x800") or millimetres ("120x80mm"). Figures are laid out in scene units of
// 1/144 inch, so that text and lines set in points come out at that size in print;
// PNG takes a dpi (300 by default for print, 144 for pixel sizes: a slide is then
// 13.33 x 7.5 inches, as presentation programs make it).
#pragma once

#include <QSize>
#include <QSizeF>

#include <optional>
#include <string>
#include <string_view>

namespace ab::ui {

struct FigureSize {
    std::string name;     // "report-column", "report-full", "slide", or the text given
    double widthMm = 0.0; // the physical size
    double heightMm = 0.0;
    std::optional<QSize> pixels; // set for pixel sizes: the PNG's size, whatever the dpi
    bool slide = false;          // lecture-sized text

    static FigureSize reportColumn(); // 85 x 64 mm
    static FigureSize reportFull();   // 170 x 105 mm
    static FigureSize slideSize();    // 1920 x 1080 px
};

inline constexpr double kSceneDpi = 144.0;
inline constexpr int kMaxPixels = 20000;
inline constexpr double kMaxMillimetres = 2000.0;
inline constexpr int kMinDpi = 50, kMaxDpi = 2400;

// A preset's name or WxH (pixels) or WxHmm; throws InputError naming `what` (e.g.
// "--size") and the text when it is neither, zero, or larger than 20,000 px or 2 m.
FigureSize parseFigureSize(std::string_view text, std::string_view what = "--size");
// A size in pixels (the older --width/--height), checked as parseFigureSize does.
FigureSize pixelFigureSize(int width, int height, std::string_view what = "--size");
// Throws InputError unless 50 <= dpi <= 2400.
void checkDpi(long long dpi, std::string_view what = "--dpi");
int defaultDpi(const FigureSize& size);

struct FigureOptions {
    FigureSize size = FigureSize::reportColumn();
    std::optional<int> dpi; // PNG only; unset: defaultDpi(size)
    int effectiveDpi() const { return dpi ? *dpi : defaultDpi(size); }
    // The layout's size, in scene units of 1/144 inch (a pixel size at its dpi).
    QSizeF sceneSize() const;
    // The physical size in millimetres (a pixel size at its dpi): SVG's and PDF's.
    QSizeF millimetres() const;
    // The PNG's pixels: a pixel size as given, a physical one at the dpi. Throws
    // InputError when it would exceed 20,000 px a side.
    QSize pngPixels() const;
};

// A chart's text is set at 8 pt for its physical size (FigureOptions::millimetres): below
// 70 x 50 mm its axis title is cut (60 x 45 mm cut "position (unit)"; "1x1" px was a blank
// image). Throws InputError naming `what` and the size where it is smaller.
inline constexpr double kChartMinWidthMm = 70.0, kChartMinHeightMm = 50.0;
void checkChartRoom(const FigureOptions& options, std::string_view what = "--size");

} // namespace ab::ui
