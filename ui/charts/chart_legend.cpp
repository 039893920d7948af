// SPDX-License-Identifier: MIT
#include "chart_legend.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QTextOption>

#include <algorithm>

namespace ab::ui {

ChartLegend::ChartLegend(QGraphicsItem* parent) : QGraphicsItem(parent) {}

void ChartLegend::setEntries(std::vector<LegendEntry> entries)
{
    entries_ = std::move(entries);
    layout(width_);
}

void ChartLegend::setCaption(const QString& caption)
{
    caption_ = caption;
    layout(width_);
}

void ChartLegend::setFonts(const QFont& legend, const QFont& caption)
{
    font_ = legend;
    captionFont_ = caption;
    layout(width_);
}

double ChartLegend::layout(double width)
{
    prepareGeometryChange();
    width_ = std::max(width, 0.0);
    placed_.clear();
    const QFontMetricsF fm(font_);
    const double spacing = fm.height() * 1.2; // between entries
    const double row = fm.height() * 1.15;
    double x = 0.0, y = entries_.empty() ? 0.0 : row / 2.0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        const double w = sampleOf(i) + fm.horizontalAdvance(entries_[i].text);
        if (x > 0.0 && x + w > width_) { // wrap: the next row
            x = 0.0;
            y += row;
        }
        placed_.push_back({QPointF(x, y), i});
        x += w + spacing;
    }
    // Centre each row.
    for (std::size_t i = 0; i < placed_.size();) {
        std::size_t j = i;
        double right = 0.0;
        for (; j < placed_.size() && placed_[j].at.y() == placed_[i].at.y(); ++j)
            right =
                placed_[j].at.x() + sampleOf(placed_[j].entry) + fm.horizontalAdvance(entries_[placed_[j].entry].text);
        const double shift = std::max(0.0, (width_ - right) / 2.0);
        for (std::size_t k = i; k < j; ++k)
            placed_[k].at.rx() += shift;
        i = j;
    }
    double h = entries_.empty() ? 0.0 : y + row / 2.0;
    captionRect_ = QRectF();
    if (!caption_.isEmpty()) {
        const QFontMetricsF cm(captionFont_);
        const QRectF r = cm.boundingRect(QRectF(0, 0, std::max(width_, 1.0), 1e6), Qt::TextWordWrap, caption_);
        const double top = h + (h > 0.0 ? cm.height() * 0.4 : 0.0);
        captionRect_ = QRectF(0, top, std::max(width_, 1.0), r.height());
        h = captionRect_.bottom();
    }
    height_ = h;
    update();
    return height_;
}

double ChartLegend::sampleOf(std::size_t entry) const
{
    // A text-only entry (no pen: a run's name before its lines) takes no sample.
    return entries_[entry].pen.style() == Qt::NoPen ? 0.0 : sample_ + QFontMetricsF(font_).height() * 0.4;
}

QRectF ChartLegend::boundingRect() const
{
    return QRectF(0, 0, width_, height_);
}

void ChartLegend::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setFont(font_);
    const QFontMetricsF fm(font_);
    for (const Placed& p : placed_) {
        const LegendEntry& e = entries_[p.entry];
        if (e.pen.style() != Qt::NoPen) {
            painter->setPen(e.pen);
            painter->drawLine(QLineF(p.at, p.at + QPointF(sample_, 0.0)));
        }
        painter->setPen(text_);
        const QRectF text(p.at.x() + sampleOf(p.entry), p.at.y() - fm.height() / 2.0,
                          fm.horizontalAdvance(e.text) + 1.0, fm.height());
        painter->drawText(text, Qt::AlignLeft | Qt::AlignVCenter, e.text);
    }
    if (!caption_.isEmpty()) {
        painter->setFont(captionFont_);
        painter->setPen(text_);
        painter->drawText(captionRect_, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, caption_);
    }
    painter->restore();
}

} // namespace ab::ui
