// SPDX-License-Identifier: MIT
// The benchmark workload of `amazeballs-cli bench` run in Bullet Physics 3 and in the
// physical many-balls engine, one after the other in one process, so that the two costs
// per ball-step come from the same machine at the same time. Built only with
// -DAMAZEBALLS_BENCH_BULLET=ON (Debian: libbullet-dev).
//
// Bullet gets the same start, gravity and step: unit spheres of unit mass with no
// friction and no sleeping, six static planes for the walls, one stepSimulation(dt, 0) per
// step (exactly one internal step), default btDbvtBroadphase and sequential-impulse solver
// (10 iterations). Bullet multiplies the restitutions of the two bodies in contact, so the
// balls get sqrt(0.95) and the walls 0.9 / sqrt(0.95): 0.95 between balls, 0.9 at walls.
#include "app/cli/bench_protocol.h"
#include "core/physical/many_balls_physical.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr int kWarmupSteps = 100;
constexpr double kDt = 1.0 / 240.0;

struct Options {
    std::vector<int> balls;
    int steps = 200;
    int repeats = 3;
    std::string out, markdown;
};

[[noreturn]] void bad(const std::string& what)
{
    std::cerr << "amazeballs-bench-bullet: " << what << "\n";
    std::exit(2);
}

int positive(const std::string& option, const char* text, long long max)
{
    char* end = nullptr;
    const long long v = std::strtoll(text, &end, 10);
    if (end == text || *end != '\0' || v < 1 || v > max)
        bad(option + ": '" + text + "' is not a whole number in [1, " + std::to_string(max) + "]");
    return static_cast<int>(v);
}

Options readOptions(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc)
            bad(a + ": missing value (options: --balls N... --steps S --repeats R --out FILE.csv --markdown FILE.md)");
        const char* value = argv[++i];
        if (a == "--balls")
            o.balls.push_back(positive(a, value, 4'000'000));
        else if (a == "--steps")
            o.steps = positive(a, value, 1'000'000);
        else if (a == "--repeats")
            o.repeats = positive(a, value, 99);
        else if (a == "--out")
            o.out = value;
        else if (a == "--markdown")
            o.markdown = value;
        else
            bad("unknown option '" + a + "'");
    }
    if (o.balls.empty())
        o.balls = {150, 1'000, 10'000, 100'000};
    return o;
}

// The workload's world in Bullet: owns everything it allocates.
class BulletWorld {
public:
    BulletWorld(const ab::State& start, double box)
        : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_), sphere_(1.0)
    {
        world_.setGravity(btVector3(0, -9.82, 0));
        btVector3 inertia(0, 0, 0);
        sphere_.calculateLocalInertia(1.0, inertia);
        const btScalar ballRestitution = std::sqrt(0.95);
        for (int i = 0; i < start.size(); ++i) {
            btRigidBody::btRigidBodyConstructionInfo info(1.0, nullptr, &sphere_, inertia);
            info.m_startWorldTransform.setIdentity();
            info.m_startWorldTransform.setOrigin(btVector3(start.p(0, i), start.p(1, i), start.p(2, i)));
            info.m_restitution = ballRestitution;
            info.m_friction = 0;
            add(std::make_unique<btRigidBody>(info))
                ->setLinearVelocity(btVector3(start.v(0, i), start.v(1, i), start.v(2, i)));
        }
        // Walls at +-box/2: a plane n.x = d with n pointing into the box.
        for (int axis = 0; axis < 3; ++axis)
            for (double sign : {1.0, -1.0}) {
                btVector3 normal(0, 0, 0);
                normal[axis] = sign;
                planes_.push_back(std::make_unique<btStaticPlaneShape>(normal, -box / 2.0));
                btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, planes_.back().get());
                info.m_restitution = 0.9 / ballRestitution;
                info.m_friction = 0;
                add(std::make_unique<btRigidBody>(info));
            }
    }
    ~BulletWorld()
    {
        for (auto& body : bodies_)
            world_.removeRigidBody(body.get());
    }

    void step() { world_.stepSimulation(kDt, 0); }

    double kineticEnergy() const
    {
        double e = 0.0;
        for (const auto& body : bodies_)
            if (body->getInvMass() > 0)
                e += 0.5 * body->getLinearVelocity().length2();
        return e;
    }

private:
    btRigidBody* add(std::unique_ptr<btRigidBody> body)
    {
        body->setActivationState(DISABLE_DEACTIVATION);
        world_.addRigidBody(body.get());
        bodies_.push_back(std::move(body));
        return bodies_.back().get();
    }

    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    btSphereShape sphere_;
    std::vector<std::unique_ptr<btStaticPlaneShape>> planes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

struct Row {
    int balls;
    std::string engine;
    ab::cli::BallStepTiming timing;
    double kineticEnergy;
};

std::string number(double x, const char* format)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, x);
    return buffer;
}

} // namespace

int main(int argc, char** argv)
{
    const Options o = readOptions(argc, argv);
    std::vector<Row> rows;
    const auto nothing = [] {};
    for (int n : o.balls) {
        const ab::RunSpec spec = ab::physical::benchmarkSpec(n, ab::ModelKind::Physical, ab::Broadphase::Grid, 1);
        {
            ab::physical::ManyBallsEngine engine(ab::physical::ManyBallsSettings::fromSpec(spec, *spec.dt));
            const auto t = ab::cli::timeBallSteps(
                n, kWarmupSteps, o.steps, o.repeats, [&] { engine.load(*spec.init); }, [&] { engine.step(); }, nothing);
            ab::State end;
            engine.store(end);
            rows.push_back({n, "amazeballs", t, 0.5 * end.v.squaredNorm()});
        }
        {
            std::unique_ptr<BulletWorld> world;
            const auto t = ab::cli::timeBallSteps(
                n, kWarmupSteps, o.steps, o.repeats,
                [&] {
                    world.reset(); // one world at a time
                    world = std::make_unique<BulletWorld>(*spec.init, ab::physical::benchmarkBoxSide(n));
                },
                [&] { world->step(); }, nothing);
            rows.push_back({n, "bullet", t, world->kineticEnergy()});
        }
        const Row& ours = rows[rows.size() - 2];
        const Row& theirs = rows.back();
        std::cout << n << " balls: amazeballs " << number(ours.timing.nsPerBallStep, "%.1f") << " ns, Bullet "
                  << number(theirs.timing.nsPerBallStep, "%.1f") << " ns per ball-step ("
                  << number(theirs.timing.nsPerBallStep / ours.timing.nsPerBallStep, "%.0f") << "x)" << std::endl;
    }
    const double rss = ab::cli::peakResidentMiB();
    auto csv = [&](std::ostream& out) {
        out << "balls,engine,threads,ns_per_ball_step,steps_per_second,cpu_ns_per_ball_step,kinetic_energy_at_end\n";
        for (const Row& r : rows)
            out << r.balls << "," << r.engine << ",1," << number(r.timing.nsPerBallStep, "%.4g") << ","
                << number(r.timing.stepsPerSecond, "%.4g") << "," << number(r.timing.cpuNsPerBallStep, "%.4g") << ","
                << number(r.kineticEnergy, "%.6g") << "\n";
    };
    if (!o.out.empty()) {
        std::ofstream file(o.out);
        csv(file);
    } else {
        csv(std::cout);
    }
    if (!o.markdown.empty()) {
        std::ofstream md(o.markdown);
        md << "| balls | amazeballs ns per ball-step | Bullet 3 ns per ball-step | Bullet / amazeballs | CPU ns, "
              "amazeballs / Bullet | kinetic energy at the end, amazeballs / Bullet |\n"
              "| ---: | ---: | ---: | ---: | ---: | ---: |\n";
        for (std::size_t i = 0; i + 1 < rows.size(); i += 2)
            md << "| " << rows[i].balls << " | " << number(rows[i].timing.nsPerBallStep, "%.1f") << " | "
               << number(rows[i + 1].timing.nsPerBallStep, "%.0f") << " | "
               << number(rows[i + 1].timing.nsPerBallStep / rows[i].timing.nsPerBallStep, "%.0f") << "x | "
               << number(rows[i].timing.cpuNsPerBallStep, "%.1f") << " / "
               << number(rows[i + 1].timing.cpuNsPerBallStep, "%.0f") << " | " << number(rows[i].kineticEnergy, "%.4g")
               << " / " << number(rows[i + 1].kineticEnergy, "%.4g") << " |\n";
        md << "\nOne thread each; the median of " << o.repeats << " runs from the start, each " << kWarmupSteps
           << " warm-up steps then " << o.steps << " timed steps; peak resident memory of the process "
           << number(rss, "%.0f") << " MiB.\n";
    }
    return 0;
}
