// SPDX-License-Identifier: MIT
#include "collision.h"

namespace ab::reference {

std::pair<double, double> headOnOutcome(double m1, double m2, double u1, double u2, double e)
{
    const double momentum = m1 * u1 + m2 * u2;
    const double approach = u1 - u2;
    return {(momentum - m2 * e * approach) / (m1 + m2), (momentum + m1 * e * approach) / (m1 + m2)};
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> obliqueOutcome(double m1, double m2, const Eigen::Vector3d& p1,
                                                           const Eigen::Vector3d& p2, const Eigen::Vector3d& u1,
                                                           const Eigen::Vector3d& u2, double e)
{
    const Eigen::Vector3d n = (p1 - p2).normalized();
    // Along the line of centres, ball 2 comes "from below": head-on with coordinates
    // measured along -n so that ball 1 approaches when u1n > u2n.
    const double u1n = -u1.dot(n), u2n = -u2.dot(n);
    const auto [v1n, v2n] = headOnOutcome(m1, m2, u1n, u2n, e);
    if (!(u1n > u2n)) // separating or at rest relative to each other: no collision
        return {u1, u2};
    return {u1 + (u1n - v1n) * n, u2 + (u2n - v2n) * n};
}

} // namespace ab::reference
