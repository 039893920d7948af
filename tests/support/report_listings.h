// SPDX-License-Identifier: MIT
// The report's MATLAB listings transcribed line by line (arrays indexed old/new as in
// Appendices A-C), as an independent oracle for the core's report model. Only the
// corrections the report itself documents are applied: eq 2.16's `+`, the new velocity
// in the stage-2 position update (eqs 2.18-2.22), and stage 3's Euclidean distance.
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace listing {

struct Series1d {
    std::vector<double> p, v;
};

// Appendix A. `grav` is signed (the listing's -0.0982).
inline Series1d appendixA(double grav, double k, double h0, double v0, int maxCount, int length, double delta_t = 1)
{
    Series1d s{std::vector<double>(length + 1, 0.0), std::vector<double>(length + 1, 0.0)};
    s.p[0] = h0;
    s.v[0] = v0;
    int count = 0;
    for (int dt = 1; dt <= length; ++dt) {
        const int index_new = dt;     // MATLAB dt+1, zero-based
        const int index_old = dt - 1; // MATLAB dt
        if (s.p[index_old] <= 0 && s.v[index_old] <= 0) {
            s.p[index_old] = 0;
            s.v[index_new] = -(k * s.v[index_old]);
            s.p[index_new] = s.v[index_new] * delta_t;
            count = count + 1;
        } else {
            s.v[index_new] = s.v[index_old] + grav * delta_t;
            s.p[index_new] = s.p[index_old] + s.v[index_old] * delta_t;
        }
        if (count > maxCount) {
            for (int i = index_old; i <= length; ++i)
                s.p[i] = s.v[i] = 0;
            break;
        }
    }
    return s;
}

using V3 = std::array<double, 3>;
struct Series3d {
    std::vector<V3> p, v;
};

// Appendix B with the position moved by v_matrix(:, index_new) (eqs 2.18-2.22).
inline Series3d appendixB(double gravY, double k, double L, V3 p0, V3 v0, int maxCount, int length,
                          double delta_t = 0.01)
{
    Series3d m{std::vector<V3>(length + 1, V3{0, 0, 0}), std::vector<V3>(length + 1, V3{0, 0, 0})};
    m.p[0] = p0;
    m.v[0] = v0;
    int count = 0;
    for (int dt = 1; dt <= length; ++dt) {
        const int n = dt, o = dt - 1;
        auto& P = m.p;
        auto& V = m.v;
        if (P[o][1] <= 0) {
            V[n][0] = V[o][0];
            P[n][0] = P[o][0] + V[n][0] * delta_t;
            P[o][1] = 0;
            V[n][1] = -(k * V[o][1]) + gravY * delta_t;
            P[n][1] = V[n][1] * delta_t;
            V[n][2] = V[o][2];
            P[n][2] = P[o][2] + V[n][2] * delta_t;
            count = count + 1;
        } else if (P[o][0] <= 0 || P[o][0] >= L) {
            P[o][0] = P[o][0] <= 0 ? 0 : L;
            V[n][0] = -(k * V[o][0]);
            P[n][0] = P[o][0] + V[n][0] * delta_t;
            V[n][1] = V[o][1] + gravY * delta_t;
            P[n][1] = P[o][1] + V[n][1] * delta_t;
            V[n][2] = V[o][2];
            P[n][2] = P[o][2] + V[n][2] * delta_t;
            count = count + 1;
        } else if (P[o][2] <= 0 || P[o][2] >= L) {
            V[n][0] = V[o][0];
            P[n][0] = P[o][0] + V[n][0] * delta_t;
            V[n][1] = V[o][1] + gravY * delta_t;
            P[n][1] = P[o][1] + V[n][1] * delta_t;
            P[o][2] = P[o][2] <= 0 ? 0 : L;
            V[n][2] = -(k * V[o][2]);
            P[n][2] = P[o][2] + V[n][2] * delta_t;
            count = count + 1;
        } else {
            V[n][0] = V[o][0];
            P[n][0] = P[o][0] + V[n][0] * delta_t;
            V[n][1] = V[o][1] + gravY * delta_t;
            P[n][1] = P[o][1] + V[n][1] * delta_t;
            V[n][2] = V[o][2];
            P[n][2] = P[o][2] + V[n][2] * delta_t;
        }
        if (count > maxCount) {
            for (int i = o; i <= length; ++i)
                P[i] = V[i] = V3{0, 0, 0};
        }
    }
    return m;
}

// Appendix C's propagation (works on copies of p_in, v_in).
inline void propagation(V3 p_in, V3 v_in, int& count, double gravY, double k, double L, double delta_t, V3& p_out,
                        V3& v_out)
{
    p_out = p_in;
    v_out = v_in;
    if (p_in[1] <= 0) {
        v_out[0] = v_in[0];
        p_out[0] = p_in[0] + v_out[0] * delta_t;
        p_in[1] = 0;
        v_out[1] = -(k * v_in[1]) + gravY * delta_t;
        p_out[1] = v_out[1] * delta_t;
        v_out[2] = v_in[2];
        p_out[2] = p_in[2] + v_out[2] * delta_t;
        count = count + 1;
    } else if (p_in[0] <= 0 || p_in[0] >= L) {
        p_in[0] = p_in[0] <= 0 ? 0 : L;
        v_out[0] = -(k * v_in[0]);
        p_out[0] = p_in[0] + v_out[0] * delta_t;
        v_out[1] = v_in[1] + gravY * delta_t;
        p_out[1] = p_in[1] + v_out[1] * delta_t;
        v_out[2] = v_in[2];
        p_out[2] = p_in[2] + v_out[2] * delta_t;
        count = count + 1;
    } else if (p_in[2] <= 0 || p_in[2] >= L) {
        v_out[0] = v_in[0];
        p_out[0] = p_in[0] + v_out[0] * delta_t;
        v_out[1] = v_in[1] + gravY * delta_t;
        p_out[1] = p_in[1] + v_out[1] * delta_t;
        p_in[2] = p_in[2] <= 0 ? 0 : L;
        v_out[2] = -(k * v_in[2]);
        p_out[2] = p_in[2] + v_out[2] * delta_t;
        count = count + 1;
    } else {
        v_out[0] = v_in[0];
        p_out[0] = p_in[0] + v_out[0] * delta_t;
        v_out[1] = v_in[1] + gravY * delta_t;
        p_out[1] = p_in[1] + v_out[1] * delta_t;
        v_out[2] = v_in[2];
        p_out[2] = p_in[2] + v_out[2] * delta_t;
    }
}

struct TwoBallSeries {
    Series3d b1, b2;
};

// Appendix C's main file.
inline TwoBallSeries appendixC(double gravY, double k, double e, double r, double L, V3 p1, V3 v1, V3 p2, V3 v2,
                               int maxCount, int length, double delta_t = 0.01)
{
    TwoBallSeries s;
    for (Series3d* b : {&s.b1, &s.b2}) {
        b->p.assign(length + 1, V3{0, 0, 0});
        b->v.assign(length + 1, V3{0, 0, 0});
    }
    s.b1.p[0] = p1;
    s.b1.v[0] = v1;
    s.b2.p[0] = p2;
    s.b2.v[0] = v2;
    int count = 0;
    for (int dt = 1; dt <= length; ++dt) {
        for (Series3d* b : {&s.b1, &s.b2})
            propagation(b->p[dt - 1], b->v[dt - 1], count, gravY, k, L, delta_t, b->p[dt], b->v[dt]);
        const V3 a = s.b1.p[dt], b = s.b2.p[dt];
        const double dist =
            std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        if (dist < 2 * r) {
            const V3 v1t = s.b1.v[dt], v2t = s.b2.v[dt];
            for (int i = 0; i < 3; ++i) {
                s.b1.v[dt][i] = v2t[i] * e;
                s.b2.v[dt][i] = v1t[i] * e;
            }
            count = count + 1;
        }
        if (count > maxCount)
            for (int i = dt - 1; i <= length; ++i)
                s.b1.v[i] = s.b2.v[i] = V3{0, 0, 0};
    }
    return s;
}

} // namespace listing
