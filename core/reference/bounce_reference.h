// SPDX-License-Identifier: MIT
// Exact motion of the scenes' physical model where it has a closed form, for tests and
// the accuracy study:
//  - BounceReference: a ball bouncing on a floor (bounce1d; the height in box3d and
//    two-balls), with or without drag, its Zeno series summed to the accumulation time.
//  - WallAxisReference: free motion along one horizontal axis between two walls.
#pragma once

#include "vertical_flight.h"

#include <limits>
#include <vector>

namespace ab::reference {

class BounceReference {
public:
    // From height y0 and velocity v0 (up positive) at t = 0 over a floor at `floor` with
    // restitution k. Flights with drag are built up to `horizon`; without drag the
    // motion is closed-form for all t.
    BounceReference(double g, double k, double y0, double v0, double floor = 0.0, Drag drag = {},
                    double horizon = std::numeric_limits<double>::infinity());

    double height(double t) const;
    double velocity(double t) const;
    // Accumulation (Zeno) time after which the ball rests on the floor; infinite when it
    // never rests (k = 1, or g = 0 and it flies off). Without drag and starting from rest
    // it is t1 (1 + k) / (1 - k), t1 the time of the first impact.
    double restTime() const { return tRest_; }
    // Times of the impacts in (0, tEnd], as many as double precision tells apart.
    std::vector<double> impactTimes(double tEnd) const;
    double maxHeight() const;

private:
    struct Flight {
        double t0;
        VerticalFlight flight;
    };
    double g_, k_, floor_;
    std::vector<Flight> flights_;
    // After the last flight: drag-free bounces launched at tTail_ with speed uTail_, each
    // k times the last (the tail of the series, where drag no longer matters).
    double tTail_ = std::numeric_limits<double>::infinity();
    double uTail_ = 0.0;
    double tRest_ = std::numeric_limits<double>::infinity();

    // Where the last search of the tail ended: samples come in time order, so the next
    // search starts there (a cache only; results do not depend on it; not thread-safe).
    mutable long long hint_ = 0;

    double tailLaunch(double n) const;
    long long tailBounce(double t) const;
};

class WallAxisReference {
public:
    // Position x0, velocity v0 at t = 0 between walls at lo and hi (lo <= x0 <= hi) with
    // restitutions kLo and kHi; no force along the axis. Hits are listed up to `horizon`.
    WallAxisReference(double x0, double v0, double lo, double hi, double kLo, double kHi, double horizon);

    double position(double t) const;
    double velocity(double t) const;
    // Wall hits in (0, tEnd]; with `hiOnly` only those at hi.
    std::vector<double> impactTimes(double tEnd, bool hiOnly = false, bool loOnly = false) const;

private:
    struct Leg {
        double t0, x0, v;
        bool endsAtHi;
    };
    std::vector<Leg> legs_;
    const Leg& legAt(double t) const;
};

} // namespace ab::reference
