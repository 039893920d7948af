// SPDX-License-Identifier: MIT
#include "finding.h"

#include "../params.h"

namespace ab::diagnostics {

namespace {

std::string num(double x)
{
    return formatSignificant(x, 3);
}

} // namespace

std::string remedyText(const Finding& f)
{
    switch (f.remedy) {
    case Remedy::None:
        return {};
    case Remedy::ReportSmallerDt:
        return "the report's own rule; a smaller --dt shrinks it, --model physical avoids it";
    case Remedy::ReportPhysical:
        return "the report's own rule; --model physical avoids it";
    case Remedy::ReportMomentum:
        return "the report's own rule; --model physical conserves momentum";
    case Remedy::ReportOnePerFrame:
        return "the report's own rule, one update per frame; --model physical avoids it";
    case Remedy::ReportStepEnd:
        return "the report finds impacts only at the end of a step; a smaller --dt shrinks it";
    case Remedy::SpringEuler:
        return "explicit Euler gains energy at every step on a spring (dt omega0 = " + num(f.dtOmega) +
               "): use symplectic-euler, verlet, rk4 or implicit-euler";
    case Remedy::SpringLimit:
        return "dt omega0 = " + num(f.dtOmega) + " and " + std::string(integratorKey(f.integrator)) +
               " is stable only below " + num(f.limit) + ": use --dt below " + num(f.dtLimit) + " or implicit-euler";
    case Remedy::EulerAddsEnergy:
        return "explicit Euler adds energy at every step: use symplectic-euler, verlet or event";
    case Remedy::LocatedOrSmallerDt:
        return "use --impacts located or a smaller --dt";
    case Remedy::SmallerDt:
        return "use a smaller --dt";
    case Remedy::StreetContacts:
        return "the street's substeps follow its fastest ball, so a smaller --dt does not shorten them; this is "
               "what its contact passes left where balls press on each other, most in a pile several balls deep: "
               "fewer balls (a smaller n) pile less deep";
    }
    return {};
}

} // namespace ab::diagnostics
