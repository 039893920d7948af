// SPDX-License-Identifier: MIT
#include "spin_equations.h"

#include "equation_rows.h"

#include "core/diagnostics/conservation.h"
#include "core/physical/physical_simulation.h"
#include "core/physical/rolling.h"
#include "ui/i18n/core_text.h"

#include <cmath>
#include <limits>

namespace ab::ui {

namespace {

// The scenes whose balls meet each other (impacts between two balls, restitution e).
bool manyBalls(SceneId scene)
{
    return scene == SceneId::TwoBalls || scene == SceneId::ManyBalls || scene == SceneId::Street;
}

QString num(double x)
{
    return QString::number(x, 'g', 4);
}

struct Units {
    QString length, time;
};

Units unitsOf(const RunSpec& spec)
{
    const SceneInfo& info = sceneInfo(spec.scene);
    return {coreText(info.lengthUnit), coreText(info.timeUnit)};
}

} // namespace

QString SpinEquations::html(const Simulation& sim)
{
    const RunSpec& spec = sim.spec();
    if (spec.model == ModelKind::Report)
        return reportNote(spec);
    if (!ballsTurn(spec))
        return {};
    QString out = QStringLiteral("<p><b>%1</b></p><table cellspacing='0' cellpadding='2'>")
                      .arg(tr("Spin: balls that turn (physical model)").toHtmlEscaped());
    out += inertiaRow(spec);
    if (spec.scene == SceneId::Bounce1d) {
        // The ball moves on the vertical: its contact point never slides, and the floor's
        // normal force has no lever on a spin about the vertical.
        out +=
            equationRow(QStringLiteral("S13"), QStringLiteral("\u03c9 = w0"),
                        tr("the ball spins about the vertical at %1 rad/%2 for the whole run: the floor cannot change "
                           "that spin")
                            .arg(num(spec.params.real("w0")), unitsOf(spec).time));
        return out + QStringLiteral("</table>");
    }
    out += equationRow(QStringLiteral("S1"), QStringLiteral("u = v_t \u2212 r \u03c9 \u00d7 n"),
                       tr("the slip of the contact point along a wall of inward normal n; u = 0: the ball rolls"));
    if (!roughContacts(spec.params)) {
        out += equationRow(QStringLiteral("S9"), QStringLiteral("P_t = 0"),
                           tr("smooth contacts (\u03bc = 0 or \u03b2 = −1): no impulse along a wall, so every spin "
                              "stays as it started"));
        return out + QStringLiteral("</table>");
    }
    out += floorRows(sim);
    out += impactRows(spec);
    return out + QStringLiteral("</table>");
}

QString SpinEquations::reportNote(const RunSpec& spec)
{
    // The constants of rotation are kept while the report model runs; say where they act.
    RunSpec physical(spec.scene);
    physical.params = spec.params;
    physical.model = ModelKind::Physical;
    if (!ballsTurn(physical))
        return {};
    return QStringLiteral("<p><b>%1</b></p><p>%2</p>")
        .arg(tr("Spin").toHtmlEscaped(),
             tr("The report's model has no rotation: its balls never turn, so friction (\u03bc, \u03b2) and the "
                "start spin act in the physical model only. Choose the physical model to see them.")
                 .toHtmlEscaped());
}

QString SpinEquations::inertiaRow(const RunSpec& spec)
{
    const ParamValues& v = spec.params;
    const Units u = unitsOf(spec);
    const double q = v.real("inertia"), r = v.real("r");
    const QString formula = QStringLiteral("I = q m r\u00b2");
    if (spec.scene == SceneId::ManyBalls || spec.scene == SceneId::Street) // equal balls, per unit mass
        return equationRow(
            QStringLiteral("I"), QStringLiteral("I/m = q r\u00b2"),
            tr("per unit mass: %1 \u00d7 (%2 %3)\u00b2 = %4 %3\u00b2").arg(num(q), num(r), u.length, num(q * r * r)));
    if (spec.scene == SceneId::TwoBalls) {
        const double m1 = v.real("m1"), m2 = v.real("m2");
        return equationRow(QStringLiteral("I"), formula,
                           tr("q = %1, r = %2 %3: I1 = %4 kg %3\u00b2, I2 = %5 kg %3\u00b2")
                               .arg(num(q), num(r), u.length, num(q * m1 * r * r), num(q * m2 * r * r)));
    }
    const double m = v.indexOf("m") ? v.real("m") : 1.0;
    return equationRow(QStringLiteral("I"), formula,
                       tr("%1 \u00d7 %2 kg \u00d7 (%3 %4)\u00b2 = %5 kg %4\u00b2")
                           .arg(num(q), num(m), num(r), u.length, num(q * m * r * r)));
}

QString SpinEquations::floorRows(const Simulation& sim)
{
    const RunSpec& spec = sim.spec();
    const ParamValues& v = spec.params;
    const Units u = unitsOf(spec);
    const double mu = v.real("mu"), g = v.real("g");
    if (!(g > 0.0))
        return {};
    // S2: the slip keeps its direction and shrinks at (1 + 1/q) mu g.
    QString out =
        equationRow(QStringLiteral("S2"),
                    QStringLiteral("dv/dt = \u2212\u03bc g u/|u|,  d\u03c9/dt = \u03bc g (n \u00d7 u/|u|)/(q r)"),
                    tr("sliding on the floor: \u03bc g = %1 %2/%3\u00b2 slows the centre and spins the ball up")
                        .arg(num(mu * g), u.length, u.time));
    QString stStart = tr("the time a ball sliding at slip |u| takes to roll");
    QString rolling = tr("the rolling state: the angular momentum about the contact point is kept; a ball "
                         "without spin rolls on at 1/(1 + q) of its speed (5/7 for a solid ball)");
    // A lone ball that starts on the floor: when it rolls, and how fast, for this start.
    const physical::World* world = physical::worldOf(sim);
    if (world && world->balls() == 1 && spec.scene == SceneId::Box3d) {
        const State s = sim.start();
        const Eigen::Vector3d p = s.p.col(0), vel = s.v.col(0), w = s.spin(0);
        const physical::Wall* floor = nullptr;
        for (const physical::Wall& wall : world->walls)
            if (world->supports(wall) && p[wall.axis] == wall.position && vel[wall.axis] == 0.0)
                floor = &wall;
        const double tStar =
            floor ? physical::rollTime(*world, 0, vel, w, floor) : std::numeric_limits<double>::infinity();
        if (floor && std::isfinite(tStar) && tStar > 0.0) {
            Eigen::Vector3d v1 = vel, w1 = w;
            physical::roll(*world, *floor, v1, w1); // S4 from the start: friction keeps m r n x v + I w
            stStart = tr("this start slides for t* = %1 %2").arg(num(tStar), u.time);
            rolling = tr("then it rolls at %1 %2/%3 (%4 of its start speed of %5 %2/%3), r \u03c9 = v")
                          .arg(num(v1.norm()), u.length, u.time, num(v1.norm() / vel.norm()), num(vel.norm()));
        }
    }
    out += equationRow(QStringLiteral("S3"), QStringLiteral("t* = q |u| / ((1 + q) \u03bc g)"), stStart);
    out += equationRow(QStringLiteral("S4"), QStringLiteral("v' = (v_t + q r \u03c9 \u00d7 n) / (1 + q)"), rolling);
    return out;
}

QString SpinEquations::impactRows(const RunSpec& spec)
{
    const ParamValues& v = spec.params;
    const double beta = v.real("beta"), mu = v.real("mu");
    const QString sticks = beta == 0.0
                               ? tr("an impact that sticks: the contact point stops (\u03b2 = 0)")
                               : tr("an impact that sticks: the slip u becomes \u2212\u03b2 u = %1 u (\u03b2 = %2)")
                                     .arg(num(-beta), num(beta));
    QString out =
        equationRow(QStringLiteral("S9"), QStringLiteral("P_t = \u2212(1 + \u03b2) m* u,  m* = q m/(1 + q)"), sticks);
    out += equationRow(QStringLiteral("S10"), QStringLiteral("|P_t| = \u03bc P_n"),
                       tr("an impact that slides: at most \u03bc = %1 times the normal impulse (Walton: the smaller of "
                          "S9 and S10)")
                           .arg(num(mu)));
    if (manyBalls(spec.scene))
        out += equationRow(
            QStringLiteral("S11-S12"),
            QStringLiteral("\u0394v_i = P_t/m_i,  \u0394v_j = \u2212P_t/m_j,  \u0394\u03c9 = \u2212r n \u00d7 "
                           "(\u00b1P_t)/I"),
            tr("between two balls: their momentum is kept and both spins change in the same sense"));
    out += equationRow(QStringLiteral("S13"), QStringLiteral("m r n \u00d7 v' + I \u03c9' = m r n \u00d7 v + I \u03c9"),
                       tr("at a wall or the floor the angular momentum about the contact point is kept"));
    const char* restitution = manyBalls(spec.scene) ? "e" : "k";
    if (v.indexOf(restitution) && v.real(restitution) == 1.0 && beta == 1.0)
        out += equationRow(QStringLiteral("S9"), QStringLiteral("|u'| = |u|"),
                           tr("%1 = 1 and \u03b2 = 1: an impact that sticks loses no energy (a superball)")
                               .arg(QString::fromLatin1(restitution)));
    return out;
}

} // namespace ab::ui
