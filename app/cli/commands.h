// SPDX-License-Identifier: MIT
// One function per command; cli.cpp dispatches on the first argument.
#pragma once

#include "args.h"

#include <iosfwd>

namespace ab::cli {

int listCommand(Args& args, std::ostream& out, std::ostream& err);
int runCommand(Args& args, std::ostream& out, std::ostream& err);
int stabilityCommand(Args& args, std::ostream& out, std::ostream& err);
int studyCommand(Args& args, std::ostream& out, std::ostream& err);
int chartCommand(Args& args, std::ostream& out, std::ostream& err);
int benchCommand(Args& args, std::ostream& out, std::ostream& err);
int figureCommand(Args& args, std::ostream& out, std::ostream& err);
int videoCommand(Args& args, std::ostream& out, std::ostream& err);

} // namespace ab::cli
