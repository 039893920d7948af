// SPDX-License-Identifier: MIT
// Builders of the four scene descriptions; each lives in the file named after its scene.
#pragma once

#include "../scene.h"

namespace ab::scenes {

SceneInfo makeBounce1d();
SceneInfo makeBox3d();
SceneInfo makeTwoBalls();
SceneInfo makeManyBalls();
SceneInfo makeStreet();

// Short constructors for table rows, so each row reads as one line of the table.
ParamSpec real(std::string key, std::string symbol, std::string unit, double def, double min, double max,
               std::string equation, std::string meaning, unsigned models = BothModels);
ParamSpec integer(std::string key, std::string symbol, double def, double min, double max, std::string equation,
                  std::string meaning, unsigned models = BothModels);
ParamSpec vector(std::string key, std::string symbol, std::string unit, Eigen::Vector3d def, double min, double max,
                 std::string equation, std::string meaning, unsigned models = BothModels);
ParamSpec positive(ParamSpec spec); // marks the lower bound as exclusive

// Rotation rows of the physical model (spin_params.cpp): mu (also between the balls when
// `betweenBalls`), beta, inertia, the radius of a point-contact ball, and a start spin.
ParamSpec frictionParam(bool betweenBalls);
ParamSpec betaParam();
ParamSpec inertiaParam();
ParamSpec spinRadiusParam(const std::string& unit);
ParamSpec startSpinParam(const std::string& key, const std::string& unit, std::string meaning);

} // namespace ab::scenes
