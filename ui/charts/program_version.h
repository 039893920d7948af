// SPDX-License-Identifier: MIT
// The program's name and version (CMake's project(VERSION)), for what the exports say
// about how they were made.
#pragma once

#include <string>

namespace ab::ui {

std::string programName();    // "Amazeballs"
std::string programVersion(); // e.g. "0.1.0"

} // namespace ab::ui
