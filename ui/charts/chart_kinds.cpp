// SPDX-License-Identifier: MIT
// The chart kinds: their keys (the contract's names for presets and `chart --chart`), the
// order the chart panel shows them in, and which ones a scene or a run has.
#include "motion_chart.h"

namespace ab::ui {

namespace {

constexpr std::pair<ChartKind, std::string_view> chartKeys[] = {
    {ChartKind::Position, "position"}, {ChartKind::Velocity, "velocity"}, {ChartKind::Energy, "energy"},
    {ChartKind::Momentum, "momentum"}, {ChartKind::Activity, "activity"}, {ChartKind::Difference, "difference"},
    {ChartKind::Spin, "spin"}};

} // namespace

const std::vector<ChartKind>& allChartKinds()
{
    // In the order the chart panel shows them: the ball's own motion (spin beside its
    // velocity), then what the whole scene conserves.
    static const std::vector<ChartKind> kinds = {ChartKind::Position,  ChartKind::Velocity, ChartKind::Spin,
                                                 ChartKind::Energy,    ChartKind::Momentum, ChartKind::Activity,
                                                 ChartKind::Difference};
    return kinds;
}

ChartUnits chartUnitsOf(const ConservationMeter& meter)
{
    return ChartUnits{meter.perUnitMass(), meter.hasSpring(), meter.turns()};
}

bool chartApplies(ChartKind kind, SceneId scene, const ChartUnits& units)
{
    return chartApplies(kind, scene) && (kind != ChartKind::Spin || units.spins);
}

bool chartApplies(ChartKind kind, const RunSpec& spec)
{
    ChartUnits units;
    units.spins = ballsTurn(spec);
    return chartApplies(kind, spec.scene, units);
}

bool chartApplies(ChartKind kind, SceneId scene)
{
    switch (kind) {
    case ChartKind::Momentum:
        return scene == SceneId::TwoBalls || scene == SceneId::ManyBalls;
    case ChartKind::Activity:
        return scene == SceneId::ManyBalls;
    default:
        return true;
    }
}

bool differenceDrawable(bool comparing, bool closedForm)
{
    return comparing || closedForm;
}

std::string_view chartKey(ChartKind kind)
{
    for (const auto& [k, key] : chartKeys)
        if (k == kind)
            return key;
    throw std::logic_error("chart kind without a key");
}

std::optional<ChartKind> parseChartKind(std::string_view key)
{
    for (const auto& [k, name] : chartKeys)
        if (name == key)
            return k;
    return std::nullopt;
}

} // namespace ab::ui
