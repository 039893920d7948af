// SPDX-License-Identifier: MIT
#include "cli.h"

#include "commands.h"
#include "interrupt.h"

#include "../../core/io/atomic_file.h"

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
    Command{"run",
            "run SCENE [options]       simulate headless and write the trajectory CSV\n"
            "                            (--meta: `#` lines with the program, settings and constants first)",
            runCommand},
    Command{"bench",
            "bench [options]           cost per ball-step of many-balls (--balls N... --threads T\n"
            "                            --broadphase grid|all-pairs --model physical|report --steps S\n"
            "                            --repeats R --out FILE.csv --markdown FILE.md\n"
            "                            --set mu|beta|inertia|spin=VALUE: rough balls)",
            benchCommand},
    Command{"chart",
            "chart SCENE [options]     the window's chart as PNG, SVG or PDF, headless:\n"
            "                            --chart position|velocity|energy|momentum|activity|difference\n"
            "                            --out FILE.png|FILE.svg|FILE.pdf [--ball B] (B = 1 is the first ball)\n"
            "                            [--size report-column|report-full|slide|WxH|WxHmm] [--dpi N]\n"
            "                            [--caption] [--compare MODEL[:INTEGRATOR[:IMPACTS]]] [--data FILE.csv]\n"
            "                            [--width W] [--height H] and the run options",
            chartCommand},
    Command{"stability",
            "stability [--case NAME]... [--out FILE.csv] [--markdown FILE.md] [--list]\n"
            "                            the stiff and extreme cases, one row per model and integrator",
            stabilityCommand},
    Command{"study", "study SCENE [options]     error against run time of the physical model's integrators",
            studyCommand},
    Command{"figure",
            "figure 2.5|2.6|2.7|3.1     the report's figure redrawn from the report model, headless:\n"
            "                            --out FILE.png|FILE.svg|FILE.pdf [--size report-column|report-full|\n"
            "                            slide|WxH|WxHmm] [--dpi N] [--width W] [--height H]",
            figureCommand},
    Command{"video",
            "video SCENE [options]     the run as an animation, headless (OpenGL: Xvfb or Mesa's EGL):\n"
            "                            --out FILE.mp4|FILE.webm|FILE.gif [--size WxH|720p|1080p] [--fps F]\n"
            "                            [--from S] [--to S] [--speed X] [--charts] [--ball B] [--quiet]\n"
            "                            and the run options; exit status 4 when there is no OpenGL",
            videoCommand},
};

void usage(std::ostream& out)
{
    out << "usage: amazeballs-cli COMMAND [ARGS]\n\ncommands:\n";
    for (const Command& c : commands)
        out << "  " << c.usage << "\n";
    out << "\nrun options: [--model report|physical] [--integrator NAME] [--impacts located|step-end]\n"
           "  [--broadphase grid|all-pairs] [--threads T] [--dt S] [--steps N | --t-end S]\n"
           "  [--set NAME=VALUE]... [--preset NAME|FILE] [--init FILE] [--every K] [--out FILE] [--summary]\n"
           "\nstudy options: [--set NAME=VALUE]... [--preset NAME|FILE] [--t-end S] [--dt-max S] [--dt-min S]\n"
           "  [--per-decade N] [--repeats N] [--impact K] [--out FILE.csv] [--chart FILE.png|FILE.svg]\n"
           "  [--markdown FILE.md] [--quiet]\n"
           "A health check follows every step of a run; its worst finding goes to stderr as one line.\n"
           "Exit status: 0 on success, 2 on bad input (one line on stderr), 1 on an internal error,\n"
           "  3 when a run's state became non-finite: it stops before that state, and the output (whole and\n"
           "  valid) holds the states before it; 4 when an output could not be written (disk full, standard\n"
           "  output closed; a file written before is kept); 5 when `video` finds no OpenGL to draw with (no\n"
           "  file is written); 130 when interrupted (no file is left).\n";
}

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

// Runs one command; what it printed is flushed inside, so that a failed write to standard
// output is reported like any other.
int dispatch(const Command& c, const std::string& name, const std::vector<std::string>& argv, std::ostream& out,
             std::ostream& err)
{
    Args args(name, std::vector<std::string>(argv.begin() + 1, argv.end()));
    try {
        const int status = c.fn(args, out, err);
        out.flush();
        if (!out)
            throw OutputError("standard output: not written (the stream failed)");
        return status;
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
    if (argv.empty()) {
        usage(err);
        return 2;
    }
    const std::string& name = argv.front();
    if (name == "help" || name == "--help" || name == "-h") {
        try {
            usage(out);
            out.flush();
        } catch (const OutputError& e) {
            err << "amazeballs-cli: help: " << oneLine(e.what()) << "\n";
            return 4;
        }
        return out ? 0 : 4;
    }
    for (const Command& c : commands)
        if (name == c.name)
            return dispatch(c, name, argv, out, err);
    err << "amazeballs-cli: unknown command '" << printableInput(name) << "' (try: amazeballs-cli help)\n";
    return 2;
}

} // namespace ab::cli
