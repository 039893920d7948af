// SPDX-License-Identifier: MIT
// The contact phase of the many-balls engine (many_balls_physical.h): the pairs of balls
// in contact, found on the grid (or by all pairs), and the passes that resolve them:
// impulses along the line of centres, Walton's tangential impulse between rough balls,
// the resting contacts of a pile, and the projection that parts overlapping centres.
#include "many_balls_physical.h"

#include "many_balls_walls.h"
#include "pair_friction.h"
#include "worker_pool.h"

#include <algorithm>
#include <cmath>

namespace ab::physical {

using broadphase::Pair;

namespace {

constexpr double kTouching = 1.0 + 1e-6; // centres this close, relative to 2r, touch

} // namespace

void ManyBallsEngine::findPairs(int list)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    const double* x = p_.data();
    const double contact2 = 4.0 * settings_.radius * settings_.radius; // (2 r)^2
    auto& out = pairs_[static_cast<std::size_t>(list)];
    out.clear();
    if (settings_.broadphase == Broadphase::Grid) {
        grid_.findPairs(list, x, x + n, x + 2 * n, contact2, out); // one list per slab
        return;
    }
    const int chunks = static_cast<int>(pairs_.size());
    broadphase::findAllPairs(x, x + n, x + 2 * n, settings_.n, broadphase::allPairsRowBegin(settings_.n, list, chunks),
                             broadphase::allPairsRowBegin(settings_.n, list + 1, chunks), contact2, out);
}

void ManyBallsEngine::resolvePass(Pass pass, bool shared)
{
    if (settings_.broadphase != Broadphase::Grid) {
        // The all-pairs lists, joined in row order, are one sequence whatever the thread
        // count; they are resolved in that order on one thread.
        for (const auto& list : pairs_)
            resolveList(list, pass, 0);
        return;
    }
    const int slabs = grid_.slabCount();
    for (int parity = 0; parity < 2; ++parity) {
        const int count = (slabs - parity + 1) / 2; // slabs parity, parity + 2, ...
        const auto resolve = [&](int j, int w) {
            resolveList(pairs_[static_cast<std::size_t>(parity + 2 * j)], pass, w);
        };
        if (shared) {
            pool_->forEach(count, resolve);
        } else {
            for (int j = 0; j < count; ++j)
                resolve(j, 0);
        }
    }
}

void ManyBallsEngine::resolveList(const std::vector<Pair>& pairs, Pass pass, int worker)
{
    const auto n = static_cast<std::size_t>(settings_.n);
    double* x = p_.data();
    double* y = x + n;
    double* z = y + n;
    double* vx = v_.data();
    double* vy = vx + n;
    double* vz = vy + n;
    const double contact = 2.0 * settings_.radius;
    const double reach2 = pass == Pass::Support ? contact * contact * kTouching * kTouching : contact * contact;
    const double e = settings_.ballRestitution;
    double& maxSpeed2 = workerMaxSpeed2_[static_cast<std::size_t>(worker)];
    long long pairRebounds = 0; // added to the worker's tally once, at the end: the tallies
                                // of two workers share a cache line
    const auto speed2 = [&](std::uint32_t i) { return vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]; };
    const bool rough = settings_.rough();
    const manyballs::Friction friction{settings_.mu, settings_.beta, settings_.inertia, settings_.radius};
    double* w = w_.data();
    const auto pairFriction = [&](std::uint32_t a, std::uint32_t b, double nx, double ny, double nz, double pn) {
        PairVelocities pair{{vx[a], vy[a], vz[a]},
                            {vx[b], vy[b], vz[b]},
                            {w[a], w[a + n], w[a + 2 * n]},
                            {w[b], w[b + n], w[b + 2 * n]}};
        waltonBetween(pair, Eigen::Vector3d(nx, ny, nz), pn, friction);
        vx[a] = pair.va.x(), vy[a] = pair.va.y(), vz[a] = pair.va.z();
        vx[b] = pair.vb.x(), vy[b] = pair.vb.y(), vz[b] = pair.vb.z();
        for (std::size_t k = 0; k < 3; ++k)
            w[a + k * n] = pair.wa[static_cast<Eigen::Index>(k)], w[b + k * n] = pair.wb[static_cast<Eigen::Index>(k)];
    };
    const auto inside = [&](double& c) { c = std::clamp(c, lo_, hi_); };
    for (const Pair& pair : pairs) {
        std::uint32_t a = pair.a, b = pair.b;
        if (pass == Pass::Support && y[b] < y[a])
            std::swap(a, b); // a below b
        double nx = x[b] - x[a], ny = y[b] - y[a], nz = z[b] - z[a];
        const double d2 = nx * nx + ny * ny + nz * nz;
        if (!(d2 < reach2))
            continue; // parted by an earlier contact
        const double d = std::sqrt(d2);
        if (d > 0.0) {
            nx /= d, ny /= d, nz /= d;
        } else {
            nx = 0.0, ny = 1.0, nz = 0.0; // coincident centres: part them vertically
        }
        // The normal relative velocity, negative while the two approach.
        const double u = (vx[b] - vx[a]) * nx + (vy[b] - vy[a]) * ny + (vz[b] - vz[a]) * nz;
        if (pass == Pass::Support) {
            // Shock propagation (Guendelman, Bridson, Fedkiw 2003) for resting contacts only
            // (slower than the rest speed): a ball resting on a supported ball below it is
            // stopped along the normal as if that ball were held by what is under it, which
            // lets a pile come to rest in one pass instead of many. Only the upper ball
            // changes, and only when the lower one does not move towards it (va.n <= 0), so
            // its kinetic energy falls by u^2 + 2 u (va.n) >= u^2. It needs gravity (the rest
            // speed is 0 without it), so free collisions keep their momentum.
            if (!supported_[a] || !(ny > 0.0) || !(std::abs(u) < restSpeed_))
                continue;
            const double lowerTowards = vx[a] * nx + vy[a] * ny + vz[a] * nz;
            if (u < 0.0 && lowerTowards <= 0.0)
                vx[b] -= u * nx, vy[b] -= u * ny, vz[b] -= u * nz;
            supported_[b] = 1;
            if (speed2(b) < restSpeed_ * restSpeed_)
                vx[b] = vy[b] = vz[b] = 0.0;
            continue;
        }
        if (u < 0.0) {
            // Eqs 2.4-2.7 along the normal n (a to b), equal masses: u becomes -e u; an
            // impulse j n on a and -j n on b with j = (1 + e) u / 2 keeps the momentum va + vb
            // and changes the kinetic energy by (e^2 - 1) u^2 / 4 <= 0. Smooth balls keep their
            // tangential parts (eqs 2.8-2.9); rough ones exchange Walton's impulse (S11-S12,
            // waltonBetween). A rebound slower than the rest speed is stopped.
            const double rebound = -e * u;
            const bool bounces = rebound > 0.0 && rebound >= restSpeed_;
            const double j = 0.5 * (1.0 + (bounces ? e : 0.0)) * u;
            if (rough)
                pairFriction(a, b, nx, ny, nz, (1.0 + (bounces ? e : 0.0)) * -u);
            vx[a] += j * nx, vy[a] += j * ny, vz[a] += j * nz;
            vx[b] -= j * nx, vy[b] -= j * ny, vz[b] -= j * nz;
            if (bounces) {
                ++rebounds_[a];
                ++rebounds_[b];
                ++pairRebounds; // the pair's impact, once
            }
            maxSpeed2 = std::max({maxSpeed2, speed2(a), speed2(b)});
        }
        // Projection: each centre moves half the overlap along n, which leaves their mean
        // where it was and the velocities as they are; the walls stay hard.
        const double half = 0.5 * (contact - d);
        x[a] -= half * nx, y[a] -= half * ny, z[a] -= half * nz;
        x[b] += half * nx, y[b] += half * ny, z[b] += half * nz;
        inside(x[a]), inside(y[a]), inside(z[a]);
        inside(x[b]), inside(y[b]), inside(z[b]);
    }
    workerImpacts_[static_cast<std::size_t>(worker)] += pairRebounds;
}

} // namespace ab::physical
