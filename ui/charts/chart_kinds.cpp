// SPDX-License-Identifier: MIT
// The chart kinds: their keys (the contract's names for presets and `chart --chart`), the
// order the chart panel shows them in, and which ones a scene or a run has.
#include "motion_chart.h"

namespace ab::ui {

namespace {

constexpr std::pair<ChartKind, std::string_view> chartKeys[] = {
    {ChartKind::Position, "position"}, {ChartKind::Velocity, "velocity"},  {ChartKind::Energy, "energy"},
    {ChartKind::Momentum, "momentum"}, {ChartKind::Activity, "activity"},  {ChartKind::Difference, "difference"},
    {ChartKind::Spin, "spin"},         {ChartKind::FootRate, "foot-rate"}, {ChartKind::Speeds, "speeds"}};

} // namespace

const std::vector<ChartKind>& allChartKinds()
{
    // In the order the chart panel shows them: the ball's own motion (spin beside its
    // velocity), then what the whole scene conserves, then the street's flood.
    static const std::vector<ChartKind> kinds = {ChartKind::Position,   ChartKind::Velocity, ChartKind::Spin,
                                                 ChartKind::Energy,     ChartKind::Momentum, ChartKind::Activity,
                                                 ChartKind::Difference, ChartKind::FootRate, ChartKind::Speeds};
    return kinds;
}

ChartUnits chartUnitsOf(const ConservationMeter& meter)
{
    return ChartUnits{meter.perUnitMass(), meter.hasSpring(), meter.turns()};
}

ChartUnits chartUnitsOf(const ConservationMeter& meter, const RunSpec& spec)
{
    ChartUnits units = chartUnitsOf(meter);
    if (spec.scene == SceneId::Street) {
        units.streetBlocks = static_cast<int>(spec.params.integer("blocks"));
        units.energyMeanOver = static_cast<int>(spec.params.integer("n")); // as the status bar's E/m a ball
    }
    return units;
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
    case ChartKind::FootRate:
    case ChartKind::Speeds:
        return scene == SceneId::Street;
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
