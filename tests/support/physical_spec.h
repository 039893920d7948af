// SPDX-License-Identifier: MIT
// The physical model's run of a scene with a given integrator, step and impact mode, its
// constants set from --set style assignments: the spec most physical-model tests start from.
#pragma once

#include "support/sim_helpers.h"

#include <QStringList>

namespace testing {

inline ab::RunSpec physical(ab::SceneId scene, ab::Integrator integrator, double dt,
                            const QStringList& assignments = {}, ab::ImpactMode impacts = ab::ImpactMode::Located)
{
    ab::RunSpec s = spec(scene, {}, ab::ModelKind::Physical);
    for (const QString& a : assignments)
        s.params.parseAssignment(a.toStdString());
    s.integrator = integrator;
    s.impacts = impacts;
    s.dt = dt;
    return s;
}

} // namespace testing
