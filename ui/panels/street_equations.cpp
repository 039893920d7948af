// SPDX-License-Identifier: MIT
#include "street_equations.h"

#include "equation_rows.h"
#include "run_options_panel.h"

#include <cmath>
#include <numbers>

namespace ab::ui {

namespace {

QString num(double x)
{
    return QString::number(x, 'g', 3);
}

} // namespace

QString StreetEquations::html(const RunSpec& spec)
{
    if (spec.scene != SceneId::Street)
        return {};
    const ParamValues& v = spec.params;
    const double g = v.real("g"), theta = v.real("slope") * std::numbers::pi / 180.0, q = v.real("inertia");
    const double mu = v.real("mu"), length = v.real("block_length");
    const int blocks = static_cast<int>(v.integer("blocks"));
    QString out = QStringLiteral("<p><b>%1</b></p><table cellspacing='0' cellpadding='2'>")
                      .arg(tr("The street with these constants").toHtmlEscaped());
    // St3: rolling needs a friction force f = q m a (from I dw/dt = f r, a = r dw/dt), and
    // with St1's a that is f = m g sin(theta) q / (1 + q) <= mu m g cos(theta).
    const double needed = q * std::tan(theta) / (1.0 + q);
    const bool rolls = mu >= needed && mu > 0.0;
    // St1 (rolling): m a = m g sin(theta) - f and f = q m a give a = g sin(theta) / (1 + q).
    // St2 (sliding): a = g (sin(theta) - mu cos(theta)), friction mu m g cos(theta) uphill.
    const double a = rolls ? g * std::sin(theta) / (1.0 + q) : g * (std::sin(theta) - mu * std::cos(theta));
    out += equationRow(rolls ? QStringLiteral("St1") : QStringLiteral("St2"),
                       rolls ? QStringLiteral("a = g sin(theta) / (1 + q)")
                             : QStringLiteral("a = g (sin(theta) - mu cos(theta))"),
                       tr("down a block of %1 deg: a = %2 m/s\u00b2 (%3)")
                           .arg(num(v.real("slope")), num(a), rolls ? tr("rolling") : tr("sliding")));
    out += equationRow(QStringLiteral("St3"), QStringLiteral("mu >= q tan(theta) / (1 + q)"),
                       tr("rolling needs \u03bc \u2265 %1; here \u03bc = %2: a ball set down on a block %3")
                           .arg(num(needed), num(mu), rolls ? tr("rolls") : tr("slides")));
    // From rest at a block's top, uniform acceleration over its length L: v^2 = 2 a L.
    const double foot = std::sqrt(std::max(2.0 * a * length, 0.0));
    out += equationRow(
        QStringLiteral("St1-St2"), QStringLiteral("v = sqrt(2 a L)"),
        tr("from rest at a block's top, a ball reaches its foot at %1 m/s, %2 km/h").arg(num(foot), num(3.6 * foot)));
    // St4-St5: leaving a crossing's edge level at speed v, the ball flies x = v t, y = -g t^2 / 2
    // and meets the block below, y = -x tan(theta), when g t^2 / 2 = v t tan(theta):
    // t = 2 v tan(theta) / g, x = 2 v^2 tan(theta) / g.
    if (blocks > 1) {
        const double t = 2.0 * foot * std::tan(theta) / g, x = foot * t;
        out += equationRow(QStringLiteral("St4-St5"), QStringLiteral("x = 2 v\u00b2 tan(theta) / g"),
                           tr("leaving a crossing at that speed, a ball flies %1 s and lands %2 m down the next block")
                               .arg(num(t), num(x)));
    }
    // The street's whole drop H = B L sin(theta); g H per unit mass is what gravity gives.
    const double drop = blocks * length * std::sin(theta);
    out += equationRow(QStringLiteral("E"), QStringLiteral("g H = g B L sin(theta)"),
                       tr("the street drops %1 m: %2 J per kg, the speed \u221a(2 g H) = %3 m/s if none were lost")
                           .arg(num(drop), num(g * drop), num(std::sqrt(2.0 * g * drop))));
    out += QStringLiteral("</table><p><i>%1</i></p>").arg(RunOptionsPanel::noReportModelReason().toHtmlEscaped());
    return out;
}

} // namespace ab::ui
