// SPDX-License-Identifier: MIT
// The GL side of the 3D view (OpenGL 3.3 core): one instanced draw call ray-casts every
// ball as a sphere impostor, one more draws a comparison run's balls as translucent
// "ghosts" (the same impostors, blended, with a bright rim), one more lays the contact
// shadows on the floor, and a plain
// coloured-vertex program draws the floor, box, scale and trace. Every call here needs
// the view's context current; release() frees all GL objects before it goes away.
#pragma once

#include "scene_geometry.h"

#include <QColor>
#include <QMatrix4x4>
#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QSize>

#include <memory>
#include <vector>

namespace ab::ui {

struct RenderInputs {
    QSize viewport; // device pixels
    QMatrix4x4 view;
    QMatrix4x4 projection;
    float pixelsPerUnit = 1.0f; // at unit distance
    float radius = 1.0f;        // ball radius, world units
    float minPixels = 4.0f;     // smallest drawn ball radius on screen
    int selected = -1;
    float floorY = 0.0f;
    float fadeHeight = 1.0f;             // contact shadows fade out at this height
    QColor background{0xec, 0xf0, 0xf5}; // the clear colour (the window's theme)
    bool shadows = true;                 // contact cues on the floor plane (not on the street's slopes)
    bool cutaway = false;                // leave out the geometry's cut-away part (the street's near houses)
    // Balls whose centres lie beyond this x are not drawn: the street's balls that have left
    // the run at its open foot, parked there by the engine (core/street/street_census.h).
    float hideBeyondX = 3.0e38f;
    // The selected ball's path: a band this many pixels wide in its colour, with a pixel's
    // edge each side in a colour of the other lightness (it shows on dark asphalt and on
    // light concrete alike).
    float traceWidth = 3.0f;
};

class SceneRenderer : protected QOpenGLExtraFunctions {
public:
    SceneRenderer();
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    // Compiles the shaders and creates the buffers; false (with `error`) when it fails.
    bool initialize(QString& error);
    void release();
    bool ready() const { return ready_; }

    void setGeometry(const SceneGeometry& geometry);
    void setColours(const std::vector<unsigned>& rgb);
    void setBalls(const std::vector<float>& xyz);
    // The balls' orientations, kOrientationFloats per ball (ui/view/ball_orientation.h),
    // where the run's balls turn: each is drawn with a beach-ball pattern turned by its own.
    // Empty (or not one per ball): plain balls, as a run whose balls do not turn.
    void setOrientations(const std::vector<float>& q);
    // The comparison run's ball centres (empty: none), drawn in the balls' colours.
    void setGhosts(const std::vector<float>& xyz);
    // The selected ball's path through `points`, drawn as a band (RenderInputs::traceWidth).
    void setTrace(const std::vector<QVector3D>& points, const QColor& colour);
    void draw(const RenderInputs& in);

private:
    bool buildPrograms(QString& error);
    void setupInstanced(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& centres, bool withColours);
    void setupFlat(QOpenGLVertexArrayObject& vao, QOpenGLBuffer& buffer);
    void setupTrace();
    void setCommonUniforms(QOpenGLShaderProgram& program, const RenderInputs& in);
    // The ball program with its uniforms: the solid balls (`selected` ringed) or the ghosts.
    void useBallProgram(const RenderInputs& in, int selected, bool ghosts);
    void drawFlat(const RenderInputs& in);
    void drawTrace(const RenderInputs& in);

    bool ready_ = false;
    std::unique_ptr<QOpenGLShaderProgram> ballProgram_, shadowProgram_, flatProgram_, traceProgram_;
    QColor traceColour_, traceEdge_;
    QOpenGLVertexArrayObject ballVao_, ghostVao_, shadowVao_, flatVao_, traceVao_;
    QOpenGLBuffer corners_, positions_, ghostPositions_, colours_, orientations_, flat_, trace_;
    int orientationCount_ = 0; // balls with an orientation uploaded
    int balls_ = 0, ghosts_ = 0, floorVertices_ = 0, cutawayVertices_ = 0, lineVertices_ = 0, wallVertices_ = 0,
        traceVertices_ = 0;
};

} // namespace ab::ui
