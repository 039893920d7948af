// SPDX-License-Identifier: MIT
// The charts' own legend and caption, drawn below the plot: each entry a short sample of
// its line in the line's own pen (colour, width and dash style; Qt Charts' QLegend draws
// only a coloured square), entries wrapped onto as many rows as the width needs (never
// elided), then an optional caption in as many lines as it takes.
#pragma once

#include <QFont>
#include <QGraphicsItem>
#include <QPen>
#include <QString>

#include <vector>

namespace ab::ui {

struct LegendEntry {
    QPen pen;
    QString text;
};

class ChartLegend : public QGraphicsItem {
public:
    explicit ChartLegend(QGraphicsItem* parent = nullptr);

    void setEntries(std::vector<LegendEntry> entries);
    const std::vector<LegendEntry>& entries() const { return entries_; }
    void setCaption(const QString& caption);
    const QString& caption() const { return caption_; }
    void setFonts(const QFont& legend, const QFont& caption);
    void setSampleLength(double length) { sample_ = length; }
    const QColor& textColour() const { return text_; }
    void setTextColour(const QColor& colour)
    {
        text_ = colour;
        update();
    }
    // Lays the entries and the caption out in `width`; returns the height they take.
    double layout(double width);
    double height() const { return height_; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    // The sample's length and the gap after it (none for a text-only entry).
    double sampleOf(std::size_t entry) const;
    struct Placed {
        QPointF at; // the sample's left end, on the text's middle line
        std::size_t entry;
    };
    std::vector<LegendEntry> entries_;
    std::vector<Placed> placed_;
    QString caption_;
    QRectF captionRect_;
    QFont font_, captionFont_;
    QColor text_ = QColor(0x22, 0x22, 0x22);
    double sample_ = 28.0;
    double width_ = 0.0, height_ = 0.0;
};

} // namespace ab::ui
