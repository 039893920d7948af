// SPDX-License-Identifier: MIT
#include "ball_view.h"

#include "view_frame.h"

#include <QGuiApplication>
#include <QOpenGLContext>
#include <QPainter>
#include <QSurfaceFormat>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

QSurfaceFormat viewFormat()
{
    QSurfaceFormat f;
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(24);
    return f;
}

} // namespace

BallView::BallView()
{
    setFormat(viewFormat());
    container_ = QWidget::createWindowContainer(this);
    container_->setObjectName("ballView");
    container_->setFocusPolicy(Qt::ClickFocus);
    container_->setMinimumSize(320, 240);
    container_->setAccessibleName(tr("3D view"));
    sincePaint_.start();
}

BallView::~BallView()
{
    releaseGl();
}

bool BallView::available()
{
    const QString platform = QGuiApplication::platformName();
    return platform != QLatin1String("offscreen") && platform != QLatin1String("minimal");
}

void BallView::initializeGL()
{
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &BallView::releaseGl, Qt::UniqueConnection);
    if (!renderer_.initialize(glError_))
        qWarning("3D view: %s", qPrintable(glError_));
    geometryDirty_ = coloursDirty_ = ballsDirty_ = traceDirty_ = ghostsDirty_ = true;
}

void BallView::releaseGl()
{
    if (!renderer_.ready() || !context())
        return;
    makeCurrent();
    renderer_.release();
    doneCurrent();
}

void BallView::resizeGL(int, int)
{
    if (!cameraMoved_)
        framePending_ = true; // keep the whole scene in view until the user moves the camera
    update();                 // a window made smaller is not exposed again: its old picture, cut, would stay
}

void BallView::setScene(const SceneLayout& layout, const QString& lengthUnit, std::vector<unsigned> colours,
                        bool reframe)
{
    const bool regionChanged = !layout_.region.isApprox(layout.region) || layout_.walls != layout.walls;
    layout_ = layout;
    geometry_ = buildSceneGeometry(layout, lengthUnit);
    solids_.reset();
    if (layout_.street)
        solids_.emplace(layout_.street);
    colours_ = std::move(colours);
    balls_.clear();
    orientations_.clear();
    trace_.clear();
    selected_ = std::min(selected_, std::max(layout.balls - 1, 0));
    ghosts_.clear();
    geometryDirty_ = coloursDirty_ = ballsDirty_ = traceDirty_ = ghostsDirty_ = true;
    if (reframe || regionChanged)
        resetView();
    else if (!layout_.street)
        setStreetShot(std::nullopt);
    update();
}

void BallView::setColours(std::vector<unsigned> colours)
{
    colours_ = std::move(colours);
    coloursDirty_ = true;
    update();
}

void BallView::setBackground(const QColor& colour)
{
    background_ = colour;
    update();
}

void BallView::resetView()
{
    // Framed at the next paint, when the window's size (the aspect) is known.
    framePending_ = true;
    cameraMoved_ = false;
    if (layout_.street || shot_)
        shot_ = layout_.street ? std::optional(StreetShot::Foot) : std::nullopt; // frameSceneCamera's street shot
    emit streetShotChanged();
    update();
}

void BallView::setStreetShot(std::optional<StreetShot> shot)
{
    shot = layout_.street ? shot : std::nullopt;
    if (shot == shot_)
        return;
    shot_ = shot;
    placeStreetShot();
    emit streetShotChanged();
}

void BallView::placeStreetShot()
{
    if (!shot_ || !layout_.street)
        return;
    const float aspect = float(width()) / float(std::max(height(), 1));
    auto front = *shot_ == StreetShot::Flood ? floodFront(*layout_.street, balls_) : std::nullopt;
    if (!front && !balls_.empty()) // every ball has left: the flood has passed the foot
        front = float(layout_.street->xFoot);
    const CameraPose pose = streetPose(*layout_.street, *shot_, aspect, front);
    camera_.setPose(pose, (geometry_.hi - geometry_.lo).length());
    framePending_ = false;
    cameraMoved_ = true;
    update();
}

void BallView::frameScene()
{
    frameSceneCamera(camera_, geometry_, layout_, float(width()) / float(std::max(height(), 1)));
    framePending_ = false;
}

void BallView::setCameraPose(const QVector3D& target, float yawDeg, float pitchDeg, float distance, float fovYDeg)
{
    camera_.setPose(target, yawDeg, pitchDeg, distance, (geometry_.hi - geometry_.lo).length(), fovYDeg);
    framePending_ = false;
    userMovedCamera();
    update();
}

void BallView::setBalls(const std::vector<float>& xyz, const std::vector<float>& orientations)
{
    const auto finite = [](const std::vector<float>& v) {
        return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
    };
    if (!finite(xyz) || !finite(orientations))
        return; // never draw a NaN: keep the last good frame
    if (xyz == balls_ && orientations == orientations_)
        return;
    balls_ = xyz;
    orientations_ = orientations;
    ballsDirty_ = true;
    if (shot_ == StreetShot::Flood)
        placeStreetShot();
    update();
}

float BallView::ghostOffset() const
{
    // Three radii: the two discs side by side with one radius of air between them, on
    // the left (the ball's height label is on its right).
    return layout_.axes == 1 ? float(-3.0 * layout_.ballRadius) : 0.0f;
}

void BallView::setGhosts(const std::vector<float>& xyz, const QString& legend)
{
    if (!std::all_of(xyz.begin(), xyz.end(), [](float x) { return std::isfinite(x); }))
        return; // never draw a NaN: keep the last good frame
    std::vector<float> shifted = xyz;
    const float offset = ghostOffset();
    for (std::size_t i = 0; i < shifted.size(); i += 3)
        shifted[i] += offset;
    if (legend != ghostLegend_) {
        ghostLegend_ = legend;
        update();
    }
    if (shifted == ghosts_)
        return;
    ghosts_ = std::move(shifted);
    ghostsDirty_ = true;
    update();
}

bool BallView::ghostPixel(int ball, QPointF& pixel) const
{
    if (ball < 0 || std::size_t(3 * ball + 2) >= ghosts_.size())
        return false;
    const auto k = static_cast<std::size_t>(3 * ball);
    return camera_.project(QVector3D(ghosts_[k], ghosts_[k + 1], ghosts_[k + 2]), size(), pixel);
}

void BallView::setSelected(int ball)
{
    if (ball == selected_)
        return;
    selected_ = ball;
    update();
}

void BallView::setTrace(std::vector<QVector3D> points)
{
    if (points == trace_)
        return;
    trace_ = std::move(points);
    traceDirty_ = true;
    update();
}

void BallView::uploadPending()
{
    if (!renderer_.ready())
        return;
    if (geometryDirty_)
        renderer_.setGeometry(geometry_);
    if (coloursDirty_)
        renderer_.setColours(colours_);
    if (ballsDirty_) {
        renderer_.setBalls(balls_);
        renderer_.setOrientations(orientations_);
    }
    if (ghostsDirty_)
        renderer_.setGhosts(ghosts_);
    if (traceDirty_ || coloursDirty_) {
        const bool has = selected_ >= 0 && std::size_t(selected_) < colours_.size();
        const QColor c = has ? QColor::fromRgb(colours_[std::size_t(selected_)]).darker(150) : QColor(Qt::darkGray);
        renderer_.setTrace(trace_, c);
    }
    geometryDirty_ = coloursDirty_ = ballsDirty_ = traceDirty_ = ghostsDirty_ = false;
}

RenderInputs BallView::renderInputs() const
{
    RenderInputs in = sceneRenderInputs(camera_, layout_, size(), selected_, background_, scale_);
    in.cutaway = shot_ == StreetShot::Side; // the near houses would hide the street's profile
    return in;
}

void BallView::paintGL()
{
    const double interval = double(sincePaint_.nsecsElapsed()) / 1e6;
    sincePaint_.restart();
    QElapsedTimer timer;
    timer.start();
    uploadPending();
    if (framePending_ && width() > 0 && height() > 0)
        frameScene();
    QPainter painter(this);
    painter.beginNativePainting();
    RenderInputs in = renderInputs();
    in.viewport = size() * devicePixelRatio();
    renderer_.draw(in);
    painter.endNativePainting();
    paintOverlay(painter);
    painter.end();
    emit framePainted(double(timer.nsecsElapsed()) / 1e6, interval);
}

void BallView::paintOverlay(QPainter& p)
{
    QFont font = p.font();
    font.setPointSizeF(10.0 * scale_);
    paintSceneLabels(p, camera_, size(), geometry_, layout_, balls_, font, background_,
                     [&](const QVector3D& at) { return solids_ && solids_->hides(camera_.eye(), at); });
    if (!ghostLegend_.isEmpty()) // bottom right, in the ghosts' violet: clear of the axis labels at the top
        drawHaloText(p, QPointF(width() - 12, height() - 40 * scale_), ghostLegend_, QColor(0x4b, 0x00, 0x82),
                     Qt::AlignRight, background_);
    if (!glError_.isEmpty())
        drawHaloText(p, QPointF(12, 44 * scale_), tr("OpenGL error: %1").arg(glError_), Qt::red, Qt::AlignLeft,
                     background_);
    if (keyFocus_)
        drawBottomHint(p, size(), tr("Arrow keys move the camera; Esc gives the keys back to the transport"),
                       QColor(0x30, 0x30, 0x30), background_);
}

void BallView::setPresentationScale(double scale)
{
    if (scale > 0.0 && scale != scale_) {
        scale_ = scale;
        update();
    }
}

float BallView::minimumBallPixels() const
{
    return smallestBallPixels(layout_, height(), scale_);
}

QVector3D BallView::ballAt(int i) const
{
    const auto k = static_cast<std::size_t>(3 * i);
    return QVector3D(balls_[k], balls_[k + 1], balls_[k + 2]);
}

float BallView::drawnRadius(const QVector3D& centre) const
{
    // As ball.vert: never smaller than minPixels on screen.
    const RenderInputs in = renderInputs();
    const float depth = std::max(-(in.view.map(centre)).z(), 1e-6f);
    return std::max(in.radius, in.minPixels * depth / in.pixelsPerUnit);
}

bool BallView::hidden(int i) const
{
    return layout_.street && ballHidden(*layout_.street, balls_[static_cast<std::size_t>(3 * i)]);
}

bool BallView::ballPixel(int ball, QPointF& pixel) const
{
    if (ball < 0 || std::size_t(3 * ball + 2) >= balls_.size() || hidden(ball))
        return false;
    return camera_.project(ballAt(ball), size(), pixel);
}

void BallView::exposeEvent(QExposeEvent* e)
{
    QOpenGLWindow::exposeEvent(e);
    update();
}

} // namespace ab::ui
