// SPDX-License-Identifier: MIT
// The application's widget style: Fusion, with two things a projector needs that Fusion
// takes from the window colour and so loses in some themes. Editable fields (line edits,
// spin boxes, combo boxes) get a frame in the theme's field border colour (3:1 against
// the window and the field, WCAG 1.4.11), thicker and in the link colour when they have the focus; the media
// icons (play, pause, step, reset) are drawn in the palette's button text colour instead
// of Fusion's fixed mid grey, which is 3:1 on white and dim on black; a button held down
// (checked) gets a frame in the link colour, where Fusion's darker shade of a black button
// cannot be told from it.
#pragma once

#include <QColor>
#include <QProxyStyle>

namespace ab::ui {

class ThemeStyle : public QProxyStyle {
    Q_OBJECT
public:
    ThemeStyle();

    void setFieldBorder(const QColor& colour) { border_ = colour; }
    QColor fieldBorder() const { return border_; }

    void drawPrimitive(PrimitiveElement element, const QStyleOption* option, QPainter* painter,
                       const QWidget* widget = nullptr) const override;
    void drawComplexControl(ComplexControl control, const QStyleOptionComplex* option, QPainter* painter,
                            const QWidget* widget = nullptr) const override;
    QIcon standardIcon(StandardPixmap icon, const QStyleOption* option = nullptr,
                       const QWidget* widget = nullptr) const override;

private:
    void drawFieldFrame(const QStyleOption* option, QPainter* painter) const;
    void drawCheckedFrame(const QStyleOption* option, QPainter* painter) const;
    void drawSliderFrames(const QStyleOptionComplex* option, QPainter* painter, const QWidget* widget) const;

    QColor border_{0x6b, 0x6b, 0x6b};
};

} // namespace ab::ui
