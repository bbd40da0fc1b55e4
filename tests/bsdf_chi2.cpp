// phong_bsdf_chi2: chi-square goodness of fit of the BSDFs' sample() against their pdf() (as
// Mitsuba's test_chisquare.cpp and pbrt-v4's bsdfs_test.cpp do).
//
// For each model (modified Phong; Blinn-Phong, exact normalization), number type (float, double),
// exponent m and incident direction wo: N samples are binned on a 10 x 20 grid of
// (cos theta in [0, 1], phi in [0, 2 pi)) of the local frame, plus one cell for the wasted samples
// (pdf = 0: below the horizon); the expected count of a grid cell is N times the integral of
// pdf(wo, .) over it (composite Gauss-Legendre graded toward the mirror direction,
// tests/support/bsdf_quadrature.hpp), that of the wasted cell N times 1 minus their sum. Cells
// expected below 5 are pooled. A test passes when its p-value is at least 1 - (1 - 0.01)^(1/tests),
// tests counting every (model, type, m, direction, histogram) of the run (Sidak's correction: a
// correct sampler fails the run with probability 0.01).
// A second histogram on the lobe's own coordinates (cos and azimuth about the mirror direction r,
// cos warped by the lobe's width) tests the shape of narrow lobes, which fill one cell of the
// first grid from m ~ 1e3.
//
// Usage: phong_bsdf_chi2 [samples per direction = 1000000] [directions = 20] [max m = 1e5]
// Exit status 0 when every test passes. CI: .ci/steps/38-bsdf.sh (-O2, 250000 samples).
// CHI2_DEBUG=1 in the environment lists the cells more than 5 sigma off and samples in empty cells.
#include <phong/bsdf.hpp>

#include "support/bsdf_quadrature.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace phong_test::bsdf_quad;

template <class T> T uniform(std::mt19937_64& rng)
{
    // Midpoints of 2^-23 (2^-52) steps, in (0, 1): u = 0 (the cone's rim) and u = 1 (the cosine
    // lobe's horizon) are measure-zero edges left to tests/bsdf.test.cpp. (Midpoints of 2^-24 steps
    // would round the last one, 1 - 2^-25, to 1 in float.)
    if constexpr (sizeof(T) == 4) return (T(rng() >> 41) + T(0.5)) * T(0x1p-23);
    else return (T(rng() >> 12) + T(0.5)) * T(0x1p-52);
}

constexpr int nz = 10, nphi = 20;

struct summary { double min_p = 1; double min_p_lobe = 1; int failures = 0; };

// The lobe's coordinates about r: v = (1 - exp(-k (1 - cos a))) / (1 - exp(-k x_max)) in [0, 1]
// for 1 - cos a <= x_max = min(2, 4 / k) (k = (m+1)/2 Phong, (m+1)/8 Blinn-Phong: the lobe's mass
// spread over the cells, its part beyond x_max below 1e-3 at high m) and the azimuth about r in a
// frame (e1, e2, r). Directions beyond x_max share the wasted samples' cell.
struct lobe_coords {
    double k, x_max, norm;
    double r[3], e1[3], e2[3];
    lobe_coords(const double rr[3], double kk) : k(kk), x_max(std::min(2.0, 4 / kk)), norm(-std::expm1(-kk * x_max))
    {
        for (int i = 0; i < 3; ++i) r[i] = rr[i];
        // e1: any unit vector orthogonal to r (independent of phong's local_frame).
        double a[3] = {1, 0, 0};
        if (std::abs(r[0]) > 0.5) { a[0] = 0; a[1] = 1; }
        const double d = a[0] * r[0] + a[1] * r[1] + a[2] * r[2];
        for (int i = 0; i < 3; ++i) e1[i] = a[i] - d * r[i];
        const double l = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (double& x : e1) x /= l;
        e2[0] = r[1] * e1[2] - r[2] * e1[1];
        e2[1] = r[2] * e1[0] - r[0] * e1[2];
        e2[2] = r[0] * e1[1] - r[1] * e1[0];
    }
    // (v, psi) of a unit direction w.
    void to(const double w[3], double& v, double& psi) const
    {
        const double c = w[0] * r[0] + w[1] * r[1] + w[2] * r[2];
        const double x = w[0] * e1[0] + w[1] * e1[1] + w[2] * e1[2], y = w[0] * e2[0] + w[1] * e2[1] + w[2] * e2[2];
        const double s2 = x * x + y * y; // 1 - c = s^2 / (1 + c) where c > 0
        const double omc = c > 0 ? s2 / (1 + c) : 1 - c;
        v = omc > x_max ? 2 : -std::expm1(-k * omc) / norm;
        psi = std::atan2(y, x);
        if (psi < 0) psi += 2 * pi;
    }
    // The direction of (v, psi) and the Jacobian |dw / (dv dpsi)|.
    void from(double v, double psi, double w[3], double& jac) const
    {
        const double omc = -std::log1p(-v * norm) / k;
        const double c = 1 - omc, s = std::sqrt(std::max(0.0, omc * (2 - omc)));
        for (int i = 0; i < 3; ++i) w[i] = c * r[i] + s * (std::cos(psi) * e1[i] + std::sin(psi) * e2[i]);
        jac = norm / (k * (1 - v * norm)); // d(cos a)/dv
    }
};

struct direction_result { double cz, p, chi2, p_lobe, chi2_lobe; int dof, dof_lobe; };

// One incident direction (index d of `directions`): both histograms and their chi-square tests.
template <class T, class B>
direction_result test_direction(const B& bsdf, double m, int samples, int d, int directions, bool blinn)
{
    std::mt19937_64 rng(0x5eed0000u + std::uint64_t(m * 7) * 64 + std::uint64_t(d) * 2 + (blinn ? 1u : 0u) + sizeof(T));
    {
        const double cz = directions == 1 ? 0.01 : 0.01 + 0.99 * d / (directions - 1);
        const double phio = 2.3 * d + 0.4, so = std::sqrt((1 - cz) * (1 + cz));
        const glm::vec<3, T> wo{T(so * std::cos(phio)), T(so * std::sin(phio)), T(cz)};
        const auto pdf = [&](const dir3& w) {
            return double(bsdf.pdf(wo, glm::vec<3, T>{T(w.x), T(w.y), T(w.z)}));
        };
        // Peak: the mirror direction r, in (z, phi); widths of the lobe (sigma ~ 1/sqrt(m)).
        const double rz = double(wo.z), rphi = std::atan2(-double(wo.y), -double(wo.x));
        const double sigma = (blinn ? 2 : 1) / std::sqrt(m + 1);
        const double wz = 0.05 * sigma * sigma, wp = 0.05 * sigma;
        std::vector<double> expected(nz * nphi + 1, 0), observed(nz * nphi + 1, 0);
        double total = 0;
        for (int i = 0; i < nz; ++i)
            for (int j = 0; j < nphi; ++j) {
                const double e = cell_integral(pdf, double(i) / nz, double(i + 1) / nz, 2 * pi * j / nphi,
                                               2 * pi * (j + 1) / nphi, rz, rphi, wz, wp);
                expected[i * nphi + j] = e * samples;
                total += e;
            }
        expected[nz * nphi] = std::max(0.0, 1 - total) * samples;
        // The lobe's histogram.
        const double rr[3] = {-double(wo.x), -double(wo.y), double(wo.z)};
        const lobe_coords lc(rr, (m + 1) / (blinn ? 8 : 2));
        std::vector<double> expected_l(nz * nphi + 1, 0), observed_l(nz * nphi + 1, 0);
        double total_l = 0;
        for (int i = 0; i < nz; ++i)
            for (int j = 0; j < nphi; ++j) {
                // pdf over (v, psi): pdf(w) |dw/(dv dpsi)|, 0 below the horizon: at each v the
                // horizon crosses psi at psi0 +- acos(-c r.z / (s rho)), break points of the psi rule.
                // The horizon first cuts the cone about r at tan a = r.z / rho (v = v_c): the v rule
                // is graded toward v_c.
                std::vector<double> vx, vw, px, pw, pb;
                const double rho = std::hypot(lc.e1[2], lc.e2[2]), psi0 = std::atan2(lc.e2[2], lc.e1[2]);
                const double a_c = std::atan2(lc.r[2], rho), omc_c = 2 * std::sin(a_c / 2) * std::sin(a_c / 2);
                const double v_c = -std::expm1(-lc.k * omc_c) / lc.norm;
                const double v0 = double(i) / nz, v1 = double(i + 1) / nz;
                std::vector<double> vb = graded_breaks(v0, v1, v_c, (v1 - v0) * 1e-6);
                for (const double g : graded_breaks(v0, v1, 0, (v1 - v0) * 1e-6)) vb.push_back(g);
                std::sort(vb.begin(), vb.end());
                vb.erase(std::unique(vb.begin(), vb.end()), vb.end());
                composite_rule(vb, vx, vw);
                const double p0 = 2 * pi * j / nphi, p1 = 2 * pi * (j + 1) / nphi;
                double e = 0;
                for (std::size_t a = 0; a < vx.size(); ++a) {
                    pb.clear();
                    for (int q = 0; q <= 4; ++q) pb.push_back(p0 + (p1 - p0) * q / 4);
                    double w0[3], jac;
                    lc.from(vx[a], 0, w0, jac);
                    const double omc = -std::log1p(-vx[a] * lc.norm) / lc.k, c = 1 - omc;
                    const double sn = std::sqrt(std::max(0.0, omc * (2 - omc)));
                    if (sn * rho > 0) {
                        const double arg = -c * lc.r[2] / (sn * rho);
                        // The density jumps to 0 there and is smooth on either side: a break point.
                        if (arg > -1 && arg < 1)
                            for (const double x : {psi0 + std::acos(arg), psi0 - std::acos(arg)})
                                for (const double y : {x - 2 * pi, x, x + 2 * pi})
                                    if (y > p0 && y < p1) pb.push_back(y);
                    }
                    // Blinn-Phong's lobe at grazing wo is a thin ellipse along the meridian through r
                    // (psi0 and psi0 + pi): grade the psi rule toward both, in the cells at or next to them.
                    for (const double x : {psi0, psi0 + pi})
                        for (const double y : {x - 2 * pi, x, x + 2 * pi})
                            if (y > 2 * p0 - p1 && y < 2 * p1 - p0)
                                for (const double g : graded_breaks(p0, p1, y, (p1 - p0) * 1e-4)) pb.push_back(g);
                    std::sort(pb.begin(), pb.end());
                    pb.erase(std::unique(pb.begin(), pb.end()), pb.end());
                    composite_rule(pb, px, pw);
                    for (std::size_t b = 0; b < px.size(); ++b) {
                        double w[3];
                        lc.from(vx[a], px[b], w, jac);
                        if (w[2] <= 0) continue;
                        e += vw[a] * pw[b] * jac * pdf(dir3{w[0], w[1], w[2]});
                    }
                }
                expected_l[i * nphi + j] = e * samples;
                total_l += e;
            }
        expected_l[nz * nphi] = std::max(0.0, 1 - total_l) * samples;
        for (int n = 0; n < samples; ++n) {
            const glm::vec<2, T> u{uniform<T>(rng), uniform<T>(rng)};
            const auto s = bsdf.sample(wo, u);
            if (!(s.pdf > 0)) {
                observed[nz * nphi] += 1;
                observed_l[nz * nphi] += 1;
                continue;
            }
            const double z = double(s.wi.z);
            double phi = std::atan2(double(s.wi.y), double(s.wi.x));
            if (phi < 0) phi += 2 * pi;
            const int i = std::min(nz - 1, int(z * nz)), j = std::min(nphi - 1, int(phi / (2 * pi) * nphi));
            observed[i * nphi + j] += 1;
            const double l = std::sqrt(double(s.wi.x) * s.wi.x + double(s.wi.y) * s.wi.y + z * z);
            const double w[3] = {double(s.wi.x) / l, double(s.wi.y) / l, z / l};
            double v, psi;
            lc.to(w, v, psi);
            const int il = std::min(nz - 1, int(v * nz)), jl = std::min(nphi - 1, int(psi / (2 * pi) * nphi));
            observed_l[v > 1 ? nz * nphi : il * nphi + jl] += 1;
        }
        if (std::getenv("CHI2_DEBUG"))
            for (std::size_t c = 0; c < observed.size(); ++c) {
                if (expected[c] < 1 && observed[c] > 0) std::printf("grid cell %zu: e %g o %g\n", c, expected[c], observed[c]);
                if (expected_l[c] >= 5 && std::abs(expected_l[c] - observed_l[c]) > 5 * std::sqrt(expected_l[c])) std::printf("lobe cell %zu: e %g o %g\n", c, expected_l[c], observed_l[c]);
            }
        const chi2_result r = chi_square(observed, expected), rl = chi_square(observed_l, expected_l);
        return {cz, r.p, r.chi2, rl.p, rl.chi2, r.dof, rl.dof};
    }
}

// One (model, type, m): every direction, on all hardware threads (the expected counts' quadrature
// is most of the run time); each direction has its own random sequence, so the result does not
// depend on the number of threads.
template <class T, class B>
void run_one(const char* model, const B& bsdf, double m, int samples, int directions, double alpha, summary& sum, bool blinn)
{
    std::vector<direction_result> res(std::size_t(directions), direction_result{});
    std::atomic<int> next{0};
    const auto work = [&] {
        for (int d; (d = next++) < directions;) res[std::size_t(d)] = test_direction<T>(bsdf, m, samples, d, directions, blinn);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::max(1u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
    double min_p = 1, min_p_lobe = 1;
    for (const direction_result& r : res) {
        min_p = std::min(min_p, r.p);
        min_p_lobe = std::min(min_p_lobe, r.p_lobe);
        if (r.p < alpha || r.p_lobe < alpha)
            std::printf("  FAIL %s %s m=%g cos(theta_o)=%.3f: p = %.3g (chi2 %.1f, dof %d), lobe grid p = %.3g (chi2 %.1f, dof %d)\n",
                        model, sizeof(T) == 4 ? "float" : "double", m, r.cz, r.p, r.chi2, r.dof, r.p_lobe, r.chi2_lobe, r.dof_lobe);
    }
    const bool ok = min_p >= alpha && min_p_lobe >= alpha;
    std::printf("%-15s %-6s m=%-7g min p over %d directions: %.2e (lobe grid %.2e): %s\n", model,
                sizeof(T) == 4 ? "float" : "double", m, directions, min_p, min_p_lobe, ok ? "pass" : "FAIL");
    sum.min_p = std::min(sum.min_p, min_p);
    sum.min_p_lobe = std::min(sum.min_p_lobe, min_p_lobe);
    sum.failures += ok ? 0 : 1;
}

constexpr double exponents[] = {1.0, 10.0, 100.0, 1e3, 1e4, 1e5};

template <class T>
void run_type(int samples, int directions, double max_m, double alpha, summary& sum)
{
    for (const double m : exponents) {
        if (m > max_m) continue;
        phong::material<T> mat;
        mat.kd = glm::vec<3, T>(T(0.25), T(0.3), T(0.2));
        mat.ks = glm::vec<3, T>(T(0.6));
        mat.shininess = T(m);
        run_one<T>("modified_phong", phong::modified_phong_bsdf<T>(mat), m, samples, directions, alpha, sum, false);
        run_one<T>("blinn_phong", phong::blinn_phong_bsdf<T>(mat), m, samples, directions, alpha, sum, true);
    }
}

} // namespace

int main(int argc, char** argv)
{
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // a line per test as it ends, also into a file
    const int samples = argc > 1 ? std::atoi(argv[1]) : 1000000;
    const int directions = argc > 2 ? std::atoi(argv[2]) : 20;
    const double max_m = argc > 3 ? std::atof(argv[3]) : 1e5;
    // Sidak's correction over every test of the run: 2 models x 2 types x the exponents x the
    // directions x 2 histograms, each at 1 - (1 - 0.01)^(1/tests), so that a correct sampler
    // fails the run with probability 0.01.
    int exponents_run = 0;
    for (const double m : exponents) exponents_run += m <= max_m ? 1 : 0;
    const int tests = 2 * 2 * exponents_run * directions * 2;
    const double alpha = -std::expm1(std::log1p(-0.01) / tests);
    std::printf("%d chi-square tests of %d samples; each passes at p >= %.3g (0.01 over all, Sidak)\n", tests, samples, alpha);
    summary sum;
    run_type<float>(samples, directions, max_m, alpha, sum);
    run_type<double>(samples, directions, max_m, alpha, sum);
    std::printf("smallest p-value: %.2e (cos theta, phi grid), %.2e (lobe grid); %d of the (model, type, m) tests failed\n",
                sum.min_p, sum.min_p_lobe, sum.failures);
    return sum.failures == 0 ? 0 : 1;
}
