// SPDX-License-Identifier: MIT
#include "theme.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ab::ui {

namespace {

QPalette makePalette(const QColor& window, const QColor& base, const QColor& alternate, const QColor& text,
                     const QColor& button, const QColor& highlight, const QColor& highlightedText,
                     const QColor& disabledText, const QColor& link)
{
    QPalette p;
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, alternate);
    p.setColor(QPalette::ToolTipBase, base);
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, disabledText);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, button);
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, highlight);
    p.setColor(QPalette::Highlight, highlight);
    p.setColor(QPalette::HighlightedText, highlightedText);
    p.setColor(QPalette::Link, link);
    p.setColor(QPalette::LinkVisited, link);
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabledText);
    return p;
}

} // namespace

const std::vector<Theme>& allThemes()
{
    static const std::vector<Theme> all{Theme::Light, Theme::Dark, Theme::HighContrastLight, Theme::HighContrastDark};
    return all;
}

QString themeTitle(Theme theme)
{
    switch (theme) {
    case Theme::Light:
        return QCoreApplication::translate("Theme", "Light");
    case Theme::Dark:
        return QCoreApplication::translate("Theme", "Dark");
    case Theme::HighContrastLight:
        return QCoreApplication::translate("Theme", "High contrast light");
    case Theme::HighContrastDark:
        return QCoreApplication::translate("Theme", "High contrast dark");
    }
    throw std::logic_error("theme without a title");
}

QString themeKey(Theme theme)
{
    switch (theme) {
    case Theme::Light:
        return QStringLiteral("light");
    case Theme::Dark:
        return QStringLiteral("dark");
    case Theme::HighContrastLight:
        return QStringLiteral("high-contrast-light");
    case Theme::HighContrastDark:
        return QStringLiteral("high-contrast-dark");
    }
    throw std::logic_error("theme without a key");
}

std::optional<Theme> parseTheme(const QString& key)
{
    for (Theme t : allThemes())
        if (themeKey(t) == key)
            return t;
    return std::nullopt;
}

bool isDark(Theme theme)
{
    return theme == Theme::Dark || theme == Theme::HighContrastDark;
}

bool isHighContrast(Theme theme)
{
    return theme == Theme::HighContrastLight || theme == Theme::HighContrastDark;
}

QPalette themePalette(Theme theme)
{
    switch (theme) {
    case Theme::Light:
        // Greyed-out text 4.6:1 on the window, white on the highlight 5.4:1 (WCAG AA, 4.5:1).
        return makePalette(QColor(0xef, 0xef, 0xef), Qt::white, QColor(0xf5, 0xf5, 0xf5), Qt::black,
                           QColor(0xef, 0xef, 0xef), QColor(0x1f, 0x6f, 0xa8), Qt::white, QColor(0x6b, 0x6b, 0x6b),
                           QColor(0x00, 0x55, 0xaa));
    case Theme::Dark:
        // Greyed-out text 4.6:1 on a button, white on the highlight 5.4:1.
        return makePalette(QColor(0x2b, 0x2d, 0x31), QColor(0x1e, 0x1f, 0x22), QColor(0x26, 0x28, 0x2b),
                           QColor(0xe6, 0xe6, 0xe6), QColor(0x3a, 0x3d, 0x42), QColor(0x2a, 0x6c, 0xb0), Qt::white,
                           QColor(0xb0, 0xb0, 0xb0), QColor(0x6c, 0xb4, 0xff));
    case Theme::HighContrastLight:
        // Black on white, a blue highlight with white text (contrast above 7:1, WCAG AAA).
        return makePalette(Qt::white, Qt::white, QColor(0xf0, 0xf0, 0xf0), Qt::black, Qt::white,
                           QColor(0x00, 0x33, 0x99), Qt::white, QColor(0x55, 0x55, 0x55), QColor(0x00, 0x33, 0x99));
    case Theme::HighContrastDark:
        return makePalette(Qt::black, Qt::black, QColor(0x1a, 0x1a, 0x1a), Qt::white, Qt::black,
                           QColor(0xff, 0xd7, 0x00), Qt::black, QColor(0xaa, 0xaa, 0xaa), QColor(0x66, 0xcc, 0xff));
    }
    throw std::logic_error("theme without a palette");
}

QColor fieldBorder(Theme theme)
{
    // 3:1 at least against both the window around a field and the base inside it (WCAG
    // 1.4.11): Fusion's own frame (the window colour, darker) is 2.3:1 in the light theme
    // and black on black in the high-contrast dark one.
    switch (theme) {
    case Theme::Light:
        return QColor(0x6b, 0x6b, 0x6b);
    case Theme::Dark:
        return QColor(0x9a, 0x9a, 0x9a);
    case Theme::HighContrastLight:
        return Qt::black;
    case Theme::HighContrastDark:
        return Qt::white;
    }
    throw std::logic_error("theme without a field border");
}

SurfaceColours surfaceColours(Theme theme)
{
    switch (theme) {
    case Theme::Light: // the 3D view's and the charts' own colours before themes existed
        return {QColor(0xec, 0xf0, 0xf5), Qt::white, QColor(0x30, 0x30, 0x30), QColor(0xd8, 0xd8, 0xd8),
                QColor(0x70, 0x70, 0x70)};
    case Theme::Dark:
        return {QColor(0x1e, 0x1f, 0x22), QColor(0x26, 0x28, 0x2b), QColor(0xe6, 0xe6, 0xe6), QColor(0x4a, 0x4d, 0x52),
                QColor(0xa0, 0xa0, 0xa0)};
    case Theme::HighContrastLight:
        return {Qt::white, Qt::white, Qt::black, QColor(0x99, 0x99, 0x99), Qt::black};
    case Theme::HighContrastDark:
        return {Qt::black, Qt::black, Qt::white, QColor(0x77, 0x77, 0x77), Qt::white};
    }
    throw std::logic_error("theme without surface colours");
}

const std::array<QColor, 8>& okabeIto()
{
    static const std::array<QColor, 8> colours{
        QColor(0x00, 0x00, 0x00), QColor(0xe6, 0x9f, 0x00), QColor(0x56, 0xb4, 0xe9), QColor(0x00, 0x9e, 0x73),
        QColor(0xf0, 0xe4, 0x42), QColor(0x00, 0x72, 0xb2), QColor(0xd5, 0x5e, 0x00), QColor(0xcc, 0x79, 0xa7)};
    return colours;
}

QColor colourBlindSafe(const QColor& colour)
{
    if (colour.hsvSaturationF() < 0.2f)
        return colour; // greys and black carry no hue to confuse
    // Nearest hue among the saturated Okabe-Ito colours; sky blue and yellow are left to
    // the balls, where a light colour on the view's background still reads.
    static const int candidates[] = {1, 3, 5, 6, 7};
    const float hue = colour.hsvHueF();
    int best = candidates[0];
    float bestDistance = 2.0f;
    for (int i : candidates) {
        const float d = std::fabs(okabeIto()[std::size_t(i)].hsvHueF() - hue);
        const float wrapped = std::min(d, 1.0f - d); // hue is on a circle
        if (wrapped < bestDistance) {
            bestDistance = wrapped;
            best = i;
        }
    }
    QColor out = okabeIto()[std::size_t(best)];
    out.setAlpha(colour.alpha());
    return out;
}

std::vector<unsigned> okabeItoBallColours(int balls, Theme theme)
{
    std::vector<unsigned> usable;
    for (std::size_t i = 0; i < okabeIto().size(); ++i) {
        if ((i == 0 && isDark(theme)) || (i == 4 && !isDark(theme)))
            continue;
        usable.push_back(okabeIto()[i].rgb() & 0xffffffu);
    }
    std::vector<unsigned> out(static_cast<std::size_t>(std::max(balls, 0)));
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = usable[i % usable.size()];
    return out;
}

} // namespace ab::ui
