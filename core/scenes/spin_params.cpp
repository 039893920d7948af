// SPDX-License-Identifier: MIT
// The rotation rows of the physical model's tables (docs/spin.md): the same constants, in
// the same words, in every stage that has them.
#include "scene_tables.h"

namespace ab::scenes {

ParamSpec frictionParam(bool betweenBalls)
{
    return real("mu", "mu", "1", 0.0, 0.0, 10.0, "Walton S10, rolling S2",
                betweenBalls ? "Coulomb friction at every contact, walls, floor and between the balls: an impact's "
                               "tangential impulse is at most mu times its normal one, and a ball sliding on the floor "
                               "feels mu m g at its contact point until it rolls (0: smooth)"
                             : "Coulomb friction at floor and walls: an impact's tangential impulse is at most mu "
                               "times its normal one, and a ball sliding on the floor feels mu m g at its contact "
                               "point until it rolls (0: smooth)",
                PhysicalModel);
}

ParamSpec betaParam()
{
    return real("beta", "beta", "1", 0.0, -1.0, 1.0, "Walton S9",
                "tangential restitution of the contact point's sliding velocity when friction holds it: -1 smooth "
                "(no friction at all), 0 the contact point stops, 1 it reverses (a superball)",
                PhysicalModel);
}

ParamSpec inertiaParam()
{
    return real("inertia", "q", "1", 0.4, 0.0, 2.0 / 3.0, "I = q m r^2",
                "moment of inertia as a fraction of m r^2: 2/5 a solid ball, 2/3 a hollow shell", PhysicalModel);
}

ParamSpec spinRadiusParam(const std::string& unit)
{
    return positive(real("r", "r", unit, 1.0, 0.0, 1e6, "I = q m r^2",
                         "radius of the ball: the lever arm of friction and the r of I = q m r^2 (for contact the "
                         "ball is a point, as in the report)",
                         PhysicalModel));
}

ParamSpec startSpinParam(const std::string& key, const std::string& unit, std::string meaning)
{
    return vector(key, key, unit, Eigen::Vector3d::Zero(), -1e6, 1e6, "free rotation: w constant in flight",
                  std::move(meaning), PhysicalModel);
}

} // namespace ab::scenes
