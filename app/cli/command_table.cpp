// SPDX-License-Identifier: MIT
#include "command_table.h"

#include "commands.h"

#include "../../core/io/preset.h"
#include "../../core/scene.h"
#include "../../core/stability/suite.h"
#include "../../ui/charts/motion_chart.h"
#include "../../ui/figures/report_figures.h"

#include <algorithm>

namespace ab::cli {

namespace {

using V = Values;

// The options every simulating command shares (run_setup.h reads them).
std::vector<OptionSpec> runOptions()
{
    return {
        {"model", "report|physical", "the model that computes the run", "report; physical for the street", false,
         V::Model},
        {"integrator", "NAME", "the physical model's integrator (amazeballs-cli list names them)",
         "symplectic-euler; event for the street", false, V::Integrator},
        {"impacts", "located|step-end",
         "located: each impact's time found inside the step; step-end: as the report, at the step's end", "located",
         false, V::Impacts},
        {"broadphase", "grid|all-pairs", "how many-balls finds the pairs that may touch", "grid", false, V::Broadphase},
        {"threads", "T", "threads for the physical model's many-balls, 1 to 256", "1"},
        {"dt", "S", "the time step, in the scene's time unit (step, s or frame), positive",
         "the scene's: the report's step for the report model"},
        {"steps", "N", "the run's length in steps, 1 to 4e9", "the preset's, else the scene's"},
        {"t-end", "S", "the run's end time, in the scene's time unit (instead of --steps)", ""},
        {"set", "NAME=VALUE", "a parameter of the scene, in its unit (vectors as x,y,z; amazeballs-cli list)",
         "the scene's defaults", true, V::Assignment},
        {"preset", "NAME|FILE", "start from a built-in preset or a preset file (.json)", "", false, V::Preset},
        {"init", "FILE.csv", "start from the first time recorded in a trajectory CSV", "", false, V::File},
    };
}

std::vector<OptionSpec> with(std::vector<OptionSpec> first, const std::vector<OptionSpec>& more)
{
    first.insert(first.end(), more.begin(), more.end());
    return first;
}

// The size options of `chart` and `figure`, with the defaults of the command.
std::vector<OptionSpec> figureSizeOptions(const char* sizeDefault, const char* widthDefault, const char* heightDefault)
{
    return {
        {"size", "report-column|report-full|slide|WxH|WxHmm",
         "the size: a preset, pixels or millimetres; a chart needs 70x50mm (397x283 px at 144 dpi)", sizeDefault},
        {"dpi", "N", "dots per inch of a size in millimetres", "the size preset's"},
        {"width", "W", "the width in pixels, 200 to 8000 (instead of --size)", widthDefault},
        {"height", "H", "the height in pixels, 150 to 8000 (instead of --size)", heightDefault},
    };
}

CommandSpec runCommandSpec()
{
    return {"run",
            "SCENE",
            false,
            V::Scene,
            "simulate headless and write the trajectory CSV",
            "Simulates SCENE headless and writes its trajectory CSV (t,ball,x,y,z,vx,vy,vz), on standard "
            "output without --out. A health check follows every step; its worst finding goes to standard error "
            "as one line.",
            with(runOptions(),
                 {
                     {"every", "K", "write every K-th state", "1"},
                     {"out", "FILE.csv", "write the trajectory to FILE.csv, whole or not at all", "standard output",
                      false, V::File},
                     {"summary", "", "print a few readable lines instead of the CSV"},
                     {"meta", "", "begin the CSV with # lines naming the program, settings and constants"},
                     {"quiet", "", "no progress on standard error (shown only on a terminal, from 2 s on)"},
                 }),
            runCommand};
}

CommandSpec chartCommandSpec()
{
    return {"chart",
            "SCENE",
            false,
            V::Scene,
            "the window's chart as PNG, SVG or PDF, headless",
            "Runs SCENE and draws one of the window's charts into an image, headless.",
            with(with(runOptions(),
                      {
                          {"chart", "KIND", "the chart to draw", "", false, V::Chart},
                          {"out", "FILE.png|FILE.svg|FILE.pdf", "the image to write (its type from its name)", "",
                           false, V::File},
                          {"ball", "B", "the ball charted, 1 for the first", "1"},
                      }),
                 with(figureSizeOptions("report-column: 85x64mm, 1004x756 px in PNG", "1200 beside --height",
                                        "800 beside --width"),
                      {
                          {"caption", "", "print the settings under the chart"},
                          {"compare", "MODEL[:INTEGRATOR[:IMPACTS]]",
                           "draw a second run of the same scene computed another way", ""},
                          {"data", "FILE.csv", "also write the chart's data as CSV", "", false, V::File},
                      })),
            chartCommand};
}

CommandSpec videoCommandSpec()
{
    return {
        "video",
        "SCENE",
        false,
        V::Scene,
        "the run as an animation, headless (OpenGL: Xvfb or Mesa's EGL)",
        "Runs SCENE and encodes its 3D view as an animation, headless. Exit status 5 when there is no OpenGL "
        "to draw with.",
        with(runOptions(),
             {
                 {"out", "FILE.mp4|FILE.webm|FILE.gif", "the animation to write (its format from its name)", "", false,
                  V::File},
                 {"size", "WxH|720p|1080p", "the frame size in pixels", "720p"},
                 {"fps", "F", "frames per second, 1 to 120", "30"},
                 {"from", "S", "start at this time, in the scene's time unit", "the run's start"},
                 {"to", "S", "end at this time, in the scene's time unit", "the run's end"},
                 {"speed", "X", "simulated time per second of video, as a multiple of real time", "1"},
                 {"charts", "", "draw the scene's charts beside the view"},
                 {"ball", "B", "the ball followed, 1 for the first", "1"},
                 {"quiet", "", "no progress and no closing line on standard error (progress shows on a terminal only)"},
             }),
        videoCommand};
}

CommandSpec studyCommandSpec()
{
    return {
        "study",
        "SCENE",
        false,
        V::Scene,
        "error against run time of the physical model's integrators",
        "Measures the error against the scene's closed form and the run time of every integrator of the "
        "physical model over a sweep of steps (work-precision), as a table, a Markdown report and a chart.",
        {
            {"set", "NAME=VALUE", "a parameter of the scene, in its unit", "the scene's defaults", true, V::Assignment},
            {"preset", "NAME|FILE", "start from a built-in preset or a preset file (.json)", "", false, V::Preset},
            {"t-end", "S", "the end time, in the scene's time unit", "the scene's"},
            {"dt-max", "S", "the largest step tried, in the scene's time unit", "the scene's"},
            {"dt-min", "S", "the smallest step tried, in the scene's time unit", "the scene's"},
            {"per-decade", "N", "steps tried per factor of ten, 1 to 20", "3"},
            {"repeats", "N", "timed repeats, the median reported, 1 to 100", "5"},
            {"impact", "K", "the error of the K-th impact's time, 1 to 100000", "3"},
            {"out", "FILE.csv", "write the table as CSV", "", false, V::File},
            {"chart", "FILE.png|FILE.svg", "draw the work-precision chart", "", false, V::File},
            {"markdown", "FILE.md", "write the report as Markdown", "standard output", false, V::File},
            {"quiet", "", "no progress on standard error"},
        },
        studyCommand};
}

CommandSpec benchCommandSpec()
{
    return {"bench",
            "",
            false,
            V::None,
            "cost per ball-step of many-balls and the street",
            "Times the many-balls scene on the benchmark workload, or the street from its hopper's release: the "
            "median of several runs per ball count, as CSV.",
            {
                {"scene", "many-balls|street", "the scene timed; repeat for both, each ball count of each in turn",
                 "many-balls", true, V::Scene},
                {"balls", "N", "a ball count to time, 1 to 4000000; repeat for several",
                 "150, 1000, 10000, 100000 and 1000000", true},
                {"threads", "T", "threads of the physical model, 1 to 256", "1"},
                {"broadphase", "grid|all-pairs", "how the pairs that may touch are found",
                 "grid, and all-pairs up to 1000 balls", false, V::Broadphase},
                {"model", "physical|report", "the model timed", "physical", false, V::Model},
                {"steps", "S", "timed steps per run, 1 to 1000000", "200"},
                {"repeats", "R", "runs per case, the median reported, 1 to 99", "3"},
                {"out", "FILE.csv", "write the CSV to FILE.csv (progress on standard output)", "standard output", false,
                 V::File},
                {"markdown", "FILE.md", "also write the table as Markdown", "", false, V::File},
                {"set", "NAME=VALUE",
                 "many-balls: a constant of rough balls, mu, beta, inertia or spin (the physical model); street: any "
                 "of its parameters but n",
                 "smooth balls; the street's defaults", true, V::Assignment},
            },
            benchCommand};
}

CommandSpec stabilityCommandSpec()
{
    return {"stability",
            "",
            false,
            V::None,
            "the stiff and extreme cases, one row per model and integrator",
            "Runs the suite of stiff and extreme cases with every model and integrator and prints one row each.",
            {
                {"case", "NAME", "run only this case; repeat for several", "every case", true, V::Case},
                {"out", "FILE.csv", "also write the rows as CSV", "", false, V::File},
                {"markdown", "FILE.md", "also write the rows as Markdown", "", false, V::File},
                {"list", "", "list the cases and stop"},
            },
            stabilityCommand};
}

std::vector<CommandSpec> makeTable()
{
    std::vector<CommandSpec> t;
    t.push_back({"list",
                 "",
                 false,
                 V::None,
                 "scenes, parameters (unit, default, range, equation), models, integrators",
                 "Lists every scene with its parameters (name, unit, default, range, equation, models), the models, "
                 "the integrators, the impact modes and the broadphases.",
                 {},
                 listCommand});
    t.push_back(runCommandSpec());
    t.push_back(benchCommandSpec());
    t.push_back(chartCommandSpec());
    t.push_back(stabilityCommandSpec());
    t.push_back(studyCommandSpec());
    t.push_back({"figure", "FIGURE", false, V::Figure, "the report's figure redrawn from the report model, headless",
                 "Redraws figure 2.5, 2.6, 2.7 or 3.1 of the report from the report model with the report's "
                 "constants.",
                 with({{"out", "FILE.png|FILE.svg|FILE.pdf", "the image to write (its type from its name)", "", false,
                        V::File}},
                      figureSizeOptions("1200x900 pixels", "1200 beside --height", "900 beside --width")),
                 figureCommand});
    t.push_back(videoCommandSpec());
    t.push_back({"help",
                 "COMMAND",
                 true,
                 V::Command,
                 "this list, or the options of COMMAND",
                 "Prints the commands, or one command's usage with its options, units and defaults.",
                 {},
                 nullptr});
    return t;
}

} // namespace

const OptionSpec* CommandSpec::option(std::string_view key) const
{
    for (const OptionSpec& o : options)
        if (o.name == key)
            return &o;
    return nullptr;
}

std::string CommandSpec::synopsis() const
{
    std::string s = name;
    if (!operand.empty())
        s += operandOptional ? " [" + operand + "]" : " " + operand;
    if (!options.empty())
        s += " [options]";
    return s;
}

const std::vector<CommandSpec>& commandTable()
{
    static const std::vector<CommandSpec> table = makeTable();
    return table;
}

const CommandSpec* findCommand(std::string_view name)
{
    for (const CommandSpec& c : commandTable())
        if (c.name == name)
            return &c;
    return nullptr;
}

std::vector<std::string> commandNames()
{
    std::vector<std::string> names;
    for (const CommandSpec& c : commandTable())
        names.push_back(c.name);
    return names;
}

std::vector<std::string> valueWords(Values v)
{
    std::vector<std::string> words;
    switch (v) {
    case V::Scene:
        for (const SceneInfo* s : allScenes())
            words.push_back(s->key);
        break;
    case V::Model:
        for (ModelKind m : allModels())
            words.emplace_back(modelKey(m));
        break;
    case V::Integrator:
        for (Integrator i : allIntegrators())
            words.emplace_back(integratorKey(i));
        break;
    case V::Impacts: // the keys core/scene.h parses, for each ImpactMode
        for (ImpactMode m : {ImpactMode::Located, ImpactMode::StepEnd})
            words.emplace_back(impactModeKey(m));
        break;
    case V::Broadphase:
        for (Broadphase b : {Broadphase::Grid, Broadphase::AllPairs})
            words.emplace_back(broadphaseKey(b));
        break;
    case V::Chart:
        for (ui::ChartKind k : ui::allChartKinds())
            words.emplace_back(ui::chartKey(k));
        break;
    case V::Case:
        for (const stability::StabilityCase& c : stability::stabilityCases())
            words.push_back(c.name);
        break;
    case V::Figure:
        for (ui::ReportFigure f : ui::allReportFigures())
            words.emplace_back(ui::figureNumber(f));
        break;
    case V::Preset:
        for (const BuiltinPreset& p : builtinPresets())
            words.push_back(p.key);
        break;
    case V::Assignment:
        for (const SceneInfo* s : allScenes())
            for (const ParamSpec& p : s->params)
                if (std::find(words.begin(), words.end(), p.key) == words.end())
                    words.push_back(p.key);
        break;
    case V::Command:
        words = commandNames();
        break;
    case V::None:
    case V::File:
        break;
    }
    return words;
}

} // namespace ab::cli
