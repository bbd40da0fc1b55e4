// Test support for the BSDFs (tests/bsdf.test.cpp, tests/bsdf_chi2.cpp): integrals of a density
// over cells of the (cos theta, phi) square, with the quadrature nodes graded toward a known peak
// (the mirror direction), and the chi-square test's p-value. Written without phong's code: the
// integrand is the only thing taken from the library under test.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace phong_test::bsdf_quad {

inline constexpr double pi = 3.14159265358979323846;

/// The break points of [a, b] for a composite rule: its quarters and p +- w 2^j (j = 0, 1, ...) inside,
/// so that panels are about as wide as their distance to the peak p (w: the narrowest scale of
/// the integrand there). Points closer to the interval than the peak are kept too (a peak just
/// outside the interval still makes it steep at that end).
inline std::vector<double> graded_breaks(double a, double b, double p, double w)
{
    std::vector<double> x{a, a + (b - a) / 4, a + (b - a) / 2, a + 3 * (b - a) / 4, b};
    const double q = std::clamp(p, a, b);
    if (w > 0 && std::abs(q - p) < 64 * (b - a) + 1) {
        x.push_back(q);
        for (double d = w; d < 2 * (b - a); d *= 2) {
            if (q - d > a) x.push_back(q - d);
            if (q + d < b) x.push_back(q + d);
        }
    }
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
    return x;
}

/// Gauss-Legendre, 6 nodes on [-1, 1].
inline constexpr double gl_x[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                   0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
inline constexpr double gl_w[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                   0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

/// Nodes and weights of a composite 6-point Gauss-Legendre rule over the panels between breaks.
inline void composite_rule(const std::vector<double>& breaks, std::vector<double>& x, std::vector<double>& w)
{
    x.clear();
    w.clear();
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double mid = (breaks[i] + breaks[i + 1]) / 2, half = (breaks[i + 1] - breaks[i]) / 2;
        for (int k = 0; k < 6; ++k) {
            x.push_back(mid + half * gl_x[k]);
            w.push_back(half * gl_w[k]);
        }
    }
}

/// The direction of (z = cos theta, phi) in the local frame.
struct dir3 { double x, y, z; };
inline dir3 direction(double z, double phi)
{
    const double s = std::sqrt(std::max(0.0, (1 - z) * (1 + z)));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

/// int over z in [z0, z1], phi in [p0, p1] of pdf(direction(z, phi)) dz dphi (= the probability
/// of the cell: dw = dz dphi), the rule graded toward the peak (zp, pp) with scales wz, wp.
/// The peak's phi is taken modulo 2 pi nearest to the cell.
template <class Pdf>
double cell_integral(const Pdf& pdf, double z0, double z1, double p0, double p1, double zp, double pp, double wz, double wp)
{
    const double pc = (p0 + p1) / 2;
    while (pp - pc > pi) pp -= 2 * pi;
    while (pc - pp > pi) pp += 2 * pi;
    std::vector<double> zx, zw, px, pw;
    composite_rule(graded_breaks(z0, z1, zp, wz), zx, zw);
    composite_rule(graded_breaks(p0, p1, pp, wp), px, pw);
    double sum = 0;
    for (std::size_t i = 0; i < zx.size(); ++i) {
        double row = 0;
        for (std::size_t j = 0; j < px.size(); ++j) {
            const dir3 d = direction(zx[i], px[j]);
            row += pw[j] * pdf(d);
        }
        sum += zw[i] * row;
    }
    return sum;
}

/// Q(a, x), the regularized upper incomplete gamma function (series for x < a + 1, else Lentz's
/// continued fraction; Numerical Recipes' gammq): the chi-square p-value is Q(dof / 2, chi2 / 2).
inline double gamma_q(double a, double x)
{
    if (x <= 0) return 1;
    const double lg = std::lgamma(a);
    if (x < a + 1) {
        double ap = a, sum = 1 / a, del = sum;
        for (int n = 0; n < 100000; ++n) {
            ap += 1;
            del *= x / ap;
            sum += del;
            if (std::abs(del) < std::abs(sum) * 1e-15) break;
        }
        return std::max(0.0, 1 - sum * std::exp(-x + a * std::log(x) - lg));
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - lg) * h;
}

/// Pearson's chi-square test of observed counts against expected ones: cells expected below 5
/// are pooled into one (dropped if the pool is still below 5 and observed nothing there); a
/// sample in a cell of expected count 0 fails outright (p = 0). Returns the p-value; dof = cells - 1.
struct chi2_result { double p, chi2; int dof; };
inline chi2_result chi_square(const std::vector<double>& observed, const std::vector<double>& expected)
{
    double chi2 = 0, pool_o = 0, pool_e = 0;
    int cells = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0 && observed[i] > 0) return {0, INFINITY, 0};
        if (expected[i] < 5) {
            pool_o += observed[i];
            pool_e += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pool_e >= 5 || pool_o > 0) {
        if (pool_e <= 0) return {0, INFINITY, 0};
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++cells;
    }
    const int dof = cells - 1;
    if (dof < 1) return {1, chi2, dof};
    return {gamma_q(dof / 2.0, chi2 / 2), chi2, dof};
}

} // namespace phong_test::bsdf_quad
