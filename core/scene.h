// SPDX-License-Identifier: MIT
// The four scenes of the report (its four stages), the two models and the integrators,
// each named once. Names here are the stable contract (shared/spec/contract.md).
#pragma once

#include "params.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ab {

enum class SceneId { Bounce1d, Box3d, TwoBalls, ManyBalls, Street };
enum class ModelKind { Report, Physical };
enum class Integrator { Euler, SymplecticEuler, Verlet, Rk4, Event, ImplicitEuler, ImplicitMidpoint };
// Where impacts are found: inside the step (time of impact solved, step split there) or,
// as the report does, only by looking at the state at the end of a step.
enum class ImpactMode { Located, StepEnd };
enum class Broadphase { Grid, AllPairs };

// One numbered equation of the report (or a textbook one the product adds), as the app
// shows it beside the stage.
struct Equation {
    std::string number;  // "2.3"
    std::string text;    // plain-text formula, e.g. "v1 = -k v0"
    std::string meaning; // one line
};

// Something a reader of the report must know: a typo in a printed equation and what the
// product implements instead, or a choice the report leaves open.
struct ReportNote {
    std::string where; // "eq 2.16"
    std::string text;
};

struct SceneInfo {
    SceneId id;
    std::string key; // contract id: bounce1d, box3d, two-balls, many-balls, street
    int stage = 0;   // 1..4, the report's order; 5 the street
    std::string title;
    std::string reportRef; // sections and appendices of the report
    std::string summary;   // two or three sentences for the stage navigator
    int axes = 3;          // 1: vertical axis only (bounce1d); 3: x, y, z
    int ballCount = 1;     // fixed count; 0 when the parameter `n` sets it
    std::vector<ParamSpec> params;
    // The report model's own step and run length, and the unit its time is counted in.
    double reportDt = 1.0;
    long long reportSteps = 0;
    std::string timeUnit;   // "step", "s" or "frame"
    std::string lengthUnit; // "m" or "unit"
    std::vector<Equation> equations;
    std::vector<ReportNote> notes;
    // Checks that involve several parameters (a start point inside the box, say);
    // throws InputError. Single values are checked against their spec before this runs.
    std::function<void(const ParamValues&)> crossCheck;

    ParamValues defaults() const { return ParamValues(&params); }
    // The parameter of that name in the table; nullptr when there is none.
    const ParamSpec* findParam(std::string_view name) const;
    // Every parameter's name, in table order (for "known: ..." and "did you mean").
    std::vector<std::string> paramKeys() const;
};

const std::vector<const SceneInfo*>& allScenes();
const SceneInfo& sceneInfo(SceneId id);
// nullptr when the key names no scene.
const SceneInfo* findScene(std::string_view key);

std::string_view modelKey(ModelKind m);
std::optional<ModelKind> parseModel(std::string_view key);
// Every model, in the order the front ends list them, with a few words and a sentence
// each: the window's model list and `list` read these.
const std::vector<ModelKind>& allModels();
std::string_view modelTitle(ModelKind m);   // "the report's own rules"
std::string_view modelSummary(ModelKind m); // one sentence on what the model is
std::string_view integratorKey(Integrator i);
std::optional<Integrator> parseIntegrator(std::string_view key);
std::string_view integratorTitle(Integrator i);
std::string_view impactModeKey(ImpactMode m);
std::optional<ImpactMode> parseImpactMode(std::string_view key);
std::string_view broadphaseKey(Broadphase b);
std::optional<Broadphase> parseBroadphase(std::string_view key);
const std::vector<Integrator>& allIntegrators();

} // namespace ab
