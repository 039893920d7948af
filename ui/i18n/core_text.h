// SPDX-License-Identifier: MIT
// The core's tables are Qt-free and English. The window shows them through the
// translator under the fixed context "core"; core_strings.cpp lists every such source
// string for lupdate, and a test checks that list against the tables.
#pragma once

#include "core/input_error.h"

#include <QString>

#include <string>
#include <string_view>
#include <vector>

namespace ab::ui {

inline constexpr char coreContext[] = "core";

// `text` from a core table in the current language (itself where no translation exists).
QString coreText(std::string_view text);

// A refusal in the current language: its sentence translated, the values it quotes filled
// in as typed; an error the core gave as plain text is shown as it is.
QString refusalText(const Refusal& r);
QString refusalText(const InputError& e);

// Every string of the core's tables that the window shows: scene titles, report
// references, summaries, units, equation meanings, notes, parameter meanings and
// references, model titles and summaries, integrator titles, the built-in presets' names and
// descriptions, the refusals' sentences.
std::vector<std::string> coreDisplayedStrings();

// The source strings listed for lupdate in core_strings.cpp.
std::vector<std::string> coreListedStrings();

} // namespace ab::ui
