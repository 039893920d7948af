// SPDX-License-Identifier: MIT
// The 3D view drawn into a framebuffer object of a fixed size, with no window: an
// offscreen surface and a context of its own (OpenGL 3.3 core, as the window's view),
// the same renderer, camera framing and labels as the window (ui/view/view_frame.h).
// Must live on the thread that made the QGuiApplication.
#pragma once

#include "ui/view/orbit_camera.h"
#include "ui/view/scene_geometry.h"
#include "ui/view/scene_renderer.h"

#include <QColor>
#include <QImage>
#include <QSize>
#include <QVector3D>

#include <memory>
#include <optional>
#include <vector>

class QOffscreenSurface;
class QOpenGLContext;
class QOpenGLFramebufferObject;

namespace ab::ui {

class OffscreenView {
public:
    explicit OffscreenView(QSize size);
    ~OffscreenView();
    OffscreenView(const OffscreenView&) = delete;
    OffscreenView& operator=(const OffscreenView&) = delete;

    // Creates the context, the framebuffer and the renderer; throws std::runtime_error
    // with one line saying what OpenGL lacks.
    void initialize();

    // The scene to draw; the camera is framed for this size unless `pose` places it.
    void setScene(const SceneLayout& layout, const QString& lengthUnit, std::vector<unsigned> colours, int selected,
                  const QColor& background, const std::optional<CameraPose>& pose);
    // Draws the balls (x y z per ball), turned by `orientations` where the balls turn
    // (kOrientationFloats per ball; empty: no pattern), and the selected ball's trace;
    // labels included.
    QImage render(const std::vector<float>& xyz, const std::vector<QVector3D>& trace,
                  const std::vector<float>& orientations = {});

    const OrbitCamera& camera() const { return camera_; }
    QSize size() const { return size_; }

private:
    void makeCurrent();

    QSize size_;
    std::unique_ptr<QOffscreenSurface> surface_;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOpenGLFramebufferObject> fbo_;
    std::unique_ptr<SceneRenderer> renderer_;
    OrbitCamera camera_;
    SceneLayout layout_;
    SceneGeometry geometry_;
    std::vector<unsigned> colours_;
    int selected_ = -1;
    QColor background_;
};

} // namespace ab::ui
