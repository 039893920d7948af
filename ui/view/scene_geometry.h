// SPDX-License-Identifier: MIT
// The still parts of a scene, built once per layout on the CPU: the floor with its grid,
// the box (edges along the axes in the axes' colours, faint side walls), the height
// scale of the vertical scene, and the labels the view writes beside them.
#pragma once

#include "ui/charts/scene_layout.h"

#include <QColor>
#include <QString>
#include <QVector3D>

#include <vector>

namespace ab::ui {

struct FlatVertex {
    float x, y, z;
    float r, g, b, a;
};

struct SceneLabel {
    QVector3D at;
    QString text;
    QColor colour;
    bool above = false; // drawn just above its point (a line it names), else centred on it
};

struct SceneGeometry {
    std::vector<FlatVertex> floor; // opaque triangles
    // Opaque triangles that a cut-away view leaves out: the street's houses on the near
    // (+z) side, which hide the road from the side shot. Empty in the other stages.
    std::vector<FlatVertex> cutaway;
    std::vector<FlatVertex> lines; // grid, edges, scale
    std::vector<FlatVertex> walls; // translucent triangles, drawn last
    std::vector<SceneLabel> labels;
    QVector3D lo, hi;       // what the camera frames
    float arrowStep = 1.0f; // the report's arrow-key step: 2 units in a 100 box
};

SceneGeometry buildSceneGeometry(const SceneLayout& layout, const QString& lengthUnit);

} // namespace ab::ui
