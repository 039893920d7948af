// SPDX-License-Identifier: MIT
#include "roots.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ab::physical {

namespace {

int degreeOf(const Poly& c)
{
    for (int d = 4; d > 0; --d)
        if (c[static_cast<std::size_t>(d)] != 0.0)
            return d;
    return 0;
}

Poly derivative(const Poly& c)
{
    Poly d{};
    for (std::size_t i = 1; i < c.size(); ++i)
        d[i - 1] = static_cast<double>(i) * c[i];
    return d;
}

void keepInside(double x, double a, double b, std::vector<double>& out)
{
    if (x >= a && x <= b)
        out.push_back(x);
}

// Real roots of a polynomial of degree 1 or 2 in [a, b], ascending. The quadratic uses
// the cancellation-free form q = -(c1 + sign(c1) sqrt(D)) / 2, roots q/c2 and c0/q.
void lowDegreeRoots(const Poly& c, int degree, double a, double b, std::vector<double>& out)
{
    if (degree == 1) {
        keepInside(-c[0] / c[1], a, b, out);
        return;
    }
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc < 0.0)
        return;
    if (disc == 0.0) {
        keepInside(-c[1] / (2.0 * c[2]), a, b, out);
        return;
    }
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    double x1 = q / c[2];
    double x2 = c[0] / q;
    if (x1 > x2)
        std::swap(x1, x2);
    keepInside(x1, a, b, out);
    keepInside(x2, a, b, out);
}

// Bisection on [lo, hi] where f changes sign, down to adjacent doubles.
double bisect(const Poly& c, double lo, double hi, double fLo)
{
    for (int i = 0; i < 2100; ++i) {
        const double mid = lo + 0.5 * (hi - lo);
        if (mid <= lo || mid >= hi)
            break;
        const double fMid = evaluate(c, mid);
        if (fMid == 0.0)
            return mid;
        if ((fMid < 0.0) == (fLo < 0.0)) {
            lo = mid;
            fLo = fMid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// Real roots in [a, b], ascending: the derivative's roots split [a, b] into pieces on
// which f is monotone, and each piece holds at most one root (found by bisection).
void realRoots(const Poly& c, int degree, double a, double b, std::vector<double>& out)
{
    if (degree == 0)
        return;
    if (degree <= 2) {
        lowDegreeRoots(c, degree, a, b, out);
        return;
    }
    std::vector<double> points{a};
    realRoots(derivative(c), degree - 1, a, b, points);
    points.push_back(b);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double x0 = points[i], x1 = points[i + 1];
        const double f0 = evaluate(c, x0), f1 = evaluate(c, x1);
        if (f0 == 0.0) {
            if (out.empty() || out.back() != x0)
                out.push_back(x0);
        } else if ((f0 < 0.0) != (f1 < 0.0) && f1 != 0.0) {
            out.push_back(bisect(c, x0, x1, f0));
        }
    }
    if (evaluate(c, b) == 0.0 && (out.empty() || out.back() != b))
        out.push_back(b);
}

} // namespace

double evaluate(const Poly& c, double h)
{
    return (((c[4] * h + c[3]) * h + c[2]) * h + c[1]) * h + c[0];
}

double firstInwardCrossing(Poly c, double hMax)
{
    if (c[0] <= 0.0) {
        // Touching or (by round-off) just inside: moving in means the first non-zero
        // derivative at 0 is negative; moving out, the contact starts afresh from 0.
        for (std::size_t d = 1; d < c.size(); ++d) {
            if (c[d] != 0.0) {
                if (c[d] < 0.0)
                    return 0.0;
                break;
            }
        }
        c[0] = 0.0;
    }
    const int degree = degreeOf(c);
    if (degree == 0)
        return never;
    if (std::isfinite(hMax)) {
        // Most contacts are far away: f cannot fall by more than sum |c_i| hMax^i.
        double fall = 0.0, power = 1.0;
        for (int i = 1; i <= degree; ++i) {
            power *= hMax;
            fall += std::abs(c[static_cast<std::size_t>(i)]) * power;
        }
        if (fall < c[0])
            return never;
    } else {
        // Cauchy's bound: every real root satisfies |h| <= 1 + max |c_i / c_n|.
        double bound = 0.0;
        for (int i = 0; i < degree; ++i)
            bound = std::max(bound, std::abs(c[static_cast<std::size_t>(i)] / c[static_cast<std::size_t>(degree)]));
        hMax = 1.0 + bound;
    }
    std::vector<double> roots;
    realRoots(c, degree, 0.0, hMax, roots);
    const Poly slope = derivative(c);
    for (double h : roots)
        if (evaluate(slope, h) < 0.0)
            return h;
    return never;
}

double bracketedRoot(const std::function<double(double)>& f, double a, double fa, double b, double fb)
{
    // Illinois variant of regula falsi: superlinear, and it never leaves the bracket.
    int side = 0;
    for (int i = 0; i < 200; ++i) {
        if (b - a <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)))
            break;
        double x = (a * fb - b * fa) / (fb - fa);
        if (!(x > a && x < b))
            x = a + 0.5 * (b - a);
        const double fx = f(x);
        if (fx < 0.0) {
            b = x;
            fb = fx;
            if (side == -1)
                fa *= 0.5;
            side = -1;
        } else {
            a = x;
            fa = fx;
            if (side == 1)
                fb *= 0.5;
            side = 1;
        }
    }
    return a;
}

} // namespace ab::physical
