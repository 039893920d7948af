// SPDX-License-Identifier: MIT
// The two man pages (docgen.h), in the man(7) macros.
#include "docgen.h"

#include "command_table.h"
#include "help.h"
#include "suggest.h"

#include "../../core/scene.h"
#include "../window_options.h"

#include <ostream>

namespace ab::cli {

std::string roff(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else if (c == '\n')
            out += "\n";
        else
            out += c;
        if ((c == '.' || c == '\'') && (out.size() == 1 || out[out.size() - 2] == '\n'))
            out.insert(out.size() - 1, "\\&");
    }
    return out;
}

namespace {

void header(std::ostream& out, const std::string& name, const PageInfo& info, const std::string& summary)
{
    std::string upper;
    for (const char c : name)
        upper += char(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    out << ".\\\" Generated from the program's option tables at build time; do not edit.\n"
        << ".TH " << roff(upper) << " 1 \"" << info.date << "\" \"Amazeballs " << info.version
        << "\" \"User Commands\"\n"
        << ".SH NAME\n"
        << roff(name) << " \\- " << roff(summary) << "\n";
}

// ".TP" item: the option in bold, its value in italics, then its text.
void optionItem(std::ostream& out, const std::string& name, const std::string& value, const std::string& text)
{
    out << ".TP\n\\fB\\-\\-" << roff(name) << "\\fR";
    if (!value.empty())
        out << " \\fI" << roff(value) << "\\fR";
    out << "\n" << roff(text) << "\n";
}

void sceneSection(std::ostream& out)
{
    out << ".SH SCENES AND PARAMETERS\n"
           "Each scene's parameters, set with \\fB\\-\\-set\\fR \\fINAME\\fR=\\fIVALUE\\fR (vectors as x,y,z). "
           "Ranges are inclusive; '(' marks an exclusive lower bound.\n";
    for (const SceneInfo* s : allScenes()) {
        out << ".SS " << roff(s->key) << "\n"
            << roff("Stage " + std::to_string(s->stage) + ": " + s->title + " (report " + s->reportRef + "). Time in " +
                    s->timeUnit + ", lengths in " + s->lengthUnit + ".")
            << "\n";
        for (const ParamSpec& p : s->params) {
            out << ".TP\n.B " << roff(p.key) << "\n"
                << roff(p.meaning + "; " + (p.unit.empty() || p.unit == "1" ? "no unit" : "in " + p.unit) +
                        ", default " + formatValue(p, p.defaultValue) + ", range " + formatRange(p) +
                        (p.equation.empty() ? "" : ", " + p.equation) + ".")
                << "\n";
        }
    }
    out << ".SH MODELS AND INTEGRATORS\n.TP\n.B \\-\\-model\n"
        << roff(joined(valueWords(Values::Model))) << "\n"
        << ".TP\n.B \\-\\-integrator\n"
        << roff(joined(valueWords(Values::Integrator))) << "\n";
}

} // namespace

void writeCliManPage(std::ostream& out, const PageInfo& info)
{
    header(out, "amazeballs-cli", info, "bouncing and colliding balls, headless: runs, charts, studies");
    out << ".SH SYNOPSIS\n.B amazeballs\\-cli\n.I COMMAND\n.RI [ ARGS ]\n.br\n"
           ".B amazeballs\\-cli help\n.RI [ COMMAND ]\n.br\n.B amazeballs\\-cli\n.I COMMAND\n.B \\-\\-help\n.br\n"
           ".B amazeballs\\-cli \\-\\-version\n"
           ".SH DESCRIPTION\n"
        << roff("amazeballs-cli runs the scenes of Amazeballs, the 2014 report's bouncing and colliding balls, "
                "without a window: trajectories as CSV, the window's charts as images, the report's figures, "
                "animations, accuracy and stability studies and benchmarks. Every bad argument is refused with "
                "one line on standard error naming it (with the nearest known name where one is near) and exit "
                "status 2.")
        << "\n.SH OPTIONS\n";
    optionItem(out, "help", "", "Print the commands and exit (also -h).");
    optionItem(out, "version", "", "Print the program's name and version and exit.");
    out << ".SH COMMANDS\n";
    for (const CommandSpec& c : commandTable()) {
        out << ".SS \"" << roff(c.synopsis()) << "\"\n" << roff(c.details) << "\n";
        if (c.operandValues != Values::None && c.operandValues != Values::File)
            out << ".PP\n" << roff(c.operand + " is one of " + joined(valueWords(c.operandValues)) + ".") << "\n";
        for (const OptionSpec& o : c.options)
            optionItem(out, o.name, o.value, optionText(o));
        optionItem(out, "help", "", "Print this command's usage (also -h).");
    }
    sceneSection(out);
    out << ".SH EXIT STATUS\n";
    for (const auto& [status, meaning] : exitStatuses())
        out << ".TP\n.B " << status << "\n" << roff(meaning) << "\n";
    out << ".SH EXAMPLES\n.nf\n"
        << roff("amazeballs-cli run bounce1d --summary\n"
                "amazeballs-cli run box3d --model physical --set k=0.75 --out box.csv\n"
                "amazeballs-cli chart two-balls --chart energy --out energy.svg\n"
                "amazeballs-cli help run")
        << "\n.fi\n.SH SEE ALSO\n.BR amazeballs (1)\n";
}

void writeWindowManPage(std::ostream& out, const PageInfo& info)
{
    header(out, "amazeballs", info, "bouncing and colliding balls, stage by stage, for teaching physics");
    out << ".SH SYNOPSIS\n.B amazeballs\n.RI [ OPTIONS ]\n.RI [ FILE.json ]\n"
           ".SH DESCRIPTION\n"
        << roff("amazeballs rebuilds the 2014 student report Amazeballs stage by stage: one ball bouncing in one "
                "dimension, one ball in a box, two balls colliding, and a few hundred balls in a box. It runs the "
                "report's own rules and textbook physics beside them, with charts, studies and a lecture mode. "
                "FILE.json is a preset to open. A bad option is refused with one line on standard error and exit "
                "status 2, before any window opens; --help and --version need no display.")
        << "\n.SH OPTIONS\n";
    optionItem(out, "help", "", "Print the options and exit (also -h).");
    optionItem(out, "help-all", "", "Print the options, Qt's among them, and exit.");
    optionItem(out, "version", "", "Print the program's name and version and exit (also -v).");
    for (const app::WindowOption& w : app::windowOptions())
        optionItem(out, w.name, w.value, w.help);
    sceneSection(out);
    out << ".SH EXIT STATUS\n.TP\n.B 0\nsuccess\n.TP\n.B 2\n"
        << roff("a bad option, value or preset: one line on standard error names it") << "\n"
        << ".SH SEE ALSO\n.BR amazeballs\\-cli (1)\n";
}

} // namespace ab::cli
