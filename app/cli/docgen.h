// SPDX-License-Identifier: MIT
// The man pages amazeballs(1) and amazeballs-cli(1) and the bash and zsh completions of
// both programs, written from the tables their parsers are made from: amazeballs-cli's
// command table (command_table.h), the window's options (window_options.h) and the
// scenes' parameter tables (core/scene.h), so none of them is kept by hand.
#pragma once

#include <iosfwd>
#include <string>

namespace ab::cli {

struct PageInfo {
    std::string version; // project(VERSION)
    std::string date;    // YYYY-MM-DD, the release's
};

void writeCliManPage(std::ostream& out, const PageInfo& info);
void writeWindowManPage(std::ostream& out, const PageInfo& info);
void writeCliBashCompletion(std::ostream& out);
void writeWindowBashCompletion(std::ostream& out);
void writeCliZshCompletion(std::ostream& out);
void writeWindowZshCompletion(std::ostream& out);

// Text as roff: backslashes, minus signs and a leading control character escaped.
std::string roff(const std::string& text);

} // namespace ab::cli
