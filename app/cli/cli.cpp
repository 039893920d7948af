// SPDX-License-Identifier: MIT
#include "cli.h"

#include "commands.h"
#include "interrupt.h"

#include <array>
#include <functional>
#include <iostream>

namespace ab::cli {

namespace {

struct Command {
    const char* name;
    const char* usage;
    int (*fn)(Args&, std::ostream&, std::ostream&);
};

const std::array commands{
    Command{"list",
            "list                      scenes, parameters (unit, default, range, equation), models, integrators",
            listCommand},
    Command{"run", "run SCENE [options]       simulate headless and write the trajectory CSV", runCommand},
    Command{"bench",
            "bench [options]           cost per ball-step of many-balls (--balls N... --threads T\n"
            "                            --broadphase grid|all-pairs --model physical|report --steps S\n"
            "                            --repeats R --out FILE.csv --markdown FILE.md)",
            benchCommand},
};

void usage(std::ostream& out)
{
    out << "usage: amazeballs-cli COMMAND [ARGS]\n\ncommands:\n";
    for (const Command& c : commands)
        out << "  " << c.usage << "\n";
    out << "\nrun options: [--model report|physical] [--integrator NAME] [--impacts located|step-end]\n"
           "  [--broadphase grid|all-pairs] [--threads T] [--dt S] [--steps N | --t-end S]\n"
           "  [--set NAME=VALUE]... [--preset NAME|FILE] [--init FILE] [--every K] [--out FILE] [--summary]\n"
           "Exit status: 0 on success, 2 on bad input (one line on stderr), 1 on an internal error.\n";
}

} // namespace

int run(const std::vector<std::string>& argv, std::ostream& out, std::ostream& err)
{
    if (argv.empty()) {
        usage(err);
        return 2;
    }
    const std::string& name = argv.front();
    if (name == "help" || name == "--help" || name == "-h") {
        usage(out);
        return 0;
    }
    for (const Command& c : commands) {
        if (name != c.name)
            continue;
        Args args(name, std::vector<std::string>(argv.begin() + 1, argv.end()));
        try {
            return c.fn(args, out, err);
        } catch (const Interrupted&) {
            err << "amazeballs-cli: " << name << ": interrupted; no output file was written\n";
            return 130;
        } catch (const InputError& e) {
            err << "amazeballs-cli: " << e.what() << "\n";
            return 2;
        } catch (const std::bad_alloc&) {
            err << "amazeballs-cli: " << name << ": out of memory (try fewer balls or steps)\n";
            return 2;
        } catch (const std::exception& e) {
            err << "amazeballs-cli: internal error: " << e.what() << "\n";
            return 1;
        }
    }
    err << "amazeballs-cli: unknown command '" << name << "' (try: amazeballs-cli help)\n";
    return 2;
}

} // namespace ab::cli
