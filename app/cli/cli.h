// SPDX-License-Identifier: MIT
// amazeballs-cli: every command takes its arguments and two streams, so tests run it in
// process. Exit status 0 on success, 2 with one line on `err` for any bad input.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace ab::cli {

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

} // namespace ab::cli
