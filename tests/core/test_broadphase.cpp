// SPDX-License-Identifier: MIT
// The broadphase: the counting-sort grid finds exactly the pairs the all-pairs test finds
// (random scenes, centres on cell boundaries, on and beyond the walls, huge boxes, any
// number of slabs), with the portable and the AVX2 kernel alike, pair for pair in the same
// order; its sort is stable and the same for any number of slabs and kernel, and the
// report's linked cells find the same lowest-index ball as a scan of every ball.
#include "core/broadphase/cell_list.h"
#include "core/broadphase/uniform_grid.h"
#include "core/random.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>

using ab::broadphase::GridGeometry;
using ab::broadphase::Pair;
using ab::broadphase::UniformGrid;

namespace {

struct Scene {
    ab::Vec3Array p;
    double lo = 0.0, side = 1.0, reach = 1.0;
};

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

// The pairs as (lower index, higher index); fails the test on a pair listed twice.
PairSet normalised(const std::vector<Pair>& pairs)
{
    PairSet set;
    for (const Pair& p : pairs) {
        const bool fresh = set.insert({std::min(p.a, p.b), std::max(p.a, p.b)}).second;
        if (!fresh || p.a == p.b)
            throw std::runtime_error("a pair listed twice, or a ball paired with itself");
    }
    return set;
}

PairSet allPairs(const Scene& s)
{
    std::vector<Pair> out;
    const int n = static_cast<int>(s.p.cols());
    const double* x = s.p.data();
    ab::broadphase::findAllPairs(x, x + n, x + 2 * n, n, s.reach * s.reach, out);
    return normalised(out);
}

// The pairs the grid lists with `kernel`, in the order it lists them.
std::vector<Pair> gridList(const Scene& s, int maxSlabs, std::size_t maxCells, UniformGrid::Kernel kernel)
{
    const int n = static_cast<int>(s.p.cols());
    const double* x = s.p.data();
    UniformGrid grid;
    grid.setKernel(kernel);
    grid.reset(GridGeometry(s.lo, s.side, s.reach, maxCells), n, maxSlabs);
    grid.build(x, x + n, x + 2 * n);
    std::vector<Pair> out;
    for (int slab = 0; slab < grid.slabCount(); ++slab)
        grid.findPairs(slab, x, x + n, x + 2 * n, s.reach * s.reach, out);
    return out;
}

bool sameList(const std::vector<Pair>& a, const std::vector<Pair>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const Pair& p, const Pair& q) { return p.a == q.a && p.b == q.b; });
}

// The grid's pairs. Every kernel this processor runs must list the same pairs in the same
// order (the order the contacts are resolved in); throws otherwise.
PairSet gridPairs(const Scene& s, int maxSlabs, std::size_t maxCells = 1u << 22)
{
    const std::vector<Pair> portable = gridList(s, maxSlabs, maxCells, UniformGrid::Kernel::Portable);
    if (UniformGrid::runs(UniformGrid::Kernel::Avx2) &&
        !sameList(gridList(s, maxSlabs, maxCells, UniformGrid::Kernel::Avx2), portable))
        throw std::runtime_error("the AVX2 kernel lists other pairs, or the same in another order");
    return normalised(portable);
}

Scene randomScene(int n, double side, double reach, std::uint64_t seed, double spill = 0.0)
{
    Scene s;
    s.lo = -side / 2.0;
    s.side = side;
    s.reach = reach;
    s.p.resize(3, n);
    ab::SplitMix64 rng(seed);
    for (int i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a)
            s.p(a, i) = s.lo - spill + (side + 2.0 * spill) * rng.uniform();
    return s;
}

// Centres on the cell boundaries and on the walls: every coordinate a whole number of
// cells from lo (cells 2.0625 wide, exact in binary, so the centres are exact too), each
// with a partner exactly `reach` away (not a pair: the test is strict) and one a hair
// closer (a pair).
Scene boundaryScene()
{
    Scene s;
    s.lo = -8.25;
    s.side = 16.5;
    s.reach = 2.0;
    const GridGeometry g(s.lo, s.side, s.reach, 1u << 20);
    const double h = g.cellSide();
    std::vector<Eigen::Vector3d> centres;
    ab::SplitMix64 rng(99);
    for (int i = 0; i < 400; ++i) {
        Eigen::Vector3d c;
        for (int a = 0; a < 3; ++a)
            c[a] = s.lo + h * static_cast<int>(rng.uniform() * (g.perAxis() + 1)); // up to lo + side
        centres.push_back(c);
        // A partner exactly reach away along a random axis, and one a hair closer.
        const int axis = static_cast<int>(rng.uniform() * 3);
        Eigen::Vector3d d = c;
        d[axis] += (rng.uniform() < 0.5 ? -1.0 : 1.0) * s.reach;
        centres.push_back(d);
        d[axis] = c[axis] + (d[axis] - c[axis]) * (1.0 - 1e-15);
        centres.push_back(d);
    }
    s.p.resize(3, static_cast<int>(centres.size()));
    for (int i = 0; i < static_cast<int>(centres.size()); ++i)
        s.p.col(i) = centres[static_cast<std::size_t>(i)];
    return s;
}

int brutalLowest(const ab::Vec3Array& p, int i, const Eigen::Vector3d& q, double reach)
{
    for (int j = 0; j < p.cols(); ++j)
        if (j != i && ab::broadphase::withinReach(q, p, j, reach))
            return j;
    return -1;
}

} // namespace

class Broadphase : public QObject {
    Q_OBJECT

private slots:
    void gridFindsExactlyTheAllPairsPairs_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("side");
        QTest::addColumn<double>("reach");
        QTest::addColumn<double>("spill");
        QTest::addColumn<int>("maxSlabs");
        QTest::addColumn<int>("maxCells");
        // Dense enough that most balls have several partners, so windows overflow 4 places.
        QTest::newRow("dense") << 3000 << 30.0 << 2.0 << 0.0 << 128 << (1 << 22);
        QTest::newRow("dense, five slabs") << 3000 << 30.0 << 2.0 << 0.0 << 5 << (1 << 22);
        QTest::newRow("dense, one slab") << 3000 << 30.0 << 2.0 << 0.0 << 1 << (1 << 22);
        // Several thousand balls: several blocks in the first stage.
        QTest::newRow("sparse, ten percent") << 9000 << 72.0 << 2.0 << 0.0 << 128 << (1 << 22);
        QTest::newRow("centres beyond the walls") << 2000 << 30.0 << 2.0 << 6.0 << 7 << (1 << 22);
        QTest::newRow("cells capped wider than reach") << 2000 << 40.0 << 2.0 << 0.0 << 128 << 64;
        QTest::newRow("one cell") << 300 << 3.0 << 2.0 << 1.0 << 128 << (1 << 22);
        // Coordinates near 1e6: the float pre-test's margin must still keep every pair.
        QTest::newRow("huge box") << 2000 << 2.0e6 << 1.5e5 << 0.0 << 128 << (1 << 22);
    }
    void gridFindsExactlyTheAllPairsPairs()
    {
        QFETCH(int, n);
        QFETCH(double, side);
        QFETCH(double, reach);
        QFETCH(double, spill);
        QFETCH(int, maxSlabs);
        QFETCH(int, maxCells);
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            const Scene s = randomScene(n, side, reach, seed, spill);
            const PairSet expected = allPairs(s);
            QVERIFY(expected.size() > static_cast<std::size_t>(n) / 20); // the scene has pairs to find
            QVERIFY(gridPairs(s, maxSlabs, static_cast<std::size_t>(maxCells)) == expected);
        }
    }

    void gridFindsExactlyTheAllPairsPairsOnCellBoundaries()
    {
        const Scene s = boundaryScene();
        QCOMPARE(GridGeometry(s.lo, s.side, s.reach, 1u << 20).cellSide(), 2.0625);
        const PairSet expected = allPairs(s);
        for (int slabs : {1, 3, 128})
            QVERIFY(gridPairs(s, slabs) == expected);
        // Exactly `reach` apart is not a pair (strict test); a hair closer is.
        for (std::uint32_t c = 0; c + 2 < static_cast<std::uint32_t>(s.p.cols()); c += 3) {
            QCOMPARE((s.p.col(c) - s.p.col(c + 1)).norm(), s.reach);
            QVERIFY(!expected.count({c, c + 1}));
            QVERIFY(expected.count({c, c + 2}));
        }
    }

    void sortIsStableAndTheSameForAnyNumberOfSlabs()
    {
        const Scene s = randomScene(9000, 40.0, 2.0, 17, 3.0);
        const int n = 9000;
        const double* x = s.p.data();
        const GridGeometry geo(s.lo, s.side, s.reach, 1u << 22);
        UniformGrid one;
        one.reset(geo, n, 128);
        one.build(x, x + n, x + 2 * n);
        // Every ball once; cells in increasing order; within a cell, increasing index.
        std::vector<std::uint32_t> sorted = one.order();
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < n; ++i)
            QCOMPARE(sorted[static_cast<std::size_t>(i)], static_cast<std::uint32_t>(i));
        const auto& start = one.cellStart();
        for (std::size_t c = 0; c + 1 < start.size(); ++c) {
            QVERIFY(start[c] <= start[c + 1]);
            for (std::uint32_t q = start[c]; q < start[c + 1]; ++q) {
                const std::uint32_t b = one.order()[q];
                QCOMPARE(geo.cellOf(s.p(0, b), s.p(1, b), s.p(2, b)), static_cast<std::uint32_t>(c));
                if (q > start[c])
                    QVERIFY(one.order()[q - 1] < b);
            }
        }
        for (int slabs : {1, 2, 11})
            for (auto kernel : {UniformGrid::Kernel::Portable, UniformGrid::Kernel::Avx2}) {
                if (!UniformGrid::runs(kernel))
                    continue;
                UniformGrid many;
                many.setKernel(kernel);
                many.reset(geo, n, slabs);
                many.build(x, x + n, x + 2 * n);
                QVERIFY(many.order() == one.order());
                QVERIFY(many.cellStart() == one.cellStart());
            }
    }

    void avx2KernelListsThePortablePairsInTheSameOrder()
    {
        // gridPairs compares the kernels in every test above; this one names it and checks
        // that windows longer than 4 places (the dense scene) and empty ones both occur.
        if (!UniformGrid::runs(UniformGrid::Kernel::Avx2))
            QSKIP("this processor has no AVX2: only the portable kernel runs");
        QVERIFY(UniformGrid::bestKernel() == UniformGrid::Kernel::Avx2);
        for (const auto& [n, side] : {std::pair{3000, 30.0}, {9000, 72.0}, {500, 400.0}}) {
            const Scene s = randomScene(n, side, 2.0, 8, 1.0);
            const auto portable = gridList(s, 128, 1u << 22, UniformGrid::Kernel::Portable);
            QVERIFY(sameList(gridList(s, 128, 1u << 22, UniformGrid::Kernel::Avx2), portable));
            QVERIFY(normalised(portable) == allPairs(s));
        }
        UniformGrid grid;
        grid.setKernel(UniformGrid::Kernel::Portable);
        QVERIFY(grid.kernel() == UniformGrid::Kernel::Portable);
    }

    void slabsOfOneParityShareNoBall()
    {
        // Slab s's pairs touch slabs s and s + 1 only, so even slabs (and odd slabs) can be
        // resolved at the same time.
        const Scene s = randomScene(4000, 30.0, 2.0, 5);
        const int n = 4000;
        const double* x = s.p.data();
        UniformGrid grid;
        grid.reset(GridGeometry(s.lo, s.side, s.reach, 1u << 22), n, 6);
        grid.build(x, x + n, x + 2 * n);
        for (int parity = 0; parity < 2; ++parity) {
            std::vector<int> owner(static_cast<std::size_t>(n), -1);
            for (int slab = parity; slab < grid.slabCount(); slab += 2) {
                std::vector<Pair> out;
                grid.findPairs(slab, x, x + n, x + 2 * n, 4.0, out);
                for (const Pair& p : out)
                    for (std::uint32_t b : {p.a, p.b}) {
                        QVERIFY(owner[b] == -1 || owner[b] == slab);
                        owner[b] = slab;
                    }
            }
        }
    }

    void geometryCellsAreAtLeastTheReachAndClampOutsiders()
    {
        const GridGeometry g(-5.0, 10.0, 2.0, 1u << 20);
        QCOMPARE(g.perAxis(), 4); // 10 / 2 = 5 would make cells exactly 2: a hair more is kept
        QVERIFY(g.cellSide() >= 2.0);
        QCOMPARE(g.coord(-100.0), 0);
        QCOMPARE(g.coord(100.0), 3);
        QCOMPARE(g.coord(std::nan("")), 0);
        QCOMPARE(g.coord(5.0), 3);
        const GridGeometry capped(0.0, 1000.0, 1.0, 1000);
        QVERIFY(capped.cellCount() <= std::size_t(12) * 12 * 12); // 10 a side and the border
    }

    void cellListFindsTheLowestIndexWithinReach()
    {
        Scene s = randomScene(1500, 30.0, 2.2, 8, 2.0);
        const GridGeometry geo(s.lo, s.side, s.reach, 1u << 20);
        ab::broadphase::CellList cells;
        cells.build(geo, s.p);
        ab::SplitMix64 rng(3);
        for (int round = 0; round < 3000; ++round) {
            const int i = static_cast<int>(rng.uniform() * 1500);
            // Move ball i somewhere (sometimes outside the cube), as the report's frame does.
            for (int a = 0; a < 3; ++a)
                s.p(a, i) = s.lo - 3.0 + (s.side + 6.0) * rng.uniform();
            const Eigen::Vector3d q = s.p.col(i);
            QCOMPARE(cells.lowestWithin(i, q, s.reach, s.p), brutalLowest(s.p, i, q, s.reach));
            cells.move(i, q.x(), q.y(), q.z());
        }
        // Rebuilding from the moved positions gives the same answers.
        cells.build(geo, s.p);
        for (int i = 0; i < 1500; i += 7)
            QCOMPARE(cells.lowestWithin(i, s.p.col(i), s.reach, s.p), brutalLowest(s.p, i, s.p.col(i), s.reach));
    }
};

QTEST_GUILESS_MAIN(Broadphase)
#include "test_broadphase.moc"
