// SPDX-License-Identifier: MIT
// Closed forms of the rough-sphere model (docs/spin.md) that the tests and the accuracy
// figures hold the physical model to. A ball of I = q m r^2 on a floor with Coulomb
// friction mu under gravity g; x along its motion, r w the spin in the rolling sense
// (r w = v when it rolls).
#pragma once

namespace ab::reference {

// The moment a ball set down sliding at v0 without spin starts to roll:
// t* = q v0 / ((1 + q) mu g) (S3 with |u| = v0, N/m = g).
double rollStart(double q, double mu, double g, double v0);

struct SlidingBall {
    double x = 0.0;  // distance from the start
    double v = 0.0;  // speed of the centre
    double rw = 0.0; // r w, rolling sense
};

// The ball at time t: sliding, v = v0 - mu g t, r w = mu g t / q (S2 integrated), until
// t*; then rolling at v0 / (1 + q) with r w = v (S4).
SlidingBall slidingBall(double q, double mu, double g, double v0, double t);

struct Bounce {
    double vt = 0.0; // tangential speed after, along the incoming one
    double rw = 0.0; // r w after, rolling sense
};

// A floor impact at incoming tangential speed u without spin, with enough friction to
// stick: the contact point's speed u becomes -beta u (S9), the centre's
// u (1 - q beta) / (1 + q), and r w = (1 + beta) u / (1 + q). For beta = 1 (e = 1 keeps
// the energy): u (1 - q) / (1 + q) and 2 u / (1 + q).
Bounce stickingBounce(double q, double beta, double u);

} // namespace ab::reference
