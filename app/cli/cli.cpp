// SPDX-License-Identifier: MIT
#include "cli.h"

#include "commands.h"
#include "help.h"
#include "interrupt.h"
#include "parser.h"
#include "suggest.h"

#include "../../core/io/atomic_file.h"

#include <iostream>

namespace ab::cli {

namespace {

// Every message is one line: whatever a message quotes, no control character reaches the
// terminal (quoted input is already escaped; this is the last guard).
std::string oneLine(std::string_view text)
{
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F) {
            static const char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[u >> 4];
            out += hex[u & 15];
        } else {
            out += c;
        }
    }
    return out;
}

// Prints what `print` writes on standard output, checked: 0, or 4 when it was not written.
template <typename Print> int printChecked(const std::string& name, std::ostream& out, std::ostream& err, Print print)
{
    try {
        print();
        out.flush();
    } catch (const OutputError& e) {
        err << "amazeballs-cli: " << name << ": " << oneLine(e.what()) << "\n";
        return 4;
    }
    return out ? 0 : 4;
}

// `help [COMMAND]`: the list of commands, or that command's usage.
int helpCommand(const Parsed& args, std::ostream& out, std::ostream& err)
{
    if (const auto name = args.positionalIfGiven()) {
        const CommandSpec* c = findCommand(*name);
        if (!c)
            throw InputError("help: unknown command '" + printableInput(*name) + "'" +
                             nearOrChoices(*name, commandNames()));
        return printChecked("help", out, err, [&] { printCommandHelp(*c, out); });
    }
    return printChecked("help", out, err, [&] { printUsage(out); });
}

// Reads the command's arguments and runs it; what it printed is flushed inside, so that a
// failed write to standard output is reported like any other.
int dispatch(const CommandSpec& c, const std::vector<std::string>& argv, std::ostream& out, std::ostream& err)
{
    const std::string& name = c.name;
    try {
        Parsed args = parseCommand(c, std::vector<std::string>(argv.begin() + 1, argv.end()));
        if (!c.fn)
            return helpCommand(args, out, err);
        const int status = c.fn(args, out, err);
        out.flush();
        if (!out)
            throw OutputError("standard output: not written (the stream failed)");
        return status;
    } catch (const HelpRequested&) {
        return printChecked(name, out, err, [&] { printCommandHelp(c, out); });
    } catch (const Interrupted&) {
        err << "amazeballs-cli: " << name << ": interrupted; no output file was written\n";
        return 130;
    } catch (const OutputError& e) {
        err << "amazeballs-cli: " << name << ": " << oneLine(e.what()) << "\n";
        return 4;
    } catch (const InputError& e) {
        err << "amazeballs-cli: " << oneLine(e.what()) << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        err << "amazeballs-cli: " << name << ": out of memory (try fewer balls or steps)\n";
        return 2;
    } catch (const std::exception& e) {
        err << "amazeballs-cli: internal error: " << oneLine(e.what()) << "\n";
        return 1;
    }
}

} // namespace

int run(const std::vector<std::string>& argv, std::ostream& out, std::ostream& err)
{
    TopLevel top;
    try {
        top = parseTopLevel(argv);
    } catch (const InputError& e) {
        err << "amazeballs-cli: " << oneLine(e.what()) << "\n";
        return 2;
    }
    if (top.help)
        return printChecked("help", out, err, [&] { printUsage(out); });
    if (top.version)
        return printChecked("version", out, err, [&] { out << "amazeballs-cli " << AMAZEBALLS_VERSION << "\n"; });
    if (top.rest.empty()) {
        err << "amazeballs-cli: missing COMMAND (usage: amazeballs-cli COMMAND [ARGS]; amazeballs-cli --help lists "
               "the commands)\n";
        return 2;
    }
    const std::string& name = top.rest.front();
    if (const CommandSpec* c = findCommand(name))
        return dispatch(*c, top.rest, out, err);
    const std::string near = didYouMean(name, commandNames());
    err << "amazeballs-cli: unknown command '" << oneLine(printableInput(name)) << "'"
        << (near.empty() ? " (try: amazeballs-cli --help)" : near) << "\n";
    return 2;
}

} // namespace ab::cli
