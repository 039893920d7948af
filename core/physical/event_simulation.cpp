// SPDX-License-Identifier: MIT
// Event-driven motion: exact, with no time step in the physics.
//  1. Between events every ball moves on a closed-form segment: the parabola
//     p0 + v0 t + a t^2 / 2 with a = gravity in flight, a = 0 at rest on the floor (or
//     the constant friction deceleration while it slides on a rough floor), and the spin
//     w0 + alpha t (constant in flight and rolling, alpha of rolling.h S2 while sliding).
//     A sliding ball's change to rolling is an event at its exact time t* (S3).
//  2. Wall and floor impacts are roots of quadratics; two balls under the same gravity
//     move in a straight line relative to each other, so their contact time is a quadratic
//     root too (a quartic when one of them rests on the floor). roots.h solves both.
//  3. Events sit in a priority queue by time. Each ball has a version that changes with
//     its segment; an event remembers the versions it was predicted from and is skipped
//     once either has changed (invalidation), so only the balls an event touches are
//     predicted again.
//  4. Zeno: a ball bouncing on the floor makes infinitely many impacts before its
//     accumulation time. A lone ball (bounce1d, box3d) enters a series segment at its
//     first such bounce: flights 2 u k^n / g launched at T_n = ts + 2u (1 - k^n) / (g (1 - k)),
//     summed to t_Z = ts + 2u / (g (1 - k)), where it rests. Its height at any time is read
//     off the series, so the run costs a few events for any k < 1. With other balls
//     around, each bounce is an event, until a bounce is too short for double precision
//     to follow (impacts.h, shortestFlight), when the ball rests.
//  5. Inelastic collapse: a ball caught between a wall and another ball (or between two
//     balls) with restitution below 1 collides ever more often, infinitely many times in
//     a finite time, as on the floor but with nothing to sum. As in the TC model of
//     Luding and McNamara (1998), a collision that follows the ball's previous one within
//     a contact time t_c (about 2e-10 of the clock, far below any real contact) is
//     elastic, which ends the collapse. Floor bounces keep the rest rule of 4 instead.
//     Balls resting on each other (a stack) need a contact model this one does not have;
//     the run stops with a message then.
// The step() of this simulation samples the exact motion every dt: --dt is the output
// interval. It continues from the state it returned last; any other state restarts it.
#include "impacts.h"
#include "integrators.h"
#include "physical_simulation.h"
#include "rolling.h"
#include "roots.h"

#include "../params.h"

#include <cmath>
#include <limits>
#include <queue>

namespace ab::physical {

namespace {

// More events than this in one sampling interval, or at one instant, means balls
// resting on each other, which needs a contact model this one does not have.
constexpr long long maxEventsPerStep = 1'000'000;
constexpr long long maxEventsAtOnce = 10'000;

struct Segment {
    double t0 = 0.0;
    Eigen::Vector3d p0 = Eigen::Vector3d::Zero(), v0 = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
    Eigen::Vector3d w0 = Eigen::Vector3d::Zero(), alpha = Eigen::Vector3d::Zero(); // spin
    double end = never; // a sliding ball rolls from here (friction, S3)
    int support = -1;   // the wall it slides on
    // Zeno series of a lone ball: the height is bounces launched from `floor` at ts with
    // speed u, each k times the last, until tRest.
    bool series = false;
    double ts = 0.0, u = 0.0, tRest = never;
    int floor = -1;
    long long logged = 0; // series bounces already written to the impact log
};

enum class Kind { Wall, Pair, Rest, Roll };

struct Event {
    double t;
    Kind kind;
    int i, j; // ball; other ball or wall
    unsigned vi, vj;
};

struct Later {
    bool operator()(const Event& a, const Event& b) const
    {
        if (a.t != b.t)
            return a.t > b.t;
        if (a.kind != b.kind)
            return a.kind > b.kind;
        return a.i != b.i ? a.i > b.i : a.j > b.j;
    }
};

class EventSimulation final : public PhysicalSimulation {
public:
    EventSimulation(const RunSpec& spec, double dt, World world, State initial)
        : PhysicalSimulation(spec, dt, std::move(world), std::move(initial))
    {
    }

    void step(State& s, State& next) override
    {
        if (!synced_ || !sameMotion(s, last_))
            resync(s);
        const double tEnd = s.t + dt_;
        run(tEnd);
        next = s;
        withSpin(next);
        next.t = tEnd;
        for (int i = 0; i < s.size(); ++i) {
            const Kinematics k = at(i, tEnd);
            next.p.col(i) = k.p;
            next.v.col(i) = k.v;
            next.w.col(i) = k.w;
        }
        next.count = count_;
        next.bounces = bounces_;
        last_ = next;
        synced_ = true;
    }

private:
    static bool sameMotion(const State& a, const State& b)
    {
        return a.t == b.t && a.p == b.p && a.v == b.v && a.spins() == b.spins() && (!a.spins() || a.w == b.w);
    }

    Segment& seg(int i) { return segments_[static_cast<std::size_t>(i)]; }
    const Segment& seg(int i) const { return segments_[static_cast<std::size_t>(i)]; }
    const Wall& wall(int w) const { return world_.walls[static_cast<std::size_t>(w)]; }

    void resync(const State& s)
    {
        const int n = s.size();
        segments_.assign(static_cast<std::size_t>(n), Segment{});
        versions_.assign(static_cast<std::size_t>(n), 0u);
        lastImpact_.assign(static_cast<std::size_t>(n), -never);
        queue_ = {};
        count_ = s.count;
        bounces_ = s.bounces;
        for (int i = 0; i < n; ++i)
            seg(i) = segmentFrom(i, s.t, {s.p.col(i), s.v.col(i), s.spin(i)});
        for (int i = 0; i < n; ++i)
            predict(i, s.t, i + 1);
    }

    // --- the closed-form motion ---

    Kinematics at(int i, double t) const
    {
        const Segment& g = seg(i);
        const double tau = std::min(t, g.end) - g.t0;
        Kinematics k{g.p0 + g.v0 * tau + 0.5 * tau * tau * g.a, g.v0 + g.a * tau, g.w0 + g.alpha * tau};
        if (t >= g.end) { // rolling on from t*, uniformly (no drag here)
            roll(world_, wall(g.support), k.v, k.w);
            k.p += k.v * (t - g.end);
        }
        if (g.series) {
            const auto [y, vy] = seriesHeight(g, t);
            k.p.y() = y;
            k.v.y() = vy;
        }
        return k;
    }

    // Launch time of bounce n of a series: T_n = ts + (2u/g) (1 - k^n) / (1 - k).
    double launchTime(const Segment& g, long long n) const
    {
        const double k = wall(g.floor).k;
        return g.ts + 2.0 * g.u / world_.g * (1.0 - std::pow(k, static_cast<double>(n))) / (1.0 - k);
    }

    // Height and vertical velocity at t on the series: find the bounce n with
    // T_n <= t < T_{n+1} (k^n = 1 - (t - ts) g (1 - k) / 2u, then checked), and fly it.
    std::pair<double, double> seriesHeight(const Segment& g, double t) const
    {
        const Wall& floor = wall(g.floor);
        if (t >= g.tRest)
            return {floor.position, 0.0};
        const double k = floor.k;
        long long n = 0;
        if (k > 0.0) {
            const double x = 1.0 - (t - g.ts) * world_.g * (1.0 - k) / (2.0 * g.u);
            n = x > 0.0 ? static_cast<long long>(std::max(0.0, std::floor(std::log(x) / std::log(k)))) : 0;
            while (n > 0 && launchTime(g, n) > t)
                --n;
            while (launchTime(g, n + 1) <= t)
                ++n;
        }
        const double un = g.u * std::pow(k, static_cast<double>(n));
        const double tau = t - launchTime(g, n);
        return {floor.position + un * tau - 0.5 * world_.g * tau * tau, un - world_.g * tau};
    }

    // The segment a ball starts at time t in state k: resting on the floor (sliding until
    // it rolls, S2-S3, or rolling) or flying under gravity.
    Segment segmentFrom(int i, double t, const Kinematics& k) const
    {
        Segment g;
        g.t0 = t;
        g.p0 = k.p;
        g.v0 = k.v;
        g.w0 = k.w;
        const Wall* support = restingOn(world_, k.p, k.v);
        const Rates r = rates(world_, i, k.v, k.w, support);
        g.a = r.a;
        g.alpha = r.alpha;
        const double h = rollTime(world_, i, k.v, k.w, support);
        if (h != never) {
            g.end = t + h;
            g.support = static_cast<int>(support - world_.walls.data());
        }
        return g;
    }

    bool rollsOn(int w, const Kinematics& k) const
    {
        return !world_.rough(wall(w)) || rolls(world_, wall(w), k.v, k.w);
    }

    // A lone ball leaving the floor at t with speed u enters the series when nothing
    // along the floor couples to its bounces (a smooth floor, or no slip at its contact
    // point: Walton's impulse is then zero at every bounce).
    bool seriesAllowed(int w, const Kinematics& k) const
    {
        const Wall& floor = wall(w);
        return world_.balls() == 1 && world_.supports(floor) && floor.k < 1.0 && rollsOn(w, k);
    }

    Segment seriesFrom(int i, int w, double t, const Kinematics& k) const
    {
        Segment g = segmentFrom(i, t, k);
        g.a.setZero(); // the height comes from the series; across the floor nothing acts
        g.series = true;
        g.floor = w;
        g.ts = t;
        g.u = wall(w).normalSpeed(k.v);
        const double kf = wall(w).k;
        // Accumulation (Zeno) time, written as launchTime's limit k^n -> 0 so that no
        // launch time rounds past it.
        g.tRest = g.ts + 2.0 * g.u / world_.g / (1.0 - kf);
        if (world_.restSpeed > 0.0 && kf > 0.0) {
            // The rest rule cuts the series at the first rebound u k^n <= restSpeed.
            const double n = std::ceil(std::log(world_.restSpeed / g.u) / std::log(kf));
            g.tRest = launchTime(g, static_cast<long long>(std::max(1.0, n)));
        }
        return g;
    }

    // --- predicting ---

    void push(double t, Kind kind, int i, int j)
    {
        const unsigned vj = kind == Kind::Pair ? versions_[static_cast<std::size_t>(j)] : 0u;
        queue_.push({t, kind, i, j, versions_[static_cast<std::size_t>(i)], vj});
    }

    // Events of ball i from time `now`: its walls, its series end or start of rolling, and
    // its pairs with every other ball (all of them when firstPartner is 0; on a restart
    // each pair once).
    void predict(int i, double now, int firstPartner = 0)
    {
        const Segment& g = seg(i);
        if (g.series)
            push(g.tRest, Kind::Rest, i, 0);
        else if (std::isfinite(g.end))
            push(g.end, Kind::Roll, i, 0);
        const Kinematics k = at(i, now);
        const Wall* support = g.series ? &wall(g.floor) : restingOn(world_, k.p, k.v);
        for (int w = 0; w < static_cast<int>(world_.walls.size()); ++w) {
            const Wall& wl = wall(w);
            if (&wl == support)
                continue;
            const Poly c{wl.gap(k.p), wl.normalSpeed(k.v), 0.5 * wl.side * g.a[wl.axis], 0.0, 0.0};
            const double h = firstInwardCrossing(c, g.end - now);
            if (h != never)
                push(now + h, Kind::Wall, i, w);
        }
        for (int j = firstPartner; j < world_.balls(); ++j)
            if (j != i)
                predictPair(std::min(i, j), std::max(i, j), now);
    }

    void predictPair(int i, int j, double now)
    {
        const Kinematics ki = at(i, now), kj = at(j, now);
        const double reach = 2.0 * world_.radius;
        // Relative motion d(h) = d0 + d1 h + d2 h^2: a straight line when both fly (d2 = 0).
        const Eigen::Vector3d d0 = ki.p - kj.p;
        const Eigen::Vector3d d1 = ki.v - kj.v;
        const Eigen::Vector3d d2 = 0.5 * (seg(i).a - seg(j).a);
        const Poly c{d0.squaredNorm() - reach * reach, 2.0 * d0.dot(d1), d1.squaredNorm() + 2.0 * d0.dot(d2),
                     2.0 * d1.dot(d2), d2.squaredNorm()};
        const double h = firstInwardCrossing(c, std::min(seg(i).end, seg(j).end) - now);
        if (h != never)
            push(now + h, Kind::Pair, i, j);
    }

    // --- running ---

    void run(double tEnd)
    {
        long long events = 0, atOnce = 0;
        double last = -never;
        while (!queue_.empty() && queue_.top().t <= tEnd) {
            const Event ev = queue_.top();
            queue_.pop();
            if (ev.vi != versions_[static_cast<std::size_t>(ev.i)] ||
                (ev.kind == Kind::Pair && ev.vj != versions_[static_cast<std::size_t>(ev.j)]))
                continue; // predicted from a segment that has since changed
            atOnce = ev.t == last ? atOnce + 1 : 0;
            last = ev.t;
            if (++events > maxEventsPerStep || atOnce > maxEventsAtOnce)
                throw InputError("--integrator event: endless impacts at t = " + formatNumber(ev.t) +
                                 " (balls resting on each other need a contact model this one does not have); "
                                 "choose a step integrator, e.g. verlet");
            logSeries(ev.t);
            handle(ev);
        }
        logSeries(tEnd);
    }

    void handle(const Event& ev)
    {
        switch (ev.kind) {
        case Kind::Wall:
            hitWall(ev.i, ev.j, ev.t);
            return;
        case Kind::Pair:
            hitPair(ev.i, ev.j, ev.t);
            return;
        case Kind::Rest:
        case Kind::Roll:
            restart(ev.i, ev.t, segmentFrom(ev.i, ev.t, at(ev.i, ev.t)));
            return;
        }
        throw std::logic_error("event without a rule");
    }

    void restart(int i, double t, Segment g)
    {
        seg(i) = std::move(g);
        ++versions_[static_cast<std::size_t>(i)];
        predict(i, t);
    }

    // A collision within the contact time of the ball's previous one (see 5 above).
    bool clustered(int i, double t) const
    {
        return t - lastImpact_[static_cast<std::size_t>(i)] <
               1e6 * std::numeric_limits<double>::epsilon() * std::abs(t);
    }

    void hitWall(int i, int w, double t)
    {
        Kinematics k = at(i, t);
        const Segment before = seg(i);
        k.p[wall(w).axis] = wall(w).position;
        const double vy = k.v.y();
        Wall hit = wall(w);
        if (!world_.supports(hit) && clustered(i, t))
            hit.k = 1.0;
        const double speed = resolveWallImpact(world_, hit, k.v, k.w, shortestFlight(world_, hit, t));
        if (speed > 0.0)
            count({t, i, -1, w, speed});
        if (before.series && k.v.y() == vy && rollsOn(before.floor, k)) {
            // A side wall that leaves the height alone, and the contact point on the floor
            // without slip: the series goes on.
            Segment g = segmentFrom(i, t, k);
            g.a.setZero();
            g.series = true;
            g.floor = before.floor;
            g.ts = before.ts;
            g.u = before.u;
            g.tRest = before.tRest;
            g.logged = before.logged;
            restart(i, t, std::move(g));
        } else if (world_.supports(wall(w)) && wall(w).normalSpeed(k.v) > 0.0 && seriesAllowed(w, k)) {
            restart(i, t, seriesFrom(i, w, t, k));
        } else {
            restart(i, t, segmentFrom(i, t, k));
        }
    }

    void hitPair(int i, int j, double t)
    {
        Kinematics ki = at(i, t), kj = at(j, t);
        separatePair(world_, i, j, ki.p, kj.p); // on the contact exactly (they are within round-off of it)
        const std::optional<double> e = clustered(i, t) || clustered(j, t) ? std::optional<double>(1.0) : std::nullopt;
        const double speed = resolvePairImpact(world_, i, j, ki.p, kj.p, ki.v, kj.v, {ki.w, kj.w}, e);
        if (speed > 0.0) {
            ++bounces_[static_cast<std::size_t>(j)];
            lastImpact_[static_cast<std::size_t>(j)] = t;
            count({t, i, j, -1, speed});
        }
        seg(j) = segmentFrom(j, t, kj);
        ++versions_[static_cast<std::size_t>(j)];
        restart(i, t, segmentFrom(i, t, ki));
        predict(j, t);
    }

    void count(const Impact& impact)
    {
        lastImpact_[static_cast<std::size_t>(impact.ball)] = impact.t;
        ++count_;
        ++bounces_[static_cast<std::size_t>(impact.ball)];
        logImpact(impact);
    }

    // The bounces inside a series happen without events; when impacts are logged they
    // are written as time passes them (while the clock can still tell them apart).
    void logSeries(double upTo)
    {
        if (!logging())
            return;
        for (int i = 0; i < world_.balls(); ++i) {
            Segment& g = seg(i);
            if (!g.series)
                continue;
            const double k = wall(g.floor).k;
            for (;;) {
                const double tn = launchTime(g, g.logged + 1);
                const double un = g.u * std::pow(k, static_cast<double>(g.logged));
                if (tn > upTo || tn >= g.tRest ||
                    tn - launchTime(g, g.logged) <= shortestFlight(world_, wall(g.floor), tn))
                    break;
                ++g.logged;
                logImpact({tn, i, -1, g.floor, un});
            }
        }
    }

    std::vector<Segment> segments_;
    std::vector<unsigned> versions_;
    std::vector<double> lastImpact_;
    std::priority_queue<Event, std::vector<Event>, Later> queue_;
    long long count_ = 0;
    std::vector<int> bounces_;
    State last_;
    bool synced_ = false;
};

} // namespace

std::unique_ptr<Simulation> makeEventSimulation(const RunSpec& spec, double dt, World world, State initial)
{
    return std::make_unique<EventSimulation>(spec, dt, std::move(world), std::move(initial));
}

} // namespace ab::physical
