// SPDX-License-Identifier: MIT
// `run`: simulate headless and write the trajectory CSV (stdout without --out).
#include "commands.h"

#include "interrupt.h"
#include "run_progress.h"
#include "run_setup.h"

#include "../../core/diagnostics/health.h"
#include "../../core/io/atomic_file.h"
#include "../../core/io/trajectory_csv.h"
#include "../../core/physical/physical_simulation.h"
#include "../../ui/charts/run_description.h"

#include <ostream>

namespace ab::cli {

namespace {

// What --summary prints: a few lines a person can read in a terminal.
struct Summary {
    long long states = 0;
    long long firstContactIndex = -1;
    double firstContactT = 0.0;
    double previousT = 0.0;
    double haltT = -1.0;
    double maxSpeed = 0.0;
    long long contacts = 0;
    long long contactsAtHalt = -1; // the counter when the report's limit stopped the motion
    long long haltIndex = -1;
    long long impacts = 0; // the many-balls engines' and the street's, each contact once
    bool perBall = false;  // the contacts are stage 4's counters, one per ball

    void observe(const State& s, long long index)
    {
        ++states;
        const long long counted = s.count + [&] {
            long long sum = 0;
            for (int b : s.bounces)
                sum += b;
            return sum;
        }();
        perBall = perBall || (counted > s.count);
        if ((counted > 0 || s.impacts > 0) && firstContactIndex < 0) {
            firstContactIndex = index;
            firstContactT = previousT; // the step from the previous state counted it
        }
        previousT = s.t;
        contacts = std::max(contacts, counted);
        impacts = std::max(impacts, s.impacts);
        // The limit marks the state the stopping step starts from (it zeroes that state's
        // velocities); the contact that passed the limit is counted in the state after it.
        if (s.halted && haltT < 0.0) {
            haltT = s.t;
            haltIndex = index;
            contactsAtHalt = counted;
        } else if (haltIndex >= 0 && index == haltIndex + 1) {
            contactsAtHalt = counted;
        }
        if (s.size() > 0)
            maxSpeed = std::max(maxSpeed, s.v.colwise().norm().maxCoeff());
    }

    // For reading, not for reading back: 12 significant digits, so that the round-off of 300
    // steps of 1/60 s reads 5, not 4.999999999999988 (the CSV keeps every digit).
    static std::string readable(double x) { return formatSignificant(x, 12); }

    void print(std::ostream& out, const Simulation& sim, const State& last) const
    {
        const SceneInfo& info = sim.scene();
        const RunSpec& spec = sim.spec();
        out << info.key << " (stage " << info.stage << "), " << modelKey(spec.model) << " model";
        if (spec.model == ModelKind::Physical)
            out << ", " << integratorKey(spec.integrator);
        out << ", dt " << formatStep(sim.dt()) << " " << info.timeUnit << ", " << (states - 1)
            << " steps to t = " << readable(last.t) << " " << info.timeUnit << "\n";
        if (firstContactIndex >= 0)
            out << "first contact: in the step from t = " << readable(firstContactT) << " " << info.timeUnit << "\n";
        // The report's counters (a scene's `count`, stage 4's bounces per ball); the engines
        // that count impacts instead (many-balls' physical model, the street) say so.
        // After the report's limit stops the motion its counter runs on, a contact each step for
        // a ball left below the floor or two balls touching at rest (Appendix C): the count that
        // means something is the one at the stop (two-balls: 101 there, 5184 after 60 s).
        if (contactsAtHalt >= 0 && contacts > contactsAtHalt)
            out << "contacts counted: " << contactsAtHalt << " up to the stop at t = " << readable(haltT) << " "
                << info.timeUnit << " (the report's counter runs on while the balls lie at rest: " << contacts
                << " by the end)\n";
        else if (contacts > 0 || impacts == 0)
            out << "contacts counted: " << contacts << (perBall ? " (the balls' bounce counters, summed)" : "") << "\n";
        if (impacts > 0)
            out << "impacts: " << impacts << " (ball on ball and on "
                << (spec.scene == SceneId::Street ? "the street" : "the walls") << ", each contact once)\n";
        if (haltT >= 0.0)
            out << "the report's bounce limit stopped the motion at t = " << readable(haltT) << " " << info.timeUnit
                << "\n";
        out << "largest speed: " << readable(maxSpeed) << " " << info.lengthUnit << "/" << info.timeUnit << "\n";
        const int shown = std::min(last.size(), 3);
        for (int i = 0; i < shown; ++i)
            out << "ball " << i << " at the end: position (" << readable(last.p(0, i)) << ", " << readable(last.p(1, i))
                << ", " << readable(last.p(2, i)) << "), velocity (" << readable(last.v(0, i)) << ", "
                << readable(last.v(1, i)) << ", " << readable(last.v(2, i)) << ")\n";
    }
};

// One line on stderr for the worst problem the health check met; a run that went
// non-finite exits with status 3.
int reportHealth(const diagnostics::HealthCheck& health, bool diverged, const State& last, const Simulation& sim,
                 std::ostream& err)
{
    const diagnostics::HealthStatus worst = health.worst();
    if (worst.level == diagnostics::Health::Ok)
        return 0;
    err << "amazeballs-cli: run: " << diagnostics::healthKey(worst.level) << ": " << worst.line();
    if (diverged)
        err << "; the run stopped there, the output ends at t = " << formatNumber(last.t) << " "
            << sim.scene().timeUnit;
    err << "\n";
    return diverged ? 3 : 0;
}

} // namespace

int runCommand(Parsed& args, std::ostream& out, std::ostream& err)
{
    const RunSetup setup = readRunSetup(args);
    const long long every = args.integer("every", 1, 1'000'000'000'000LL).value_or(1);
    const auto outPath = args.option("out");
    const bool summary = args.flag("summary");
    const bool meta = args.flag("meta");

    const auto sim = makeSimulation(setup.spec);
    if (outPath)
        checkWritable(*outPath); // fail before a long run, not after

    Summary sum;
    State last; // the last state written: a non-finite one never is
    const State start = sim->start();
    diagnostics::HealthCheck health(*sim, start);
    const bool spin = physical::hasRotation(*sim, start); // wx,wy,wz after the contract's columns
    bool diverged = false;
    const double tEnd = start.t + static_cast<double>(setup.steps) * sim->dt();
    const bool csvOnTerminal = !outPath && !summary && RunProgress::isTerminal(out); // rows show it going
    // For a person at a terminal, as the progress is (a script's standard error keeps its one line).
    if (!summary && !args.flag("quiet") && RunProgress::isTerminal(err))
        if (const auto note = largeTrajectoryNote(start.size(), setup.steps, every, spin))
            err << "amazeballs-cli: run: note: " << *note << std::endl; // before the run, not after
    RunProgress progress(err, !args.flag("quiet") && !csvOnTerminal && RunProgress::isTerminal(err), setup.steps, tEnd,
                         sim->scene().timeUnit);
    auto simulate = [&](std::ostream* csv) {
        long long index = 0;
        if (csv && meta) // `#` lines before the contract's header, only when asked for
            for (const std::string& line : ui::RunDescription::comments({&sim->spec(), sim->dt()}, nullptr, false, -1,
                                                                        start.size(), "trajectory"))
                *csv << "# " << line << "\n";
        if (csv)
            writeTrajectoryHeader(*csv, spin);
        runRecorded(
            *sim, start, setup.steps, 1,
            [&](const State& s) {
                if (index > 0 && health.check(last, s) == diagnostics::Health::Failed && health.figures().nonfinite) {
                    diverged = true; // stop before writing it
                    return;
                }
                if (csv && index % every == 0)
                    writeTrajectoryRows(*csv, s, spin);
                sum.observe(s, index);
                last = s;
                progress.update(index, s.t);
                ++index;
            },
            [&] { return diverged || interrupted(); });
        throwIfInterrupted();
    };
    if (outPath)
        writeFileAtomically(*outPath, [&](std::ostream& file) { simulate(&file); });
    else
        simulate(summary ? nullptr : &out);
    progress.end(); // before the summary and the health check's line
    if (summary)
        sum.print(out, *sim, last);
    return reportHealth(health, diverged, last, *sim, err);
}

} // namespace ab::cli
