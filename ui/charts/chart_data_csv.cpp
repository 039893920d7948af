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

// The columns of one run after t and ball: its header (prefixed for the comparison's) and a
// row of its samples. The ball's own cells are empty once it has left at the street's foot
// (where the engine holds it at rest, out of the run), the speeds' once no ball is left on
// the street.
class RunColumns {
public:
    explicit RunColumns(const ChartData& d)
        : d_(d), shown_(d.axes == 1 ? std::vector<int>{1} : std::vector<int>{0, 1, 2}), u_(unitsOf(d)),
          feet_(footBlocks(d.streetBlocks))
    {
    }

    const std::vector<int>& shown() const { return shown_; }
    const Units& units() const { return u_; }
    // The cells a row of samples() writes, for a comparison row with nothing recorded yet.
    std::size_t count() const
    {
        return 2 * shown_.size() + 9 + (d_.spins ? 5 : 0) + feet_.size() +
               (d_.streetBlocks > 0 ? std::size_t(kSpeedLines) + 1 : 0);
    }

    void header(std::ostream& out, const std::string& prefix) const
    {
        static const char* names[3] = {"x", "y", "z"};
        for (int a : shown_)
            out << "," << prefix << names[a] << " [" << u_.length << "]";
        for (int a : shown_)
            out << "," << prefix << "v" << names[a] << " [" << u_.speed << "]";
        for (const char* c : {"energy_total", "energy_kinetic", "energy_potential", "energy_spring"})
            out << "," << prefix << c << " [" << u_.energy << "]";
        for (const char* c : {"momentum_x", "momentum_y", "momentum_z"})
            out << "," << prefix << c << " [" << u_.momentum << "]";
        out << "," << prefix << "moving [balls]," << prefix << "impacts [1]";
        if (d_.spins) {
            for (int a = 0; a < 3; ++a)
                out << "," << prefix << "w" << names[a] << " [" << u_.spin << "]";
            for (const char* c : {"energy_translation", "energy_rotation"})
                out << "," << prefix << c << " [" << u_.energy << "]";
        }
        for (int block : feet_)
            out << "," << prefix << "past_foot_" << block + 1 << " [balls]";
        if (d_.streetBlocks > 0) {
            for (const char* c : {"speed_p10", "speed_median", "speed_p90", "speed_max"})
                out << "," << prefix << c << " [" << u_.speed << "]";
            out << "," << prefix << "energy_left [" << u_.energy << "]";
        }
    }

    void samples(Writer& w, const MotionTrack& m, std::size_t i) const
    {
        const bool ballHere = i < m.ballSamples();
        auto own = [&](double x) { ballHere ? w.put(x) : w.empty(1); };
        for (int a : shown_)
            own(m.p(a)[i]);
        for (int a : shown_)
            own(m.v(a)[i]);
        for (const auto* column : {&m.energy(), &m.kinetic(), &m.potential(), &m.spring()})
            w.put((*column)[i]);
        for (int a = 0; a < 3; ++a)
            w.put(m.momentum(a)[i]);
        w.put(static_cast<long long>(m.moving()[i]));
        w.put(m.impacts()[i]);
        if (d_.spins) {
            for (int a = 0; a < 3; ++a)
                own(m.w(a)[i]);
            w.put(m.translation()[i]);
            w.put(m.rotation()[i]);
        }
        for (std::size_t k = 0; k < feet_.size(); ++k)
            w.put(static_cast<long long>(m.pastFoot(int(k))[i]));
        if (d_.streetBlocks > 0) {
            for (int k = 0; k < kSpeedLines; ++k)
                i < m.streetSamples() ? w.put(m.speed(k)[i]) : w.empty(1);
            w.put(m.left()[i]);
        }
    }

private:
    const ChartData& d_;
    std::vector<int> shown_;
    Units u_;
    std::vector<int> feet_;
};

} // namespace

void writeChartCsv(std::ostream& out, const ChartData& d)
{
    static const char* names[3] = {"x", "y", "z"};
    const RunColumns columns(d);
    const Units& u = columns.units();
    for (const std::string& line : d.comments)
        out << "# " << line << "\n";
    out << "t [" << u.t << "],ball";
    columns.header(out, "");
    if (d.closedForm) {
        for (int a : columns.shown())
            out << "," << names[a] << "_closed_form [" << u.length << "]";
        for (int a : columns.shown())
            out << ",v" << names[a] << "_closed_form [" << u.speed << "]";
    }
    if (d.comparison) {
        out << ",compare_t [" << u.t << "]";
        columns.header(out, "compare_");
    }
    out << "\n";
    Writer w(out);
    const MotionTrack& run = *d.run;
    const MotionTrack* compare = d.comparison;
    std::size_t j = 0; // the comparison's last sample at or before the row's time
    for (std::size_t i = 0; i < run.size(); ++i) {
        const double t = run.t()[i];
        w.put(t, true);
        w.put(d.ball + 1);
        columns.samples(w, run, i);
        if (d.closedForm) {
            const std::optional<Kinematics> k = d.closedForm->at ? d.closedForm->at(t) : std::nullopt;
            for (int part = 0; part < 2; ++part)
                for (int a : columns.shown())
                    k ? w.put(part == 0 ? k->p[a] : k->v[a]) : w.empty(1);
        }
        if (compare) {
            while (j + 1 < compare->size() && compare->t()[j + 1] <= t)
                ++j;
            if (j < compare->size() && compare->t()[j] <= t) {
                w.put(compare->t()[j]);
                columns.samples(w, *compare, j);
            } else {
                w.empty(1 + columns.count()); // nothing recorded yet at this time
            }
        }
        out << "\n";
    }
}

} // namespace ab::ui
