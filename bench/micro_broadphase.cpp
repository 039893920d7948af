// SPDX-License-Identifier: MIT
// Google Benchmark micro-benchmarks of the broadphase on the benchmark workload's start
// (a jittered lattice at about 10% volume fraction, radius 1): the counting-sort build,
// the pair search, and the all-pairs search it replaces. Items are balls, so the reported
// rate is balls per second. Built only with -DAMAZEBALLS_BENCH_MICRO=ON.
#include "core/broadphase/uniform_grid.h"
#include "core/physical/many_balls_physical.h"

#include <benchmark/benchmark.h>

namespace {

struct Workload {
    explicit Workload(int n)
        : n(n), side(ab::physical::benchmarkBoxSide(n)), start(ab::physical::jitteredGridStart(n, 1.0, side, 1.0, 2014))
    {
        grid.reset(ab::broadphase::GridGeometry(-side / 2.0 + 1.0, side - 2.0, 2.0, 8 * static_cast<std::size_t>(n)), n,
                   128);
        // In cell order, as the engine keeps its balls.
        grid.build(x(), y(), z());
        ab::State sorted = start;
        for (int q = 0; q < n; ++q)
            sorted.p.col(q) = start.p.col(grid.order()[static_cast<std::size_t>(q)]);
        start = sorted;
    }
    const double* x() const { return start.p.data(); }
    const double* y() const { return x() + n; }
    const double* z() const { return x() + 2 * n; }

    int n;
    double side;
    ab::State start;
    ab::broadphase::UniformGrid grid;
};

// Argument 1 of both grid benchmarks: the kernel (0 portable, 1 AVX2); skipped where the
// processor lacks it.
bool useKernel(benchmark::State& state, ab::broadphase::UniformGrid& grid)
{
    const auto kernel = static_cast<ab::broadphase::UniformGrid::Kernel>(state.range(1));
    if (!ab::broadphase::UniformGrid::runs(kernel)) {
        state.SkipWithError("this processor does not run the kernel");
        return false;
    }
    grid.setKernel(kernel);
    return true;
}

void GridBuild(benchmark::State& state)
{
    Workload w(static_cast<int>(state.range(0)));
    if (!useKernel(state, w.grid))
        return;
    for (auto _ : state) {
        w.grid.build(w.x(), w.y(), w.z());
        benchmark::DoNotOptimize(w.grid.order().data());
    }
    state.SetItemsProcessed(state.iterations() * w.n);
}

void GridFindPairs(benchmark::State& state)
{
    Workload w(static_cast<int>(state.range(0)));
    if (!useKernel(state, w.grid))
        return;
    w.grid.build(w.x(), w.y(), w.z());
    std::vector<ab::broadphase::Pair> pairs;
    for (auto _ : state) {
        pairs.clear();
        for (int s = 0; s < w.grid.slabCount(); ++s)
            w.grid.findPairs(s, w.x(), w.y(), w.z(), 4.0, pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.SetItemsProcessed(state.iterations() * w.n);
}

void AllPairs(benchmark::State& state)
{
    Workload w(static_cast<int>(state.range(0)));
    std::vector<ab::broadphase::Pair> pairs;
    for (auto _ : state) {
        pairs.clear();
        ab::broadphase::findAllPairs(w.x(), w.y(), w.z(), w.n, 4.0, pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.SetItemsProcessed(state.iterations() * w.n);
}

} // namespace

BENCHMARK(GridBuild)->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000}, {0, 1}});
BENCHMARK(GridFindPairs)->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000}, {0, 1}});
BENCHMARK(AllPairs)->Arg(1'000)->Arg(10'000);

BENCHMARK_MAIN();
