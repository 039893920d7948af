// SPDX-License-Identifier: MIT
#include "help.h"

#include "suggest.h"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace ab::cli {

namespace {

// The text in lines of at most `width` characters, each after `indent` spaces.
void wrapped(std::ostream& out, const std::string& text, std::size_t indent, std::size_t width = 78)
{
    std::istringstream words(text);
    std::string word, line;
    auto flush = [&] {
        if (!line.empty())
            out << std::string(indent, ' ') << line << "\n";
        line.clear();
    };
    while (words >> word) {
        if (!line.empty() && indent + line.size() + 1 + word.size() > width)
            flush();
        line += (line.empty() ? "" : " ") + word;
    }
    flush();
}

// "  label    text", the text wrapped in a column after the label's.
void hanging(std::ostream& out, const std::string& label, std::size_t column, const std::string& text)
{
    std::ostringstream body;
    wrapped(body, text, column);
    out << "  " << std::left << std::setw(int(column - 2)) << label << body.str().substr(column);
}

} // namespace

std::string optionSynopsis(const OptionSpec& o)
{
    return "--" + o.name + (o.flag() ? "" : " " + o.value);
}

std::string optionText(const OptionSpec& o)
{
    std::string text = o.help;
    if (o.repeatable)
        text += "; repeatable";
    if (!o.fallback.empty())
        text += " (default: " + o.fallback + ")";
    return text;
}

const std::vector<std::pair<int, std::string>>& exitStatuses()
{
    static const std::vector<std::pair<int, std::string>> statuses{
        {0, "success"},
        {1, "an internal error"},
        {2, "bad input: one line on standard error names it, and nothing is written"},
        {3, "a run's state became non-finite: the run stops before that state, and its output (whole and valid) "
            "holds the states before it"},
        {4, "an output could not be written (a full disk, standard output closed); a file written before is kept"},
        {5, "video found no OpenGL to draw with; no file is written"},
        {130, "interrupted; no output file is left"},
    };
    return statuses;
}

void printUsage(std::ostream& out)
{
    out << "usage: amazeballs-cli COMMAND [ARGS]\n"
           "       amazeballs-cli help COMMAND    a command's options, units and defaults\n"
           "       amazeballs-cli COMMAND --help  the same\n"
           "       amazeballs-cli --version\n\ncommands:\n";
    for (const CommandSpec& c : commandTable())
        hanging(out, c.synopsis(), 27, c.summary);
    out << "\n";
    wrapped(out,
            "SCENE is one of " + joined(valueWords(Values::Scene)) +
                "; amazeballs-cli list shows each scene's parameters.",
            0);
    out << "\nexit status:\n";
    for (const auto& [status, meaning] : exitStatuses())
        hanging(out, std::to_string(status), 7, meaning);
    out << "\nThe manual: man amazeballs-cli.\n";
}

void printCommandHelp(const CommandSpec& c, std::ostream& out)
{
    out << "usage: amazeballs-cli " << c.synopsis() << "\n\n";
    wrapped(out, c.details, 0);
    if (c.operandValues != Values::None && c.operandValues != Values::File) {
        out << "\n";
        wrapped(out, c.operand + " is one of " + joined(valueWords(c.operandValues)) + ".", 0);
    }
    out << "\noptions:\n";
    for (const OptionSpec& o : c.options) {
        out << "  " << optionSynopsis(o) << "\n";
        wrapped(out, optionText(o), 6);
    }
    out << "  -h, --help\n      print this usage\n";
}

} // namespace ab::cli
