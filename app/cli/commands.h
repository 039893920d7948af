// SPDX-License-Identifier: MIT
// One function per command; cli.cpp dispatches on the first argument.
#pragma once

#include "parsed.h"

#include <iosfwd>

namespace ab::cli {

int listCommand(Parsed& args, std::ostream& out, std::ostream& err);
int runCommand(Parsed& args, std::ostream& out, std::ostream& err);
int stabilityCommand(Parsed& args, std::ostream& out, std::ostream& err);
int studyCommand(Parsed& args, std::ostream& out, std::ostream& err);
int chartCommand(Parsed& args, std::ostream& out, std::ostream& err);
int benchCommand(Parsed& args, std::ostream& out, std::ostream& err);
int figureCommand(Parsed& args, std::ostream& out, std::ostream& err);
int videoCommand(Parsed& args, std::ostream& out, std::ostream& err);

} // namespace ab::cli
