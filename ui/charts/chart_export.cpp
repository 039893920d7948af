// SPDX-License-Identifier: MIT
#include "chart_export.h"

#include "program_version.h"

#include "core/io/atomic_file.h"
#include "core/params.h"

#include <QBuffer>
#include <QChart>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QGraphicsScene>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

namespace ab::ui {

namespace {

// A chart that was never shown has no layout yet: place it in a scene of the wanted size
// and activate the layout (Qt Charts 6.4 otherwise draws an empty frame). The chart's
// own scene, if it has one, is restored afterwards.
class Staged {
public:
    Staged(QChart* chart, QSizeF size) : chart_(chart), oldScene_(chart->scene()), oldGeometry_(chart->geometry())
    {
        if (oldScene_)
            oldScene_->removeItem(chart_);
        scene_.addItem(chart_);
        scene_.setSceneRect(QRectF(QPointF(0, 0), size));
        // Laid out at a slightly different size first: Qt Charts 6.4 keeps the axes'
        // label widths of the last layout at a size (eliding labels to "..." that have
        // grown since, as when the range was set after a first layout); a change of size
        // makes it measure them again. Twice at the size: a legend or caption that wraps
        // changes the margins, and so the layout.
        for (const QSizeF s : {size + QSizeF(1.0, 1.0), size, size}) {
            chart_->setGeometry(QRectF(QPointF(0, 0), s));
            if (chart_->layout())
                chart_->layout()->activate();
        }
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

    void render(QPainter& painter, const QRectF& target) { scene_.render(&painter, target, scene_.sceneRect()); }

private:
    QChart* chart_;
    QGraphicsScene* oldScene_;
    QRectF oldGeometry_;
    QGraphicsScene scene_;
};

std::string pathText(const QString& path)
{
    return path.toStdString();
}

void writePng(QIODevice& file, const QString& path, const FigureOptions& options, const ScenePainter& paint)
{
    const QSize pixels = options.pngPixels();
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        throw InputError(pathText(path) + ": not enough memory for a " + std::to_string(pixels.width()) + "x" +
                         std::to_string(pixels.height()) + " image");
    image.fill(Qt::white);
    const int dotsPerMetre = int(options.effectiveDpi() / 0.0254 + 0.5);
    image.setDotsPerMeterX(dotsPerMetre);
    image.setDotsPerMeterY(dotsPerMetre);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setRenderHint(QPainter::TextAntialiasing);
        const QSizeF scene = options.sceneSize();
        painter.scale(pixels.width() / scene.width(), pixels.height() / scene.height());
        paint(painter, QRectF(QPointF(0, 0), scene));
    }
    if (!image.save(&file, "PNG"))
        throw InputError(pathText(path) + ": PNG encoding failed");
}

void writeSvg(QIODevice& file, const FigureOptions& options, const QString& title, const ScenePainter& paint)
{
    // The drawing in scene units (the viewBox), declared 1/144 inch each: the width and
    // height attributes then carry the physical size in millimetres (given in tenths of
    // a scene unit, so the whole-number size rounds by less than 0.02 mm).
    const QSizeF scene = options.sceneSize();
    QSvgGenerator svg;
    svg.setOutputDevice(&file);
    svg.setResolution(int(10 * kSceneDpi));
    svg.setSize(QSize(int(std::lround(10 * scene.width())), int(std::lround(10 * scene.height()))));
    svg.setViewBox(QRectF(QPointF(0, 0), scene));
    svg.setTitle(title);
    svg.setDescription(QString::fromStdString(programName()) + " " + QString::fromStdString(programVersion()));
    QPainter painter(&svg);
    paint(painter, QRectF(QPointF(0, 0), scene));
    painter.end();
}

void writePdf(QIODevice& file, const QString& path, const FigureOptions& options, const QString& title,
              const ScenePainter& paint)
{
    const QSizeF mm = options.millimetres();
    QPdfWriter pdf(&file);
    pdf.setPageSize(QPageSize(mm, QPageSize::Millimeter, QString(), QPageSize::ExactMatch));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
    pdf.setResolution(1200);
    pdf.setTitle(title);
    pdf.setCreator(QString::fromStdString(programName()) + " " + QString::fromStdString(programVersion()));
    QPainter painter(&pdf);
    if (!painter.isActive())
        throw InputError(pathText(path) + ": cannot start the PDF");
    painter.setRenderHint(QPainter::Antialiasing);
    const QSizeF scene = options.sceneSize();
    painter.scale(pdf.width() / scene.width(), pdf.height() / scene.height());
    paint(painter, QRectF(QPointF(0, 0), scene));
    painter.end();
}

} // namespace

QImage renderChart(QChart* chart, QSize size)
{
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    Staged staged(chart, size);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    staged.render(painter, QRectF(QPointF(0, 0), size));
    return image;
}

void checkFigurePath(const QString& path, const std::string& what)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != "png" && suffix != "svg" && suffix != "pdf")
        throw InputError((what.empty() ? "" : what + ": ") + printableInput(pathText(path)) +
                         (suffix.isEmpty() ? std::string(": no image type")
                                           : ": unknown image type '" + printableInput(suffix.toStdString()) + "'") +
                         " (use .png, .svg or .pdf)");
}

void writeFigureFile(const QString& path, const FigureOptions& options, const QString& title, const ScenePainter& paint)
{
    checkFigurePath(path);
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == "png")
        (void)options.pngPixels(); // refuse a size too large before touching the disk
    checkWritable(pathText(path));
    // Encoded in memory, then written through the one output path (core/io/atomic_file.h):
    // every write checked, devices and links respected, nothing half-written.
    QByteArray bytes;
    QBuffer file(&bytes);
    file.open(QIODevice::WriteOnly);
    if (suffix == "png")
        writePng(file, path, options, paint);
    else if (suffix == "svg")
        writeSvg(file, options, title, paint);
    else
        writePdf(file, path, options, title, paint);
    file.close();
    writeFileAtomically(pathText(path), std::string_view(bytes.constData(), std::size_t(bytes.size())));
}

void exportChart(QChart* chart, const QString& path, const FigureOptions& options)
{
    checkFigurePath(path);
    Staged staged(chart, options.sceneSize());
    writeFigureFile(path, options, chart->title(),
                    [&](QPainter& painter, const QRectF& scene) { staged.render(painter, scene); });
}

void exportChart(QChart* chart, const QString& path, QSize size)
{
    FigureOptions options{pixelFigureSize(size.width(), size.height()), int(kSceneDpi)};
    exportChart(chart, path, options);
}

} // namespace ab::ui
