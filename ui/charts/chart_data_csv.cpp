// SPDX-License-Identifier: MIT
#include "chart_data_csv.h"

#include "street_sample.h"

#include <charconv>
#include <string_view>

namespace ab::ui {

namespace {

struct Units {
    std::string t, length, speed, energy, momentum, spin;
};

Units unitsOf(const ChartData& d)
{
    // Energy is m |v|^2: mass length^2 / time^2; momentum m v: mass length / time.
    const std::string mass = d.perUnitMass ? "" : "kg ";
    const std::string speed = d.lengthUnit + "/" + d.timeUnit;
    return Units{d.timeUnit,   d.lengthUnit,       speed, mass + d.lengthUnit + "^2/" + d.timeUnit + "^2",
                 mass + speed, "rad/" + d.timeUnit};
}

class Writer {
public:
    explicit Writer(std::ostream& out) : out_(out) {}
    // Shortest round-trip form, independent of the locale (std::to_chars never reads it).
    template <typename T> void put(T x, bool first = false)
    {
        if (!first)
            out_ << ',';
        out_ << std::string_view(number_, std::to_chars(number_, number_ + sizeof number_, x).ptr);
    }
    void empty(std::size_t cells) { out_ << std::string(cells, ','); }

private:
    std::ostream& out_;
    char number_[32];
};

} // namespace

void writeChartCsv(std::ostream& out, const ChartData& d)
{
    static const char* names[3] = {"x", "y", "z"};
    const std::vector<int> shown = d.axes == 1 ? std::vector<int>{1} : std::vector<int>{0, 1, 2};
    const Units u = unitsOf(d);
    const std::vector<int> feet = footBlocks(d.streetBlocks);
    for (const std::string& line : d.comments)
        out << "# " << line << "\n";
    // The columns after t and ball, once for the run and once, prefixed, for the comparison.
    auto header = [&](const std::string& prefix) {
        for (int a : shown)
            out << "," << prefix << names[a] << " [" << u.length << "]";
        for (int a : shown)
            out << "," << prefix << "v" << names[a] << " [" << u.speed << "]";
        for (const char* c : {"energy_total", "energy_kinetic", "energy_potential", "energy_spring"})
            out << "," << prefix << c << " [" << u.energy << "]";
        for (const char* c : {"momentum_x", "momentum_y", "momentum_z"})
            out << "," << prefix << c << " [" << u.momentum << "]";
        out << "," << prefix << "moving [balls]," << prefix << "impacts [1]";
        if (d.spins) {
            for (int a = 0; a < 3; ++a)
                out << "," << prefix << "w" << names[a] << " [" << u.spin << "]";
            for (const char* c : {"energy_translation", "energy_rotation"})
                out << "," << prefix << c << " [" << u.energy << "]";
        }
        for (int block : feet)
            out << "," << prefix << "past_foot_" << block + 1 << " [balls]";
        if (d.streetBlocks > 0) {
            for (const char* c : {"speed_p10", "speed_median", "speed_p90", "speed_max"})
                out << "," << prefix << c << " [" << u.speed << "]";
            out << "," << prefix << "energy_left [" << u.energy << "]";
        }
    };
    out << "t [" << u.t << "],ball";
    header("");
    if (d.closedForm) {
        for (int a : shown)
            out << "," << names[a] << "_closed_form [" << u.length << "]";
        for (int a : shown)
            out << ",v" << names[a] << "_closed_form [" << u.speed << "]";
    }
    if (d.comparison) {
        out << ",compare_t [" << u.t << "]";
        header("compare_");
    }
    out << "\n";
    Writer w(out);
    // The ball's own cells are empty once it has left at the street's foot (where the engine
    // holds it at rest, out of the run), the speeds' once no ball is left on the street.
    auto row = [&](const MotionTrack& m, std::size_t i) {
        const bool ballHere = i < m.ballSamples();
        for (int part = 0; part < 2; ++part)
            for (int a : shown) {
                if (ballHere)
                    w.put(part == 0 ? m.p(a)[i] : m.v(a)[i]);
                else
                    w.empty(1);
            }
        w.put(m.energy()[i]);
        w.put(m.kinetic()[i]);
        w.put(m.potential()[i]);
        w.put(m.spring()[i]);
        for (int a = 0; a < 3; ++a)
            w.put(m.momentum(a)[i]);
        w.put(static_cast<long long>(m.moving()[i]));
        w.put(m.impacts()[i]);
        if (d.spins) {
            for (int a = 0; a < 3; ++a) {
                if (ballHere)
                    w.put(m.w(a)[i]);
                else
                    w.empty(1);
            }
            w.put(m.translation()[i]);
            w.put(m.rotation()[i]);
        }
        for (std::size_t k = 0; k < feet.size(); ++k)
            w.put(static_cast<long long>(m.pastFoot(int(k))[i]));
        if (d.streetBlocks > 0) {
            if (i < m.streetSamples())
                for (int k = 0; k < kSpeedLines; ++k)
                    w.put(m.speed(k)[i]);
            else
                w.empty(kSpeedLines);
            w.put(m.left()[i]);
        }
    };
    const MotionTrack& run = *d.run;
    const MotionTrack* compare = d.comparison;
    const std::size_t compareColumns = 1 + 2 * shown.size() + 9 + (d.spins ? 5 : 0) + feet.size() +
                                       (d.streetBlocks > 0 ? std::size_t(kSpeedLines) + 1 : 0);
    std::size_t j = 0; // the comparison's last sample at or before the row's time
    for (std::size_t i = 0; i < run.size(); ++i) {
        const double t = run.t()[i];
        w.put(t, true);
        w.put(d.ball + 1);
        row(run, i);
        if (d.closedForm) {
            const std::optional<Kinematics> k = d.closedForm->at ? d.closedForm->at(t) : std::nullopt;
            for (int part = 0; part < 2; ++part)
                for (int a : shown) {
                    if (k)
                        w.put(part == 0 ? k->p[a] : k->v[a]);
                    else
                        w.empty(1);
                }
        }
        if (compare) {
            while (j + 1 < compare->size() && compare->t()[j + 1] <= t)
                ++j;
            if (j < compare->size() && compare->t()[j] <= t) {
                w.put(compare->t()[j]);
                row(*compare, j);
            } else {
                w.empty(compareColumns); // nothing recorded yet at this time
            }
        }
        out << "\n";
    }
}

} // namespace ab::ui
