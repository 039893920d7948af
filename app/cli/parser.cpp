// SPDX-License-Identifier: MIT
#include "parser.h"

#include "suggest.h"

#include <CLI/CLI.hpp>

#include <regex>

namespace ab::cli {

namespace {

// CLI11 reads its arguments from the back.
std::vector<std::string> reversed(const std::vector<std::string>& args)
{
    return {args.rbegin(), args.rend()};
}

// "--ste=5" -> "ste": the name a misspelt option is compared by.
std::string bareName(const std::string& arg)
{
    std::string name = arg.substr(0, arg.find('='));
    name.erase(0, name.find_first_not_of('-'));
    return name;
}

// The first argument nobody asked for: an unknown option (with the nearest known ones) or
// an argument too many.
[[noreturn]] void throwLeftOver(const std::string& where, const std::string& arg,
                                const std::vector<std::string>& optionNames)
{
    const bool isOption = arg.size() > 1 && arg[0] == '-';
    if (!isOption)
        throw InputError(where + "unexpected argument '" + printableInput(arg) + "'");
    const std::string shown = printableInput(arg.substr(0, arg.find('=')));
    throw InputError(where + "unknown option '" + shown + "'" + didYouMean(bareName(arg), optionNames, "--"));
}

// CLI11's message for a parse error as one line in the contract's style.
[[noreturn]] void throwParseError(const std::string& where, const CLI::ParseError& e)
{
    const std::string what = e.what();
    static const std::regex missing(R"(^(--[A-Za-z0-9-]+): \d+ required .* missing$)");
    static const std::regex override(R"(^-*([A-Za-z0-9-]+) was given a disallowed flag override$)");
    std::smatch m;
    if (std::regex_match(what, m, missing))
        throw InputError(m[1].str() + ": missing value");
    if (std::regex_match(what, m, override))
        throw InputError("--" + m[1].str() + ": takes no value");
    throw InputError(where + printableInput(what));
}

std::vector<std::string> optionNames(const CommandSpec& command)
{
    std::vector<std::string> names;
    for (const OptionSpec& o : command.options)
        names.push_back(o.name);
    names.emplace_back("help");
    return names;
}

const char* const kOperand = "operand";

} // namespace

std::unique_ptr<CLI::App> makeParser(const CommandSpec& command)
{
    auto app = std::make_unique<CLI::App>(command.summary, "amazeballs-cli " + command.name);
    app->set_help_flag("-h,--help", "print this command's usage");
    app->allow_extras(); // reported as one line, with a suggestion (parseCommand)
    if (!command.operand.empty())
        app->add_option(kOperand, command.operand)->type_name(command.operand)->expected(1);
    for (const OptionSpec& o : command.options) {
        const std::string name = "--" + o.name;
        CLI::Option* option = o.flag() ? app->add_flag(name)->description(o.help)->disable_flag_override()
                                       : app->add_option(name, o.help)->type_name(o.value)->expected(1);
        // Repeatable options keep every value; the others too, the last one winning.
        option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    }
    return app;
}

Parsed parseCommand(const CommandSpec& command, const std::vector<std::string>& args)
{
    const std::unique_ptr<CLI::App> app = makeParser(command);
    const std::string where = command.name + ": ";
    try {
        app->parse(reversed(args));
    } catch (const CLI::CallForHelp&) {
        throw HelpRequested{};
    } catch (const CLI::ParseError& e) {
        throwParseError(where, e);
    }
    // CLI11 leaves the "--" that ends the options among the extras.
    for (const std::string& arg : app->remaining())
        if (arg != "--")
            throwLeftOver(where, arg, optionNames(command));
    std::optional<std::string> operand;
    if (!command.operand.empty())
        if (const CLI::Option* o = app->get_option(kOperand); o->count() > 0)
            operand = o->results().front();
    std::map<std::string, std::vector<std::string>> values;
    for (const OptionSpec& spec : command.options) {
        const CLI::Option* o = app->get_option("--" + spec.name);
        if (o->count() == 0)
            continue;
        values[spec.name] = spec.flag() ? std::vector<std::string>{"true"} : o->results();
    }
    return Parsed(command, std::move(operand), std::move(values));
}

std::unique_ptr<CLI::App> makeTopLevelParser()
{
    auto app = std::make_unique<CLI::App>("Bouncing and colliding balls, headless", "amazeballs-cli");
    app->set_help_flag("-h,--help", "print the commands");
    app->add_flag("--version")->description("print the program's name and version");
    app->prefix_command(); // the command and everything after it are the command's
    return app;
}

TopLevel parseTopLevel(const std::vector<std::string>& args)
{
    const std::unique_ptr<CLI::App> app = makeTopLevelParser();
    TopLevel top;
    try {
        app->parse(reversed(args));
    } catch (const CLI::CallForHelp&) {
        top.help = true;
        return top;
    } catch (const CLI::ParseError& e) {
        throwParseError("", e);
    }
    top.version = app->get_option("--version")->count() > 0;
    top.rest = app->remaining();
    if (!top.rest.empty() && top.rest.front().size() > 1 && top.rest.front()[0] == '-')
        throwLeftOver("", top.rest.front(), {"help", "version"});
    return top;
}

} // namespace ab::cli
