// SPDX-License-Identifier: MIT
// The street's contacts between balls (core/street/street_pairs.cpp), worked by hand: two
// balls found inside each other are parted along their line of centres, half each and
// over-relaxed (point 4: 1.8 times the overlap, so the pair ends 0.8 times it apart), their
// centre of mass kept, while both fall as one projectile; the parting changes no velocity.
#include "core/street/street_engine.h"

#include <QtTest>

#include <cmath>

using ab::RunSpec;
using ab::SceneId;
using ab::State;
using Eigen::Vector3d;

class StreetPairs : public QObject {
    Q_OBJECT

private slots:
    void twoBallsInsideEachOtherArePartedPastTouchingAndFallAsOne()
    {
        RunSpec spec(SceneId::Street);
        spec.params.parseAssignment("n=2");
        spec.dt = 1.0 / 60.0; // the scene's step
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double r = 0.03, g = 9.82, dt = 1.0 / 60.0;
        const double overlap = 0.2 * r;
        // Two balls at rest 2 m above the road, side by side across it, a fifth of r inside
        // each other: nothing but the pair and gravity acts within the step.
        const double x = 20.0, y = layout.roadY(x) + 2.0;
        State start;
        start.resize(2);
        start.w.setZero(3, 2);
        start.p.col(0) = Vector3d(x, y, 0.0);
        start.p.col(1) = Vector3d(x, y, 2.0 * r - overlap);
        spec.init = start;
        auto sim = ab::makeSimulation(spec);
        State s = sim->start(), next;
        sim->step(s, next);

        // Parted along n = e_z by 1.8 overlap in all: 0.9 overlap each, 2 r + 0.8 overlap apart.
        const Vector3d d = next.p.col(1) - next.p.col(0);
        QVERIFY2(std::abs(d.z() - (2.0 * r + 0.8 * overlap)) < 1e-12, qPrintable(QString::number(d.z(), 'g', 17)));
        QVERIFY(std::abs(d.x()) < 1e-12 && std::abs(d.y()) < 1e-12);
        // The centre of mass falls from rest: y - g dt^2 / 2 (St4), across the road where it was.
        const Vector3d centre = 0.5 * (next.p.col(0) + next.p.col(1));
        const Vector3d expected(x, y - 0.5 * g * dt * dt, 0.5 * (2.0 * r - overlap));
        QVERIFY2((centre - expected).norm() < 1e-12, qPrintable(QString::number((centre - expected).norm(), 'g', 3)));
        // Parting moves positions only: both balls have gravity's velocity, -g dt, and no more.
        for (int i = 0; i < 2; ++i)
            QVERIFY((next.v.col(i) - Vector3d(0.0, -g * dt, 0.0)).norm() < 1e-12);
        QCOMPARE(next.impacts, 0LL); // nothing approached: no impulse
    }
};

QTEST_APPLESS_MAIN(StreetPairs)
#include "test_street_pairs.moc"
