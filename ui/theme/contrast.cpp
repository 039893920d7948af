// SPDX-License-Identifier: MIT
#include "contrast.h"

#include <algorithm>
#include <cmath>

namespace ab::ui {

double relativeLuminance(const QColor& c)
{
    // WCAG 2.1, "relative luminance": the sRGB channels linearised, weighted by the eye's
    // sensitivity (www.w3.org/TR/WCAG21/#dfn-relative-luminance).
    auto linear = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * linear(c.redF()) + 0.7152 * linear(c.greenF()) + 0.0722 * linear(c.blueF());
}

double contrastRatio(const QColor& a, const QColor& b)
{
    // WCAG 2.1 contrast ratio (L1 + 0.05) / (L2 + 0.05), L1 the lighter.
    const double la = relativeLuminance(a), lb = relativeLuminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QColor withContrast(const QColor& colour, const QColor& background, double ratio)
{
    // Lighter on a dark background, darker on a light one, in small steps of HSL
    // lightness (the hue stays), until the ratio holds; black or white at the end.
    const bool dark = relativeLuminance(background) < 0.18;
    QColor c = colour;
    for (int i = 0; i < 100 && contrastRatio(c, background) < ratio; ++i) {
        float h, s, l, a;
        c.getHslF(&h, &s, &l, &a);
        l = dark ? std::min(1.0f, l + 0.02f) : std::max(0.0f, l - 0.02f);
        c = QColor::fromHslF(h, s, l, a);
    }
    return c;
}

} // namespace ab::ui
