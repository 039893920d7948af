// SPDX-License-Identifier: MIT
#include "chart_export.h"

#include "core/io/atomic_file.h"
#include "core/params.h"

#include <QBuffer>
#include <QChart>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QPainter>
#include <QSvgGenerator>

namespace ab::ui {

namespace {

// A chart that was never shown has no layout yet: place it in a scene of the wanted size
// and activate the layout (Qt Charts 6.4 otherwise draws an empty frame). The chart's
// own scene, if it has one, is restored afterwards.
class Staged {
public:
    Staged(QChart* chart, QSize size) : chart_(chart), oldScene_(chart->scene()), oldGeometry_(chart->geometry())
    {
        if (oldScene_)
            oldScene_->removeItem(chart_);
        scene_.addItem(chart_);
        chart_->setGeometry(QRectF(QPointF(0, 0), size));
        scene_.setSceneRect(QRectF(QPointF(0, 0), size));
        if (chart_->layout())
            chart_->layout()->activate();
    }
    ~Staged()
    {
        scene_.removeItem(chart_);
        if (oldScene_) {
            oldScene_->addItem(chart_);
            chart_->setGeometry(oldGeometry_);
        }
    }
    Staged(const Staged&) = delete;
    Staged& operator=(const Staged&) = delete;

    void render(QPainter& painter, QSize size)
    {
        scene_.render(&painter, QRectF(QPointF(0, 0), size), scene_.sceneRect());
    }

private:
    QChart* chart_;
    QGraphicsScene* oldScene_;
    QRectF oldGeometry_;
    QGraphicsScene scene_;
};

} // namespace

QImage renderChart(QChart* chart, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    Staged staged(chart, size);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    staged.render(painter, size);
    return image;
}

void exportChart(QChart* chart, const QString& path, QSize size)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "png" && suffix != "svg")
        throw InputError(path.toStdString() + ": unknown image type '" + suffix.toStdString() + "' (use .png or .svg)");
    checkWritable(path.toStdString());
    // Encoded in memory, then written through the one output path (core/io/atomic_file.h):
    // every write checked, devices and links respected, nothing half-written.
    QByteArray bytes;
    QBuffer file(&bytes);
    file.open(QIODevice::WriteOnly);
    if (suffix == "png") {
        if (!renderChart(chart, size).save(&file, "PNG"))
            throw InputError(path.toStdString() + ": PNG encoding failed");
    } else {
        QSvgGenerator svg;
        svg.setOutputDevice(&file);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(chart->title());
        svg.setDescription("Amazeballs chart");
        Staged staged(chart, size);
        QPainter painter(&svg);
        staged.render(painter, size);
        painter.end();
    }
    writeFileAtomically(path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())));
}

} // namespace ab::ui
