// SPDX-License-Identifier: MIT
#include "scene_renderer.h"

#include "ball_orientation.h"

#include <QVector2D>

#include <cstddef>

namespace ab::ui {

namespace {

// One triangle a ball: the equilateral triangle around the unit circle (its corners 2 from
// the centre, its sides 1 from it), which the shaders scale to the ball's outline. It has
// 30% more area than the square around the circle but half the triangles, and software
// OpenGL pays more for setting up a triangle than for the fragments of a ball a few pixels
// wide: at 10,000 balls one triangle a ball draws a frame in 8-23% less CPU time.
constexpr float triangleCorners[6] = {0.0f, 2.0f, -1.7320508f, -1.0f, 1.7320508f, -1.0f};
constexpr int cornerCount = 3;

// A corner of the trace's band (resources/shaders/trace.vert): the point it lies at, the
// other end of its segment, and the edge of the band it is on.
struct TraceCorner {
    float x, y, z;
    float ox, oy, oz;
    float side;
};

std::unique_ptr<QOpenGLShaderProgram> program(const char* name, QString& error, const char* fragment = nullptr)
{
    auto p = std::make_unique<QOpenGLShaderProgram>();
    const QString base = QStringLiteral(":/shaders/%1").arg(QString::fromLatin1(name));
    const QString frag = fragment ? QStringLiteral(":/shaders/%1").arg(QString::fromLatin1(fragment)) : base;
    if (!p->addShaderFromSourceFile(QOpenGLShader::Vertex, base + ".vert") ||
        !p->addShaderFromSourceFile(QOpenGLShader::Fragment, frag + ".frag") || !p->link()) {
        error = QStringLiteral("shader %1: %2").arg(QString::fromLatin1(name), p->log().trimmed());
        return nullptr;
    }
    return p;
}

} // namespace

SceneRenderer::SceneRenderer()
    : corners_(QOpenGLBuffer::VertexBuffer), positions_(QOpenGLBuffer::VertexBuffer),
      ghostPositions_(QOpenGLBuffer::VertexBuffer), colours_(QOpenGLBuffer::VertexBuffer),
      orientations_(QOpenGLBuffer::VertexBuffer), flat_(QOpenGLBuffer::VertexBuffer),
      trace_(QOpenGLBuffer::VertexBuffer)
{
}

SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::initialize(QString& error)
{
    initializeOpenGLFunctions();
    if (!buildPrograms(error))
        return false;
    for (QOpenGLBuffer* b : {&corners_, &positions_, &ghostPositions_, &colours_, &orientations_, &flat_, &trace_}) {
        b->create();
        b->setUsagePattern(QOpenGLBuffer::DynamicDraw);
    }
    corners_.bind();
    corners_.allocate(triangleCorners, sizeof triangleCorners);
    positions_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    ghostPositions_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    orientations_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    for (QOpenGLVertexArrayObject* vao : {&ballVao_, &ghostVao_, &shadowVao_, &flatVao_, &traceVao_})
        vao->create();
    setupInstanced(ballVao_, positions_, true);
    {
        // One orientation per ball, read only where the balls turn (enabled in draw()).
        QOpenGLVertexArrayObject::Binder bind(&ballVao_);
        orientations_.bind();
        glVertexAttribPointer(3, kOrientationFloats, GL_FLOAT, GL_FALSE, 0, nullptr);
        glVertexAttribDivisor(3, 1);
    }
    setupInstanced(ghostVao_, ghostPositions_, true);
    setupInstanced(shadowVao_, positions_, false);
    setupFlat(flatVao_, flat_);
    setupTrace();
    ready_ = true;
    return true;
}

bool SceneRenderer::buildPrograms(QString& error)
{
    ballProgram_ = program("ball", error);
    if (ballProgram_)
        shadowProgram_ = program("shadow", error);
    if (shadowProgram_)
        flatProgram_ = program("flat", error);
    if (flatProgram_)
        traceProgram_ = program("trace", error, "flat");
    return traceProgram_ != nullptr;
}

void SceneRenderer::setupInstanced(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& centres, bool withColours)
{
    QOpenGLVertexArrayObject::Binder bind(&vao);
    corners_.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    centres.bind();
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glVertexAttribDivisor(1, 1); // one centre per ball
    if (withColours) {
        colours_.bind();
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, nullptr);
        glVertexAttribDivisor(2, 1);
    }
}

void SceneRenderer::setupFlat(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& buffer)
{
    QOpenGLVertexArrayObject::Binder bind(&vao);
    buffer.bind();
    const auto stride = static_cast<GLsizei>(sizeof(FlatVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(FlatVertex, r)));
}

void SceneRenderer::setupTrace()
{
    // A corner: its point, its segment's other end, its edge of the band (trace.vert).
    QOpenGLVertexArrayObject::Binder bind(&traceVao_);
    trace_.bind();
    const auto stride = static_cast<GLsizei>(sizeof(TraceCorner));
    const std::pair<GLint, std::size_t> attributes[] = {
        {3, offsetof(TraceCorner, x)}, {3, offsetof(TraceCorner, ox)}, {1, offsetof(TraceCorner, side)}};
    for (GLuint k = 0; k < 3; ++k) {
        glEnableVertexAttribArray(k);
        glVertexAttribPointer(k, attributes[k].first, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<void*>(attributes[k].second));
    }
}

void SceneRenderer::release()
{
    ready_ = false;
    for (QOpenGLVertexArrayObject* vao : {&ballVao_, &ghostVao_, &shadowVao_, &flatVao_, &traceVao_})
        vao->destroy();
    for (QOpenGLBuffer* b : {&corners_, &positions_, &ghostPositions_, &colours_, &orientations_, &flat_, &trace_})
        b->destroy();
    ballProgram_.reset();
    shadowProgram_.reset();
    flatProgram_.reset();
    traceProgram_.reset();
}

void SceneRenderer::setGeometry(const SceneGeometry& g)
{
    std::vector<FlatVertex> all;
    all.reserve(g.floor.size() + g.cutaway.size() + g.lines.size() + g.walls.size());
    all.insert(all.end(), g.floor.begin(), g.floor.end());
    all.insert(all.end(), g.cutaway.begin(), g.cutaway.end());
    all.insert(all.end(), g.lines.begin(), g.lines.end());
    all.insert(all.end(), g.walls.begin(), g.walls.end());
    floorVertices_ = static_cast<int>(g.floor.size());
    cutawayVertices_ = static_cast<int>(g.cutaway.size());
    lineVertices_ = static_cast<int>(g.lines.size());
    wallVertices_ = static_cast<int>(g.walls.size());
    flat_.bind();
    flat_.allocate(all.data(), static_cast<int>(all.size() * sizeof(FlatVertex)));
}

void SceneRenderer::setColours(const std::vector<unsigned>& rgb)
{
    std::vector<unsigned char> rgba(4 * rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        rgba[4 * i] = static_cast<unsigned char>(rgb[i] >> 16);
        rgba[4 * i + 1] = static_cast<unsigned char>(rgb[i] >> 8);
        rgba[4 * i + 2] = static_cast<unsigned char>(rgb[i]);
        rgba[4 * i + 3] = 255;
    }
    colours_.bind();
    colours_.allocate(rgba.data(), static_cast<int>(rgba.size()));
}

void SceneRenderer::setBalls(const std::vector<float>& xyz)
{
    balls_ = static_cast<int>(xyz.size() / 3);
    positions_.bind();
    positions_.allocate(xyz.data(), static_cast<int>(xyz.size() * sizeof(float)));
}

void SceneRenderer::setOrientations(const std::vector<float>& q)
{
    orientationCount_ = static_cast<int>(q.size() / kOrientationFloats);
    if (orientationCount_ == 0)
        return;
    orientations_.bind();
    orientations_.allocate(q.data(), static_cast<int>(q.size() * sizeof(float)));
}

void SceneRenderer::setGhosts(const std::vector<float>& xyz)
{
    ghosts_ = static_cast<int>(xyz.size() / 3);
    ghostPositions_.bind();
    ghostPositions_.allocate(xyz.data(), static_cast<int>(xyz.size() * sizeof(float)));
}

void SceneRenderer::setTrace(const std::vector<QVector3D>& points, const QColor& colour)
{
    // Two triangles a segment (trace.vert): corners A and C on one edge of the band, B and D
    // on the other; a corner at the segment's far end sees the segment reversed, so its side
    // is negated to stay on the same edge.
    std::vector<TraceCorner> v;
    v.reserve(points.size() > 1 ? 6 * (points.size() - 1) : 0);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const QVector3D& p = points[i - 1];
        const QVector3D& q = points[i];
        if (p == q)
            continue; // no direction: nothing to draw
        const TraceCorner a{p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), 1.0f};
        const TraceCorner b{p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), -1.0f};
        const TraceCorner c{q.x(), q.y(), q.z(), p.x(), p.y(), p.z(), -1.0f};
        const TraceCorner d{q.x(), q.y(), q.z(), p.x(), p.y(), p.z(), 1.0f};
        v.insert(v.end(), {a, c, d, a, d, b});
    }
    traceColour_ = colour;
    // The edge in white beside a dark path, in near-black beside a light one.
    traceEdge_ = colour.lightnessF() < 0.55 ? QColor(Qt::white) : QColor(0x1a, 0x1a, 0x1a);
    traceVertices_ = static_cast<int>(v.size());
    trace_.bind();
    trace_.allocate(v.data(), static_cast<int>(v.size() * sizeof(TraceCorner)));
}

void SceneRenderer::setCommonUniforms(QOpenGLShaderProgram& p, const RenderInputs& in)
{
    p.bind();
    p.setUniformValue("view", in.view);
    p.setUniformValue("projection", in.projection);
    p.setUniformValue("radius", in.radius);
    p.setUniformValue("minPixels", in.minPixels);
    p.setUniformValue("pixelsPerUnit", in.pixelsPerUnit);
    p.setUniformValue("hideBeyondX", in.hideBeyondX);
}

void SceneRenderer::draw(const RenderInputs& in)
{
    glViewport(0, 0, in.viewport.width(), in.viewport.height());
    glClearColor(in.background.redF(), in.background.greenF(), in.background.blueF(), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!ready_)
        return;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    drawFlat(in); // floor and lines

    if (balls_ > 0) {
        useBallProgram(in, in.selected, false);
        ballVao_.bind();
        // The pattern only with an orientation for every ball: the buffer is never read past its end.
        const bool pattern = orientationCount_ == balls_;
        ballProgram_->setUniformValue("pattern", pattern ? 1 : 0);
        if (pattern)
            glEnableVertexAttribArray(3);
        else
            glDisableVertexAttribArray(3);
        glDrawArraysInstanced(GL_TRIANGLES, 0, cornerCount, balls_); // every ball in one call
    }
    if (balls_ > 0 && in.shadows) {
        // The floor cues after the balls: where a ball hides the floor, the depth test
        // drops the cue's fragments before they are shaded (the cue writes no depth of its
        // own, so the test can run first), which matters for a pile of thousands of balls
        // under software OpenGL. What is seen is the same as drawing them first.
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        setCommonUniforms(*shadowProgram_, in);
        shadowProgram_->setUniformValue("floorY", in.floorY);
        shadowProgram_->setUniformValue("fadeHeight", in.fadeHeight);
        shadowVao_.bind();
        glDrawArraysInstanced(GL_TRIANGLES, 0, cornerCount, balls_);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    if (ghosts_ > 0) {
        // After the solid balls, blended and without writing depth: a ghost in front of a
        // ball tints it, one behind it is hidden by it, and ghosts never hide each other.
        useBallProgram(in, -1, true);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        ghostVao_.bind();
        glDrawArraysInstanced(GL_TRIANGLES, 0, cornerCount, ghosts_); // every ghost in one call
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    flatProgram_->bind();
    flatProgram_->setUniformValue("viewProjection", in.projection * in.view);
    if (wallVertices_ > 0) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        flatVao_.bind();
        glDrawArrays(GL_TRIANGLES, floorVertices_ + cutawayVertices_ + lineVertices_, wallVertices_);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    flatVao_.release();
    flatProgram_->release();
    // After the translucent walls, which write no depth: the path is drawn in its own colours
    // (a wall's tint would fall on the edge, which writes no depth either, and not the path).
    drawTrace(in);
}

void SceneRenderer::drawTrace(const RenderInputs& in)
{
    if (traceVertices_ == 0)
        return;
    traceProgram_->bind();
    traceProgram_->setUniformValue("viewProjection", in.projection * in.view);
    traceProgram_->setUniformValue("viewport", QVector2D(float(in.viewport.width()), float(in.viewport.height())));
    traceVao_.bind();
    // The whole edge first, a pixel wider each side, tested against the scene but writing no
    // depth; then the whole path over it. So no part of the path hides under the edge of
    // another part nearer the eye (a ball dropping towards the eye draws its path over
    // itself), and the scene in front still hides both.
    const auto rgba = [](const QColor& c) { return QVector4D(c.redF(), c.greenF(), c.blueF(), 1.0f); };
    traceProgram_->setUniformValue("width", in.traceWidth + 2.0f);
    traceProgram_->setUniformValue("colour", rgba(traceEdge_));
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_TRIANGLES, 0, traceVertices_);
    glDepthMask(GL_TRUE);
    traceProgram_->setUniformValue("width", in.traceWidth);
    traceProgram_->setUniformValue("colour", rgba(traceColour_));
    glDrawArrays(GL_TRIANGLES, 0, traceVertices_);
    traceVao_.release();
    traceProgram_->release();
}

void SceneRenderer::useBallProgram(const RenderInputs& in, int selected, bool ghosts)
{
    setCommonUniforms(*ballProgram_, in);
    ballProgram_->setUniformValue("selected", selected);
    ballProgram_->setUniformValue("depthTerms", QVector2D(in.projection(2, 2), in.projection(2, 3)));
    ballProgram_->setUniformValue("lightDir", QVector3D(-0.4f, 0.7f, 0.75f).normalized());
    ballProgram_->setUniformValue("ghost", ghosts ? 1 : 0);
    ballProgram_->setUniformValue("pattern", 0); // the ghosts stay plain
    if (ghosts) // a little larger than the ball: a ghost where the ball is still shows, as a ring
    {
        ballProgram_->setUniformValue("radius", in.radius * 1.3f);
        ballProgram_->setUniformValue("minPixels", in.minPixels * 1.3f);
    }
}

void SceneRenderer::drawFlat(const RenderInputs& in)
{
    flatProgram_->bind();
    flatProgram_->setUniformValue("viewProjection", in.projection * in.view);
    flatVao_.bind();
    // The floor sits a little behind its grid lines and the shadows, so they never flicker.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, floorVertices_ + (in.cutaway ? 0 : cutawayVertices_));
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDrawArrays(GL_LINES, floorVertices_ + cutawayVertices_, lineVertices_);
}

} // namespace ab::ui
