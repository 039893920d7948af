// SPDX-License-Identifier: MIT
// What the window's 3D view and the animation export (ui/video/) both draw from, so a
// clip looks as the view does: the camera's framing of a scene, the renderer's inputs for
// a viewport, and the labels painted over the GL image (axis names, the height scale's
// numbers, the falling ball's height).
#pragma once

#include "orbit_camera.h"
#include "scene_geometry.h"
#include "scene_renderer.h"

#include "core/simulation.h"

#include <QFont>
#include <QPainter>

#include <functional>
#include <vector>

namespace ab::ui {

// Colour of each ball as 0xRRGGBB: fixed, distinct colours for one or two balls; for
// many, random bright hues drawn from the scene's seed (the report gives random colours).
std::vector<unsigned> ballColours(const RunSpec& spec, int balls);

// Frames the whole scene for a view of aspect `aspect` (width / height), seen from where
// the report's WebGL camera stands (the vertical scene from the side).
void frameSceneCamera(OrbitCamera& camera, const SceneGeometry& geometry, const SceneLayout& layout, float aspect);

// The smallest radius a ball is drawn with on a view `viewHeight` pixels high, times
// `scale` (lecture mode's presentation scale).
float smallestBallPixels(const SceneLayout& layout, int viewHeight, double scale);

// The street's foot as the renderer's float threshold: a ball whose float x is above it has
// left (street::hasLeft of that x read back as a double).
float footAsFloat(double xFoot);

// The renderer's inputs for a view `size` logical pixels large (viewport: the caller's
// device pixels), `selected` ringed when the scene has more than one ball; balls and
// marks `scale` times larger (lecture mode).
RenderInputs sceneRenderInputs(const OrbitCamera& camera, const SceneLayout& layout, QSize size, int selected,
                               const QColor& background, double scale = 1.0);

// How a label in `colour` is drawn over a view of `background`: a white halo over a light
// view, a black one over a dark view (white over black read as a pale box round grey text),
// and the text's colour moved in lightness until it stands 7:1 against its halo (WCAG's AAA
// for text: it is read from the back of a lecture hall).
struct LabelInk {
    QColor text, halo;
};
LabelInk labelInk(const QColor& colour, const QColor& background);

// Text in `colour` with a halo (labelInk), readable over any part of a scene of `background`.
void drawHaloText(QPainter& p, const QPointF& at, const QString& text, const QColor& colour, Qt::Alignment align,
                  const QColor& background = Qt::white);

// `text` along the bottom left of a view `size` large, in `colour` with a halo: on one line
// where it fits, else a line for each of its "; " parts, the font made smaller where even
// a part would not fit (lecture mode's large text in a narrow view).
void drawBottomHint(QPainter& p, QSize size, const QString& text, const QColor& colour,
                    const QColor& background = Qt::white);

// The geometry's labels and, in the vertical scene, the ball's height beside it, in `font`,
// over a view of `background`. A label whose point `hidden` says is behind something solid
// is not drawn.
void paintSceneLabels(QPainter& p, const OrbitCamera& camera, QSize size, const SceneGeometry& geometry,
                      const SceneLayout& layout, const std::vector<float>& balls, const QFont& font,
                      const QColor& background, const std::function<bool(const QVector3D&)>& hidden = {});

} // namespace ab::ui
