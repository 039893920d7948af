// SPDX-License-Identifier: MIT
// Presets: a scene with its model, integrator, step, parameters and view choices as a
// small versioned JSON file. Read strictly (every error names the field), written
// atomically. Built-in presets ship inside the program and are found by name.
#pragma once

#include "../scene.h"
#include "../simulation.h"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ab {

// What the app remembers of its view; the CLI ignores it.
struct PresetView {
    std::optional<double> cameraYaw;      // degrees
    std::optional<double> cameraPitch;    // degrees
    std::optional<double> cameraDistance; // scene length units
    std::optional<Eigen::Vector3d> cameraTarget;
    std::vector<std::string> charts; // chart keys, e.g. "position", "velocity", "energy"
    std::optional<int> selectedBall;
    // A second run of the same scene and start, computed another way, drawn beside the
    // first (ghosted in the 3D view, dashed on the charts); unset: no comparison.
    std::optional<RunVariant> compare;
    // Playback speed, times real time (the window's [0.1, 10]); unset: the stage's own.
    std::optional<double> speed;

    friend bool operator==(const PresetView&, const PresetView&) = default;
};

struct Preset {
    static constexpr int currentVersion = 1;

    std::string name;        // a short title
    std::string description; // one or two sentences
    SceneId scene = SceneId::Bounce1d;
    ModelKind model = ModelKind::Report;
    std::optional<Integrator> integrator;
    std::optional<ImpactMode> impacts;
    std::optional<double> dt;
    std::optional<long long> steps;
    // Only the parameters the preset sets, each already checked against the scene's table.
    std::vector<std::pair<std::string, Eigen::Vector3d>> params;
    PresetView view;

    friend bool operator==(const Preset&, const Preset&) = default;
};

// Parses preset JSON text; `origin` names the source in messages. Throws InputError
// naming the field that is wrong (malformed JSON with line and column, wrong type,
// missing field, unknown key, value out of range, unsupported version).
Preset parsePreset(std::string_view json, const std::string& origin);
std::string presetToJson(const Preset& preset);

// A built-in preset's name, or a path to a .json file.
Preset loadPreset(const std::string& nameOrPath);
void savePreset(const std::filesystem::path& path, const Preset& preset);

struct BuiltinPreset {
    std::string key; // file name without .json, e.g. "bounce1d-report"
    Preset preset;
};
const std::vector<BuiltinPreset>& builtinPresets();

// Sets the spec's model, integrator, impacts, dt and parameters from the preset; the
// preset's scene must be the spec's (InputError otherwise). Steps are the caller's.
void applyPreset(const Preset& preset, RunSpec& spec);

// The chart keys a preset's view.charts may hold: the window's charts (ui/charts
// chartKey(); a test checks both lists agree).
const std::vector<std::string>& presetChartKeys();

} // namespace ab
