// SPDX-License-Identifier: MIT
#include "theme_style.h"

#include <QApplication>
#include <QIconEngine>
#include <QPainter>
#include <QPainterPath>
#include <QStyleFactory>
#include <QStyleOption>

namespace ab::ui {

namespace {

// A media icon drawn as a vector shape in the application palette's button text colour
// at the moment it is painted, so that it follows a theme switch without being set again.
class MediaIconEngine : public QIconEngine {
public:
    explicit MediaIconEngine(QStyle::StandardPixmap kind) : kind_(kind) {}
    QIconEngine* clone() const override { return new MediaIconEngine(kind_); }

    // What a button draws. QIconEngine's own pixmap() paints over the pixels as allocated,
    // so that the shape sat on whatever the memory held (noise around Play and Pause).
    QPixmap pixmap(const QSize& size, QIcon::Mode mode, QIcon::State state) override
    {
        QPixmap pm(size);
        pm.fill(Qt::transparent);
        QPainter painter(&pm);
        paint(&painter, QRect(QPoint(0, 0), size), mode, state);
        return pm;
    }

    void paint(QPainter* painter, const QRect& rect, QIcon::Mode mode, QIcon::State) override
    {
        const QPalette palette = QApplication::palette();
        const QColor colour =
            palette.color(mode == QIcon::Disabled ? QPalette::Disabled : QPalette::Active, QPalette::ButtonText);
        const double s = std::min(rect.width(), rect.height());
        const QRectF box(rect.x() + (rect.width() - s) / 2.0, rect.y() + (rect.height() - s) / 2.0, s, s);
        const QRectF r = box.adjusted(0.14 * s, 0.14 * s, -0.14 * s, -0.14 * s);
        QPainterPath path;
        auto triangle = [&path](QPointF a, QPointF b, QPointF c) {
            path.moveTo(a);
            path.lineTo(b);
            path.lineTo(c);
            path.closeSubpath();
        };
        const double w = r.width(), h = r.height();
        switch (kind_) {
        case QStyle::SP_MediaPlay:
            triangle(r.topLeft() + QPointF(0.12 * w, 0), r.bottomLeft() + QPointF(0.12 * w, 0),
                     QPointF(r.right(), r.center().y()));
            break;
        case QStyle::SP_MediaPause:
            path.addRect(QRectF(r.left() + 0.12 * w, r.top(), 0.28 * w, h));
            path.addRect(QRectF(r.right() - 0.40 * w, r.top(), 0.28 * w, h));
            break;
        case QStyle::SP_MediaSkipForward:
            triangle(r.topLeft(), r.bottomLeft(), QPointF(r.left() + 0.75 * w, r.center().y()));
            path.addRect(QRectF(r.left() + 0.78 * w, r.top(), 0.22 * w, h));
            break;
        case QStyle::SP_MediaSkipBackward:
            path.addRect(QRectF(r.left(), r.top(), 0.22 * w, h));
            triangle(r.topRight(), r.bottomRight(), QPointF(r.left() + 0.25 * w, r.center().y()));
            break;
        default: // SP_MediaStop
            path.addRect(r.adjusted(0.08 * w, 0.08 * h, -0.08 * w, -0.08 * h));
            break;
        }
        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        painter->setPen(Qt::NoPen);
        painter->setBrush(colour);
        painter->drawPath(path);
        painter->restore();
    }

private:
    QStyle::StandardPixmap kind_;
};

// A rounded frame `width` wide just inside `rect`, antialiased.
void strokeFrame(QPainter* painter, const QRectF& rect, const QColor& colour, double width)
{
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(colour, width));
    const double inset = width / 2.0;
    painter->drawRoundedRect(rect.adjusted(inset, inset, -inset, -inset), 2.0, 2.0);
    painter->restore();
}

} // namespace

ThemeStyle::ThemeStyle() : QProxyStyle(QStyleFactory::create(QStringLiteral("Fusion")))
{
    setObjectName(QStringLiteral("amazeballs-theme-style"));
}

void ThemeStyle::drawFieldFrame(const QStyleOption* option, QPainter* painter) const
{
    const bool focus = option->state & State_HasFocus;
    const bool enabled = option->state & State_Enabled;
    // The focus frame in the link colour: 3:1 on the window in every theme, where the
    // selection highlight (which white text must read on) cannot be in the dark one.
    QColor colour = focus ? option->palette.color(QPalette::Link) : border_;
    if (!enabled)
        colour = option->palette.color(QPalette::Disabled, QPalette::Text);
    strokeFrame(painter, option->rect, colour, focus ? 2.0 : 1.0);
}

void ThemeStyle::drawPrimitive(PrimitiveElement element, const QStyleOption* option, QPainter* painter,
                               const QWidget* widget) const
{
    if (element == PE_FrameLineEdit) {
        drawFieldFrame(option, painter);
        return;
    }
    QProxyStyle::drawPrimitive(element, option, painter, widget);
    if ((element == PE_PanelButtonCommand || element == PE_PanelButtonTool) && (option->state & State_On))
        drawCheckedFrame(option, painter);
}

void ThemeStyle::drawCheckedFrame(const QStyleOption* option, QPainter* painter) const
{
    // Fusion shows a button held down (the stage, the street's camera shot) by a darker
    // shade of the button colour, which on a black button is black: a frame in the link
    // colour (3:1 on the window in every theme, as the focus frame) says which is down.
    const QColor colour = option->state & State_Enabled ? option->palette.color(QPalette::Link)
                                                        : option->palette.color(QPalette::Disabled, QPalette::Text);
    strokeFrame(painter, QRectF(option->rect).adjusted(0.5, 0.5, -0.5, -0.5), colour, 2.0);
}

void ThemeStyle::drawComplexControl(ComplexControl control, const QStyleOptionComplex* option, QPainter* painter,
                                    const QWidget* widget) const
{
    QProxyStyle::drawComplexControl(control, option, painter, widget);
    if (control == CC_SpinBox && option->subControls & SC_SpinBoxFrame)
        drawFieldFrame(option, painter);
    else if (control == CC_ComboBox && option->subControls & SC_ComboBoxFrame)
        drawFieldFrame(option, painter);
    else if (control == CC_Slider)
        drawSliderFrames(option, painter, widget);
}

void ThemeStyle::drawSliderFrames(const QStyleOptionComplex* option, QPainter* painter, const QWidget* widget) const
{
    // Fusion draws a slider's groove and handle in shades of the window and button colours,
    // which on the high-contrast dark theme's black are black: the time slider's handle was a
    // dark speck. Each gets the field border (3:1 on the window in every theme, WCAG 1.4.11),
    // the handle twice as thick, so where it stands reads on a projector.
    const QColor colour =
        option->state & State_Enabled ? border_ : option->palette.color(QPalette::Disabled, QPalette::Text);
    if (option->subControls & SC_SliderGroove)
        strokeFrame(painter,
                    QRectF(subControlRect(CC_Slider, option, SC_SliderGroove, widget)).adjusted(0.5, 0.5, -0.5, -0.5),
                    colour, 1.0);
    if (option->subControls & SC_SliderHandle)
        strokeFrame(painter, QRectF(subControlRect(CC_Slider, option, SC_SliderHandle, widget)).adjusted(1, 1, -1, -1),
                    colour, 2.0);
}

QIcon ThemeStyle::standardIcon(StandardPixmap icon, const QStyleOption* option, const QWidget* widget) const
{
    switch (icon) {
    case SP_MediaPlay:
    case SP_MediaPause:
    case SP_MediaStop:
    case SP_MediaSkipForward:
    case SP_MediaSkipBackward:
        return QIcon(new MediaIconEngine(icon));
    default:
        return QProxyStyle::standardIcon(icon, option, widget);
    }
}

} // namespace ab::ui
