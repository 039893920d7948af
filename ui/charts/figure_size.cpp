// SPDX-License-Identifier: MIT
#include "figure_size.h"

#include "core/params.h"

#include <charconv>
#include <cmath>

namespace ab::ui {

namespace {

constexpr double mmPerInch = 25.4;

std::string named(std::string_view what, std::string_view text)
{
    return std::string(what) + ": '" + printableInput(text) + "'";
}

void checkPhysical(const FigureSize& s, std::string_view what)
{
    if (!(s.widthMm > 0.0 && s.heightMm > 0.0))
        throw InputError(named(what, s.name) + " is empty (width and height must be above zero)");
    if (s.widthMm > kMaxMillimetres || s.heightMm > kMaxMillimetres)
        throw InputError(named(what, s.name) + " is larger than 2 m a side");
}

std::optional<double> number(std::string_view text)
{
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
        return std::nullopt;
    return x;
}

} // namespace

FigureSize FigureSize::reportColumn()
{
    return FigureSize{"report-column", 85.0, 64.0, std::nullopt, false};
}

FigureSize FigureSize::reportFull()
{
    return FigureSize{"report-full", 170.0, 105.0, std::nullopt, false};
}

FigureSize FigureSize::slideSize()
{
    FigureSize s{"slide", 0.0, 0.0, QSize(1920, 1080), true};
    s.widthMm = 1920.0 / kSceneDpi * mmPerInch;
    s.heightMm = 1080.0 / kSceneDpi * mmPerInch;
    return s;
}

FigureSize pixelFigureSize(int width, int height, std::string_view what)
{
    const std::string text = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0)
        throw InputError(named(what, text) + " is empty (width and height must be above zero)");
    if (width > kMaxPixels || height > kMaxPixels)
        throw InputError(named(what, text) + " is larger than 20000 px a side");
    FigureSize s{text, width / kSceneDpi * mmPerInch, height / kSceneDpi * mmPerInch, QSize(width, height), false};
    return s;
}

FigureSize parseFigureSize(std::string_view text, std::string_view what)
{
    if (text == "report-column")
        return FigureSize::reportColumn();
    if (text == "report-full")
        return FigureSize::reportFull();
    if (text == "slide")
        return FigureSize::slideSize();
    std::string_view body = text;
    const bool mm = body.size() > 2 && body.substr(body.size() - 2) == "mm";
    if (mm)
        body.remove_suffix(2);
    const std::size_t x = body.find('x');
    const auto w = x == std::string_view::npos ? std::nullopt : number(body.substr(0, x));
    const auto h = x == std::string_view::npos ? std::nullopt : number(body.substr(x + 1));
    if (!w || !h)
        throw InputError(named(what, text) +
                         " is not a size (use report-column, report-full, slide, WxH in pixels or WxHmm)");
    if (mm) {
        FigureSize s{std::string(text), *w, *h, std::nullopt, false};
        checkPhysical(s, what);
        return s;
    }
    if (*w != std::floor(*w) || *h != std::floor(*h))
        throw InputError(named(what, text) + " is not a whole number of pixels");
    if (*w > kMaxPixels || *h > kMaxPixels)
        throw InputError(named(what, text) + " is larger than 20000 px a side");
    FigureSize s = pixelFigureSize(int(*w), int(*h), what);
    s.name = std::string(text);
    return s;
}

void checkDpi(long long dpi, std::string_view what)
{
    if (dpi < kMinDpi || dpi > kMaxDpi)
        throw InputError(std::string(what) + ": " + std::to_string(dpi) + " is outside [50, 2400]");
}

int defaultDpi(const FigureSize& size)
{
    return size.pixels ? int(kSceneDpi) : 300;
}

QSizeF FigureOptions::sceneSize() const
{
    if (size.pixels) // the pixels at the dpi make the physical size the text is set for
        return QSizeF(size.pixels->width() * kSceneDpi / effectiveDpi(),
                      size.pixels->height() * kSceneDpi / effectiveDpi());
    return QSizeF(size.widthMm / mmPerInch * kSceneDpi, size.heightMm / mmPerInch * kSceneDpi);
}

QSizeF FigureOptions::millimetres() const
{
    const QSizeF scene = sceneSize();
    return QSizeF(scene.width() / kSceneDpi * mmPerInch, scene.height() / kSceneDpi * mmPerInch);
}

QSize FigureOptions::pngPixels() const
{
    if (size.pixels)
        return *size.pixels;
    const double w = std::round(size.widthMm / mmPerInch * effectiveDpi());
    const double h = std::round(size.heightMm / mmPerInch * effectiveDpi());
    if (w > kMaxPixels || h > kMaxPixels)
        throw InputError("--dpi: " + std::to_string(effectiveDpi()) + " makes " + size.name + " " +
                         std::to_string(int(w)) + "x" + std::to_string(int(h)) + " px, more than 20000 px a side");
    return QSize(std::max(1, int(w)), std::max(1, int(h)));
}

void checkChartRoom(const FigureOptions& options, std::string_view what)
{
    const QSizeF mm = options.millimetres();
    if (mm.width() >= kChartMinWidthMm && mm.height() >= kChartMinHeightMm)
        return;
    // Whole millimetres and pixels; a tenth below 10 ("0.2" for a pixel's size).
    const auto whole = [](double x) { return formatNumber(x >= 10.0 ? std::round(x) : std::round(10.0 * x) / 10.0); };
    std::string at = options.size.name;
    if (options.size.pixels) // the pixels at the dpi make the physical size
        at += " at " + std::to_string(options.effectiveDpi()) + " dpi (" + whole(mm.width()) + "x" +
              whole(mm.height()) + "mm)";
    throw InputError(std::string(what) + ": " + at + " is too small for a chart, its text at 8 pt (at least " +
                     whole(kChartMinWidthMm) + "x" + whole(kChartMinHeightMm) + "mm, " +
                     whole(kChartMinWidthMm / mmPerInch * options.effectiveDpi()) + "x" +
                     whole(kChartMinHeightMm / mmPerInch * options.effectiveDpi()) + " px at " +
                     std::to_string(options.effectiveDpi()) + " dpi)");
}

} // namespace ab::ui
