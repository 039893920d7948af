// SPDX-License-Identifier: MIT
#include "offscreen_view.h"

#include "ui/view/view_frame.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>

#include <stdexcept>

namespace ab::ui {

OffscreenView::OffscreenView(QSize size) : size_(size) {}

OffscreenView::~OffscreenView()
{
    if (context_ && surface_ && context_->makeCurrent(surface_.get())) {
        if (renderer_)
            renderer_->release();
        fbo_.reset();
        context_->doneCurrent();
    }
}

void OffscreenView::initialize()
{
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    const std::string platform = QGuiApplication::platformName().toStdString();
    context_ = std::make_unique<QOpenGLContext>();
    context_->setFormat(format);
    if (!context_->create())
        throw std::runtime_error("no OpenGL context on the '" + platform + "' platform");
    surface_ = std::make_unique<QOffscreenSurface>();
    surface_->setFormat(context_->format());
    surface_->create();
    if (!surface_->isValid() || !context_->makeCurrent(surface_.get()))
        throw std::runtime_error("no offscreen OpenGL surface on the '" + platform + "' platform");
    const QSurfaceFormat got = context_->format();
    if (got.version() < qMakePair(3, 3))
        throw std::runtime_error("OpenGL " + std::to_string(got.majorVersion()) + "." +
                                 std::to_string(got.minorVersion()) + " on the '" + platform +
                                 "' platform; the 3D view needs 3.3");
    fbo_ = std::make_unique<QOpenGLFramebufferObject>(size_, QOpenGLFramebufferObject::Depth);
    if (!fbo_->isValid())
        throw std::runtime_error("no " + std::to_string(size_.width()) + "x" + std::to_string(size_.height()) +
                                 " framebuffer object");
    renderer_ = std::make_unique<SceneRenderer>();
    QString error;
    if (!renderer_->initialize(error))
        throw std::runtime_error("OpenGL: " + error.toStdString());
}

void OffscreenView::makeCurrent()
{
    if (!context_ || !context_->makeCurrent(surface_.get()))
        throw std::runtime_error("OffscreenView: the OpenGL context is gone");
}

void OffscreenView::setScene(const SceneLayout& layout, const QString& lengthUnit, std::vector<unsigned> colours,
                             int selected, const QColor& background, const std::optional<CameraPose>& pose)
{
    makeCurrent();
    layout_ = layout;
    geometry_ = buildSceneGeometry(layout, lengthUnit);
    colours_ = std::move(colours);
    selected_ = selected;
    background_ = background;
    renderer_->setGeometry(geometry_);
    renderer_->setColours(colours_);
    if (pose)
        camera_.setPose(*pose, (geometry_.hi - geometry_.lo).length());
    else
        frameSceneCamera(camera_, geometry_, layout_, float(size_.width()) / float(size_.height()));
}

QImage OffscreenView::render(const std::vector<float>& xyz, const std::vector<QVector3D>& trace,
                             const std::vector<float>& orientations)
{
    makeCurrent();
    renderer_->setBalls(xyz);
    renderer_->setOrientations(orientations);
    const bool has = selected_ >= 0 && std::size_t(selected_) < colours_.size();
    const QColor traceColour =
        has ? QColor::fromRgb(colours_[std::size_t(selected_)]).darker(150) : QColor(Qt::darkGray);
    renderer_->setTrace(trace, traceColour);
    fbo_->bind();
    renderer_->draw(sceneRenderInputs(camera_, layout_, size_, selected_, background_));
    // The translucent walls blend into alpha too; a window ignores it, an image would not:
    // make every pixel opaque, keeping the colours as drawn.
    QOpenGLFunctions* gl = context_->functions();
    gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    gl->glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    gl->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    fbo_->release();
    QImage image = fbo_->toImage();
    // Labels as the window draws them, scaled with the frame (10 pt in a view ~720 px tall).
    QFont font;
    font.setPixelSize(std::max(11, size_.height() / 52));
    QPainter p(&image);
    paintSceneLabels(p, camera_, size_, geometry_, layout_, xyz, font, background_);
    return image;
}

} // namespace ab::ui
