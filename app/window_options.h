// SPDX-License-Identifier: MIT
// The window's options: the table its QCommandLineParser (main.cpp) is made from, and the
// amazeballs(1) man page and its shell completions (cli/docgen.h). The help texts are
// translated in the context "main".
#pragma once

#include "cli/command_table.h"

#include <QtGlobal>

#include <vector>

namespace ab::app {

struct WindowOption {
    const char* name;
    const char* value; // empty for a flag
    const char* help;  // QT_TRANSLATE_NOOP("main", ...)
    cli::Values values = cli::Values::None;
    const char* words = ""; // the values it takes, space-separated, where they are fixed
};

inline const std::vector<WindowOption>& windowOptions()
{
    static const std::vector<WindowOption> options{
        {"compare", "MODEL[:INTEGRATOR[:IMPACTS]]",
         QT_TRANSLATE_NOOP("main", "Run the stage again beside the first, computed by MODEL (report or "
                                   "physical), INTEGRATOR and IMPACTS (located or step-end).")},
        {"scene", "KEY", QT_TRANSLATE_NOOP("main", "Start on stage KEY."), cli::Values::Scene},
        {"set", "NAME=VALUE", QT_TRANSLATE_NOOP("main", "Set a constant, NAME=VALUE."), cli::Values::Assignment},
        {"play", "", QT_TRANSLATE_NOOP("main", "Start playing.")},
        {"speed", "X", QT_TRANSLATE_NOOP("main", "Play at X times real time (0.1 to 10).")},
        {"threads", "N",
         QT_TRANSLATE_NOOP("main", "Step the physical model's many balls on N threads (1 to 256; by default one "
                                   "fewer than the processor's cores, at most 8).")},
        {"measure-frames", "S", QT_TRANSLATE_NOOP("main", "Play for S seconds, print frame times, quit.")},
        {"preset", "NAME|FILE", QT_TRANSLATE_NOOP("main", "Open a built-in preset by NAME, or a preset FILE."),
         cli::Values::Preset},
        {"fresh", "",
         QT_TRANSLATE_NOOP("main", "Start as on a first start: neither read nor write the remembered "
                                   "window, stage and settings.")},
        {"lecture", "",
         QT_TRANSLATE_NOOP("main", "Open in lecture mode: full screen, large text, the step-by-step walk.")},
        {"theme", "KEY", QT_TRANSLATE_NOOP("main", "Colours: light, dark, high-contrast-light or high-contrast-dark."),
         cli::Values::None, "light dark high-contrast-light high-contrast-dark"},
    };
    return options;
}

} // namespace ab::app
