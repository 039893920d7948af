// SPDX-License-Identifier: MIT
#include "scene.h"

#include "scenes/scene_tables.h"

#include <algorithm>
#include <array>
#include <utility>

namespace ab {

namespace scenes {

ParamSpec real(std::string key, std::string symbol, std::string unit, double def, double min, double max,
               std::string equation, std::string meaning, unsigned models)
{
    ParamSpec s;
    s.key = std::move(key);
    s.symbol = std::move(symbol);
    s.unit = std::move(unit);
    s.kind = ParamKind::Real;
    s.defaultValue = Eigen::Vector3d(def, 0.0, 0.0);
    s.min = min;
    s.max = max;
    s.equation = std::move(equation);
    s.meaning = std::move(meaning);
    s.models = models;
    return s;
}

ParamSpec integer(std::string key, std::string symbol, double def, double min, double max, std::string equation,
                  std::string meaning, unsigned models)
{
    ParamSpec s =
        real(std::move(key), std::move(symbol), "1", def, min, max, std::move(equation), std::move(meaning), models);
    s.kind = ParamKind::Integer;
    return s;
}

ParamSpec vector(std::string key, std::string symbol, std::string unit, Eigen::Vector3d def, double min, double max,
                 std::string equation, std::string meaning, unsigned models)
{
    ParamSpec s = real(std::move(key), std::move(symbol), std::move(unit), 0.0, min, max, std::move(equation),
                       std::move(meaning), models);
    s.kind = ParamKind::Vector;
    s.defaultValue = def;
    return s;
}

ParamSpec positive(ParamSpec spec)
{
    spec.minExclusive = true;
    return spec;
}

} // namespace scenes

const std::vector<const SceneInfo*>& allScenes()
{
    static const std::array<SceneInfo, 5> infos = {scenes::makeBounce1d(), scenes::makeBox3d(), scenes::makeTwoBalls(),
                                                   scenes::makeManyBalls(), scenes::makeStreet()};
    static const std::vector<const SceneInfo*> list = {&infos[0], &infos[1], &infos[2], &infos[3], &infos[4]};
    return list;
}

const ParamSpec* SceneInfo::findParam(std::string_view name) const
{
    const auto spec = std::find_if(params.begin(), params.end(), [&](const ParamSpec& s) { return s.key == name; });
    return spec == params.end() ? nullptr : &*spec;
}

std::vector<std::string> SceneInfo::paramKeys() const
{
    std::vector<std::string> keys;
    for (const ParamSpec& p : params)
        keys.push_back(p.key);
    return keys;
}

const SceneInfo& sceneInfo(SceneId id)
{
    for (const SceneInfo* s : allScenes())
        if (s->id == id)
            return *s;
    throw std::logic_error("scene id without a description");
}

const SceneInfo* findScene(std::string_view key)
{
    for (const SceneInfo* s : allScenes())
        if (s->key == key)
            return s;
    return nullptr;
}

namespace {

template <typename E, std::size_t N>
std::optional<E> parseKey(const std::array<std::pair<E, std::string_view>, N>& keys, std::string_view key)
{
    for (const auto& [value, name] : keys)
        if (name == key)
            return value;
    return std::nullopt;
}

template <typename E, std::size_t N>
std::string_view keyOf(const std::array<std::pair<E, std::string_view>, N>& keys, E value)
{
    for (const auto& [v, name] : keys)
        if (v == value)
            return name;
    throw std::logic_error("enum value without a key");
}

constexpr std::array<std::pair<ModelKind, std::string_view>, 2> modelKeys{
    {{ModelKind::Report, "report"}, {ModelKind::Physical, "physical"}}};
constexpr std::array<std::pair<ModelKind, std::string_view>, 2> modelTitles{
    {{ModelKind::Report, "the report's own rules"}, {ModelKind::Physical, "textbook rigid balls"}}};
constexpr std::array<std::pair<ModelKind, std::string_view>, 2> modelSummaries{
    {{ModelKind::Report, "the report's own discrete rules, bounce counters and all (one scheme per stage)"},
     {ModelKind::Physical, "textbook rigid-ball physics: momentum-conserving impulses, a physical rest rule"}}};
constexpr std::array<std::pair<Integrator, std::string_view>, 7> integratorKeys{{
    {Integrator::Euler, "euler"},
    {Integrator::SymplecticEuler, "symplectic-euler"},
    {Integrator::Verlet, "verlet"},
    {Integrator::Rk4, "rk4"},
    {Integrator::Event, "event"},
    {Integrator::ImplicitEuler, "implicit-euler"},
    {Integrator::ImplicitMidpoint, "implicit-midpoint"},
}};
constexpr std::array<std::pair<Integrator, std::string_view>, 7> integratorTitles{{
    {Integrator::Euler, "Explicit Euler"},
    {Integrator::SymplecticEuler, "Symplectic Euler"},
    {Integrator::Verlet, "Velocity Verlet"},
    {Integrator::Rk4, "Runge-Kutta 4"},
    {Integrator::Event, "Event-driven, exact"},
    {Integrator::ImplicitEuler, "Implicit Euler"},
    {Integrator::ImplicitMidpoint, "Implicit midpoint"},
}};
constexpr std::array<std::pair<ImpactMode, std::string_view>, 2> impactKeys{
    {{ImpactMode::Located, "located"}, {ImpactMode::StepEnd, "step-end"}}};
constexpr std::array<std::pair<Broadphase, std::string_view>, 2> broadphaseKeys{
    {{Broadphase::Grid, "grid"}, {Broadphase::AllPairs, "all-pairs"}}};

} // namespace

std::string_view modelKey(ModelKind m)
{
    return keyOf(modelKeys, m);
}
std::optional<ModelKind> parseModel(std::string_view key)
{
    return parseKey(modelKeys, key);
}
std::string_view modelTitle(ModelKind m)
{
    return keyOf(modelTitles, m);
}
std::string_view modelSummary(ModelKind m)
{
    return keyOf(modelSummaries, m);
}
std::string_view integratorKey(Integrator i)
{
    return keyOf(integratorKeys, i);
}
std::optional<Integrator> parseIntegrator(std::string_view key)
{
    return parseKey(integratorKeys, key);
}
std::string_view integratorTitle(Integrator i)
{
    return keyOf(integratorTitles, i);
}
std::string_view impactModeKey(ImpactMode m)
{
    return keyOf(impactKeys, m);
}
std::optional<ImpactMode> parseImpactMode(std::string_view key)
{
    return parseKey(impactKeys, key);
}
std::string_view broadphaseKey(Broadphase b)
{
    return keyOf(broadphaseKeys, b);
}
std::optional<Broadphase> parseBroadphase(std::string_view key)
{
    return parseKey(broadphaseKeys, key);
}

namespace {

// The values of a key table, in its order.
template <typename Value, std::size_t N>
std::vector<Value> valuesOf(const std::array<std::pair<Value, std::string_view>, N>& table)
{
    std::vector<Value> values;
    for (const auto& entry : table)
        values.push_back(entry.first);
    return values;
}

} // namespace

const std::vector<ModelKind>& allModels()
{
    static const std::vector<ModelKind> list = valuesOf(modelKeys);
    return list;
}

const std::vector<Integrator>& allIntegrators()
{
    static const std::vector<Integrator> list = valuesOf(integratorKeys);
    return list;
}

} // namespace ab
