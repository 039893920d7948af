// SPDX-License-Identifier: MIT
#include "program_version.h"

#ifndef AB_PROGRAM_VERSION
#error "AB_PROGRAM_VERSION is set by ui/CMakeLists.txt from project(VERSION)"
#endif

namespace ab::ui {

std::string programName()
{
    return "Amazeballs";
}

std::string programVersion()
{
    return AB_PROGRAM_VERSION;
}

} // namespace ab::ui
