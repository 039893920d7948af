// SPDX-License-Identifier: MIT
// `stability`: the suite of stiff and extreme cases (core/stability), as a table on
// stdout and, on request, CSV and markdown files.
#include "commands.h"
#include "suggest.h"

#include "interrupt.h"

#include "../../core/io/atomic_file.h"
#include "../../core/stability/suite.h"

#include <ostream>

namespace ab::cli {

namespace {

std::vector<const stability::StabilityCase*> selectedCases(const std::vector<std::string>& names)
{
    std::vector<const stability::StabilityCase*> cases;
    for (const std::string& name : names) {
        const stability::StabilityCase* c = stability::findCase(name);
        if (!c)
            throw InputError("--case: unknown case '" + printableInput(name) + "'" +
                             nearOrChoices(name, valueWords(Values::Case)));
        cases.push_back(c);
    }
    if (names.empty())
        for (const stability::StabilityCase& c : stability::stabilityCases())
            cases.push_back(&c);
    return cases;
}

// The closing lines: how many rows of each verdict, and the rows that could not run.
void printTally(std::ostream& out, const std::vector<stability::RowResult>& rows)
{
    int ok = 0, degraded = 0, failed = 0, missing = 0, skipped = 0;
    for (const stability::RowResult& r : rows) {
        if (r.outcome == stability::RowOutcome::NotAvailable)
            ++missing;
        else if (r.outcome == stability::RowOutcome::Skipped)
            ++skipped;
        else
            (r.verdict == "ok" ? ok : r.verdict == "degraded" ? degraded : failed)++;
    }
    out << rows.size() << " rows: " << ok << " ok, " << degraded << " degraded, " << failed << " failed";
    if (missing > 0)
        out << "; " << missing << " not available in this build (no figures)";
    if (skipped > 0)
        out << "; " << skipped << " not run";
    out << "\n";
}

} // namespace

int stabilityCommand(Parsed& args, std::ostream& out, std::ostream&)
{
    const std::vector<std::string> names = args.options("case");
    const auto csvPath = args.option("out");
    const auto markdownPath = args.option("markdown");
    const bool list = args.flag("list");
    const auto cases = selectedCases(names);
    if (list) {
        for (const stability::StabilityCase* c : cases)
            out << c->name << ": " << c->summary << "\n";
        return 0;
    }
    if (csvPath)
        checkWritable(*csvPath);
    if (markdownPath)
        checkWritable(*markdownPath);

    std::vector<stability::RowResult> results;
    for (const stability::StabilityCase* c : cases) {
        for (const stability::CaseRow& row : c->rows()) {
            results.push_back(stability::runRow(row, interrupted));
            throwIfInterrupted();
        }
    }
    for (const stability::StabilityCase* c : cases)
        if (c->name == "stiff-spring") {
            out << "Stability limits on the undamped oscillator (growth x10 within 1000 steps):\n";
            stability::writeLimits(out);
            out << "\n";
        }
    stability::writeTable(out, results);
    printTally(out, results);
    if (csvPath)
        writeFileAtomically(*csvPath, [&](std::ostream& f) { stability::writeCsv(f, results); });
    if (markdownPath)
        writeFileAtomically(*markdownPath, [&](std::ostream& f) {
            f << "## Stability limits of dt omega0 on the undamped oscillator\n\n";
            stability::writeLimits(f);
            f << "\n## Cases\n\n";
            stability::writeMarkdown(f, results);
        });
    return 0;
}

} // namespace ab::cli
