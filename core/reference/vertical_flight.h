// SPDX-License-Identifier: MIT
// Closed-form vertical flight (up positive) under gravity g and air drag, written out in
// vertical_flight.cpp with the derivation beside each formula. Used by the references of
// bounce1d (with or without drag), box3d and two-balls (without).
#pragma once

namespace ab::reference {

// Drag per unit mass: beta = b / m (1/time) for F = -b v, kappa = c / m (1/length) for
// F = -c |v| v. At most one of them may be non-zero (the sum has no closed form).
struct Drag {
    double beta = 0.0;
    double kappa = 0.0;
};

class VerticalFlight {
public:
    VerticalFlight(double g, Drag drag, double y0, double v0);

    // Height and velocity tau after the start.
    double height(double tau) const;
    double velocity(double tau) const;
    // The first tau > 0 at which the height comes down to `floor` (the flight starts at
    // or above it); infinite when it never does (g = 0 and not moving down).
    double landing(double floor) const;
    // The highest point of the flight.
    double apex() const;

private:
    double g_;
    Drag drag_;
    double y0_, v0_;
    double vt_ = 0.0;    // terminal speed: g / beta (linear) or sqrt(g / kappa) (quadratic)
    double tApex_ = 0.0; // quadratic drag: end of the rising phase

    double fallFrom(double y, double v, double tau, bool wantHeight) const;
};

} // namespace ab::reference
