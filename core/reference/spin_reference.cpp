// SPDX-License-Identifier: MIT
#include "spin_reference.h"

namespace ab::reference {

double rollStart(double q, double mu, double g, double v0)
{
    return q * v0 / ((1.0 + q) * mu * g); // S3
}

SlidingBall slidingBall(double q, double mu, double g, double v0, double t)
{
    const double ts = rollStart(q, mu, g, v0);
    if (t < ts) // S2: dv/dt = -mu g, r dw/dt = mu g / q
        return {v0 * t - 0.5 * mu * g * t * t, v0 - mu * g * t, mu * g * t / q};
    const double roll = v0 / (1.0 + q); // S4 with w = 0 at the start
    const double xs = v0 * ts - 0.5 * mu * g * ts * ts;
    return {xs + roll * (t - ts), roll, roll};
}

Bounce stickingBounce(double q, double beta, double u)
{
    // dv = -(1 + beta) q / (1 + q) u, r dw = (1 + beta) u / (1 + q) (S9, S13)
    return {u - (1.0 + beta) * q / (1.0 + q) * u, (1.0 + beta) * u / (1.0 + q)};
}

} // namespace ab::reference
