// SPDX-License-Identifier: MIT
// The exact motion of a scene's physical model, where it has a closed form: bounce1d
// without drag or with linear or quadratic drag; box3d without drag or friction (the
// axes separate: a bounce on y, free motion between two walls on x and z); two-balls in
// the symmetric head-on meeting (the report's default), where the other ball acts on
// each as a wall at the mid-plane with restitution e. The accuracy study and the tests
// compare runs with it.
#pragma once

#include "../simulation.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace ab::reference {

class Reference {
public:
    virtual ~Reference() = default;

    int balls() const { return static_cast<int>(mass_.size()); }
    virtual Eigen::Vector3d position(int ball, double t) const = 0;
    virtual Eigen::Vector3d velocity(int ball, double t) const = 0;
    // Every impact (floor, walls, the pair) in (0, tEnd], in time order, as far as double
    // precision tells them apart. Simultaneous impacts of two balls are listed twice.
    virtual std::vector<double> impactTimes(double tEnd) const = 0;
    // The length a relative error is measured against (start height, box side).
    virtual double lengthScale() const = 0;
    // One line naming the closed form, for tables and charts.
    virtual std::string description() const = 0;

    // Kinetic plus potential energy (zero at y = 0) of every ball.
    double energy(double t) const;

protected:
    Reference(std::vector<double> mass, double g) : mass_(std::move(mass)), g_(g) {}

    std::vector<double> mass_;
    double g_;
};

// The reference for the spec's scene and parameters, with events listed up to `horizon`.
// InputError naming the parameter when no closed form covers them.
std::unique_ptr<Reference> makeReference(const RunSpec& spec, double horizon);

} // namespace ab::reference
