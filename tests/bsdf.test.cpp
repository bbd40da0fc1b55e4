// The BSDFs (phong/bsdf.hpp): local frame, normalization, albedo, white furnace, pdf integral,
// sample/pdf/eval consistency, reciprocity, the sampling's accuracy in ulps at any exponent, no
// NaN or inf at the edges, validate. The chi-square test of sample against pdf is
// tests/bsdf_chi2.cpp (its own executable, run built -O2 by .ci/steps/38-bsdf.sh). Expected values come from integrals written here (long double, no phong code), the
// closed forms derived in docs/bsdf.md, the published figures, or Monte Carlo.
#include <phong/bsdf.hpp>

#include "support/bsdf_quadrature.hpp"
#include "support/numeric.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {
template <class T> using vec2 = glm::vec<2, T>;
template <class T> using vec3 = glm::vec<3, T>;
using ld = long double;
constexpr ld pi_l = 3.14159265358979323846264338327950288L;

template <class T> phong::material<T> make_material(T kd, T ks, T m)
{
    phong::material<T> mat;
    mat.kd = vec3<T>(kd);
    mat.ks = vec3<T>(ks);
    mat.shininess = m;
    return mat;
}
template <class T> vec3<T> direction(double cos_theta, double phi)
{
    const double s = std::sqrt((1 - cos_theta) * (1 + cos_theta));
    return {T(s * std::cos(phi)), T(s * std::sin(phi)), T(cos_theta)};
}
template <class T> T uniform(std::mt19937_64& rng)
{
    if constexpr (sizeof(T) == 4) return (T(rng() >> 40) + T(0.5)) * T(0x1p-24);
    else return (T(rng() >> 11) + T(0.5)) * T(0x1p-53);
}
template <class T> vec3<T> random_upper(std::mt19937_64& rng)
{
    return direction<T>(double(uniform<T>(rng)), 2 * 3.141592653589793 * double(uniform<T>(rng)));
}
// By the bits: -ffinite-math-only folds std::isfinite to true (.ci/steps/36-fast-math.sh builds this file so).
using phong_test::finite_bits;
template <class T> bool finite3(const vec3<T>& v) { return finite_bits(v.x) && finite_bits(v.y) && finite_bits(v.z); }
double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// Simpson's rule on [a, b] with n (even) panels, in long double.
template <class F> ld simpson(F f, ld a, ld b, int n)
{
    const ld h = (b - a) / n;
    ld s = f(a) + f(b);
    for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
    return s * h / 3;
}
} // namespace

TEST_CASE_TEMPLATE("bsdf: local_frame is orthonormal, right-handed, with n as +z", T, float, double)
{
    std::mt19937_64 rng(1);
    const T tol = T(8) * std::numeric_limits<T>::epsilon();
    std::vector<vec3<T>> normals{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0, T(-0.0)}};
    for (int i = 0; i < 10000; ++i) {
        const double z = 2 * double(uniform<T>(rng)) - 1;
        normals.push_back(direction<T>(z, 6.283185307179586 * double(uniform<T>(rng))));
    }
    for (const auto& n0 : normals) {
        const vec3<T> n = n0.z == T(0) && n0.x == T(0) && n0.y == T(0) ? vec3<T>(0, 0, 1) : n0;
        const auto f = phong::local_frame(n);
        CHECK(std::abs(phong::detail::dot(f.s, f.s) - T(1)) <= tol);
        CHECK(std::abs(phong::detail::dot(f.t, f.t) - T(1)) <= tol);
        CHECK(std::abs(phong::detail::dot(f.s, f.t)) <= tol);
        CHECK(std::abs(phong::detail::dot(f.s, n)) <= tol);
        CHECK(std::abs(phong::detail::dot(f.t, n)) <= tol);
        const vec3<T> c = phong::detail::cross(f.s, f.t);
        CHECK(phong::detail::dot(c - n, c - n) <= tol * tol * 16);
        const vec3<T> l = f.to_local(n);
        CHECK(std::abs(l.z - T(1)) <= tol);
    }
}

TEST_CASE("bsdf: Blinn-Phong normalizations against an independent integral at normal incidence")
{
    // A(m) = N int_0^{pi/2} cos^m(th/2) cos th 2 pi sin th dth: wo = n, so h is halfway, th_h = th/2.
    const auto albedo = [](ld N, ld m) {
        const ld b = std::min(pi_l / 2, ld(40 / std::sqrt(m + 1))); // the lobe is negligible beyond
        return N * simpson([&](ld th) { return std::pow(std::cos(th / 2), m) * std::cos(th) * 2 * pi_l * std::sin(th); }, 0, b, 20000);
    };
    for (const double m : {0.0, 0.5, 1.0, 2.0, 8.8, 10.0, 100.0, 1e3, 1e4, 1e5}) {
        CAPTURE(m);
        const double exact = albedo(phong::blinn_phong_normalization(double(m)), m);
        CHECK(std::abs(exact - 1) < 1e-9);
        CHECK(std::abs(double(albedo(phong::blinn_phong_normalization(float(m)), m)) - 1) < 1e-6);
    }
    // The figures: (m+8)/(8 pi) gives 1.024 at m = 1 and 1.075 at m = 10; three.js keeps 34 %.
    using phong::blinn_normalization;
    CHECK(std::abs(double(albedo(phong::blinn_phong_normalization(1.0, blinn_normalization::approximate), 1)) - 1.0243) < 1e-4);
    CHECK(std::abs(double(albedo(phong::blinn_phong_normalization(10.0, blinn_normalization::approximate), 10)) - 1.0748) < 1e-4);
    CHECK(std::abs(double(albedo(phong::blinn_phong_normalization(1.0, blinn_normalization::three_js), 1)) - 0.3414) < 1e-4);
    // Closed form of the exact one by hand at m = 0 and 2: 1/pi, 4*6 / (8 pi 2.5).
    CHECK(std::abs(phong::blinn_phong_normalization(0.0) * pi_l - 1) < 1e-15);
    CHECK(std::abs(phong::blinn_phong_normalization(2.0) - 24 / (8 * pi_l * 2.5L)) < 1e-15);
    // The modified Phong's (m+2)/(2 pi) at normal incidence: int (m+2)/(2 pi) cos^(m+1) th 2 pi sin th dth = 1.
    for (const double m : {0.0, 1.0, 10.0, 1e3, 1e5}) {
        const ld b = std::min(pi_l / 2, ld(40 / std::sqrt(m + 1)));
        const ld a = simpson([&](ld th) { return (m + 2) / (2 * pi_l) * std::pow(std::cos(th), m + 1) * 2 * pi_l * std::sin(th); }, 0, b, 20000);
        CHECK(std::abs(double(a) - 1) < 1e-9);
    }
}

TEST_CASE_TEMPLATE("bsdf: albedo's quadrature against a brute-force integral of eval_cos", T, float, double)
{
    // Midpoint rule over (cos th, phi), 300 x 600, in double: error about 1e-5 for 1 <= m <= 10
    // (m = 0 has a jump at wi.r = 0 where the midpoint rule is off by 3e-4: closed forms below).
    const auto brute = [](const auto& b, const vec3<T>& wo) {
        const int n = 300;
        double s = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 2 * n; ++j)
                s += double(b.eval_cos(wo, direction<T>((i + 0.5) / n, (j + 0.5) / (2 * n) * 2 * 3.141592653589793)).x);
        return s / (2.0 * n * n) * 2 * 3.141592653589793;
    };
    for (const T m : {T(1), T(2), T(10)})
        for (const double c : {1.0, 0.8, 0.4, 0.1, 0.001}) {
            CAPTURE(m);
            CAPTURE(c);
            const auto mat = make_material<T>(T(0), T(1), m);
            const vec3<T> wo = direction<T>(c, 0.7);
            const phong::modified_phong_bsdf<T> p(mat);
            const phong::blinn_phong_bsdf<T> b(mat);
            CHECK(std::abs(double(p.specular_albedo(wo)) - brute(p, wo)) < 1e-4);
            CHECK(std::abs(double(b.specular_albedo(wo)) - brute(b, wo)) < 1e-4);
        }
    // Closed forms: the modified Phong at m = 0 on the horizon reflects 1/2 (a quarter sphere of
    // cosines over pi); at normal incidence 1 for every m.
    const phong::modified_phong_bsdf<T> p0(make_material<T>(T(0), T(1), T(0)));
    CHECK(std::abs(double(p0.specular_albedo(direction<T>(1e-7, 0.3))) - 0.5) < 1e-5);
    for (const T m : {T(0), T(1), T(1e3), T(1e6)})
        CHECK(std::abs(double(phong::modified_phong_bsdf<T>(make_material<T>(T(0), T(1), m)).specular_albedo({0, 0, 1})) - 1) < 1e-6);
}

TEST_CASE_TEMPLATE("bsdf: white furnace: albedo <= 1 when kd + ks <= 1, and the mean sample weight is the albedo", T, float, double)
{
    double worst = 0;
    for (const T m : {T(0), T(0.5), T(1), T(2), T(5), T(10), T(30), T(100), T(1e3), T(1e4), T(1e5), T(1e6)})
        for (const T kd : {T(0), T(0.4)}) {
            const auto mat = make_material<T>(kd, T(1) - kd, m);
            const phong::modified_phong_bsdf<T> p(mat);
            const phong::blinn_phong_bsdf<T> b(mat);
            for (int i = 0; i <= 64; ++i) {
                const double c = i == 0 ? 1e-4 : i / 64.0;
                const vec3<T> wo = direction<T>(c, 1.1);
                const double ap = double(p.albedo(wo).x), ab = double(b.albedo(wo).x);
                CHECK(ap <= 1 + 1e-3);
                CHECK(ab <= 1 + 1e-3);
                CHECK(ap >= double(kd));
                worst = std::max({worst, ap, ab});
            }
            if (kd == T(0)) CHECK(std::abs(double(p.albedo({0, 0, 1}).x) - 1) < 1e-3);
        }
    MESSAGE("largest albedo with kd + ks = 1: " << worst);
    // Monte Carlo: E[weight] = int f cos = albedo (every direction where f > 0 has pdf > 0).
    std::mt19937_64 rng(7);
    const int n = 100000;
    for (const T m : {T(1), T(100), T(1e5)})
        for (const double c : {1.0, 0.5, 0.05}) {
            CAPTURE(m);
            CAPTURE(c);
            const auto mat = make_material<T>(T(0.3), T(0.7), m);
            const vec3<T> wo = direction<T>(c, 2.0);
            const auto check = [&](const auto& bsdf) {
                double s = 0, s2 = 0;
                for (int k = 0; k < n; ++k) {
                    const double w = double(bsdf.sample(wo, vec2<T>(uniform<T>(rng), uniform<T>(rng))).weight.x);
                    s += w;
                    s2 += w * w;
                }
                const double mean = s / n, sd = std::sqrt(std::max(0.0, s2 / n - mean * mean) / n);
                CHECK(std::abs(mean - double(bsdf.albedo(wo).x)) <= 5 * sd + 1e-4);
            };
            check(phong::modified_phong_bsdf<T>(mat));
            check(phong::blinn_phong_bsdf<T>(mat));
        }
}

TEST_CASE_TEMPLATE("bsdf: pdf integrates to 1 less the wasted part", T, float, double)
{
    using phong_test::bsdf_quad::cell_integral;
    using phong_test::bsdf_quad::dir3;
    const double two_pi = 6.283185307179586;
    for (const double m : {1.0, 10.0, 100.0, 1e3, 1e4, 1e5})
        for (const double c : {1.0, 0.7, 0.01}) {
            CAPTURE(m);
            CAPTURE(c);
            const auto mat = make_material<T>(T(0), T(1), T(m)); // p = 1: the specular lobe alone
            const vec3<T> wo = direction<T>(c, 0.9);
            const double rphi = std::atan2(-double(wo.y), -double(wo.x));
            const auto integral = [&](const auto& b, double sigma) {
                const auto pdf = [&](const dir3& w) { return double(b.pdf(wo, vec3<T>(T(w.x), T(w.y), T(w.z)))); };
                return cell_integral(pdf, 0, 1, rphi - two_pi / 2, rphi + two_pi / 2, double(wo.z), rphi, 0.05 * sigma * sigma, 0.05 * sigma);
            };
            // Modified Phong: the lobe's part below the horizon, W = int_0^{s^(m+1)} acos(rho)/pi dt,
            // rho = c cos th / (sqrt(1 - c^2) sin th), c = t^(1/(m+1)); in y with c = sin th (1 - y^2).
            const ld co = ld(wo.z), so = std::sqrt(1 - co * co);
            const ld W = so == 0 ? 0 : simpson([&](ld y) {
                const ld cc = so * (1 - y * y), s = std::sqrt(1 - cc * cc);
                if (cc <= 0 || s <= 0) return ld(0);
                const ld rho = std::min(ld(1), cc * co / (s * so));
                return (m + 1) * std::pow(cc, ld(m)) * std::acos(rho) / pi_l * 2 * so * y;
            }, 0, 1, 200000);
            const double ip = integral(phong::modified_phong_bsdf<T>(mat), 1 / std::sqrt(m + 1));
            CHECK(std::abs(ip - (1 - double(W))) < 1e-3);
            // Blinn-Phong: at normal incidence the wasted part is P(cos th_h < 1/sqrt 2) = 2^(-(m+1)/2);
            // elsewhere, the integral plus the fraction of wasted samples is 1 (Monte Carlo, 5 sigma).
            const phong::blinn_phong_bsdf<T> b(mat);
            const double ib = integral(b, 2 / std::sqrt(m + 1));
            if (c == 1.0) {
                CHECK(std::abs(ib - (1 - std::pow(2.0, -(m + 1) / 2))) < 1e-3);
            } else {
                std::mt19937_64 rng(3);
                const int n = 200000;
                int wasted = 0;
                for (int k = 0; k < n; ++k) wasted += b.sample(wo, vec2<T>(uniform<T>(rng), uniform<T>(rng))).pdf > T(0) ? 0 : 1;
                const double f = double(wasted) / n, sd = std::sqrt(f * (1 - f) / n);
                CHECK(ib <= 1 + 1e-3);
                CHECK(std::abs(ib + f - 1) <= 5 * sd + 1e-3);
            }
        }
}

TEST_CASE_TEMPLATE("bsdf: sample's pdf and weight equal pdf() and eval_cos() / pdf()", T, float, double)
{
    std::mt19937_64 rng(11);
    const int n = sizeof(T) == 4 ? 1000000 : 200000;
    const double tol = sizeof(T) == 4 ? 1e-5 : 1e-12;
    const T ms[] = {T(0), T(1), T(10), T(100), T(1e3), T(1e4), T(1e5), T(1e6)};
    double worst_pdf = 0, worst_weight = 0;
    for (int model = 0; model < 2; ++model)
        for (int k = 0; k < n; ++k) {
            const T m = ms[k % 8];
            const auto mat = make_material<T>(T(0.3), T(0.6), m);
            const vec3<T> wo = random_upper<T>(rng);
            const vec2<T> u{uniform<T>(rng), uniform<T>(rng)};
            const auto test = [&](const auto& b) {
                const auto s = b.sample(wo, u);
                if (!(s.pdf > T(0))) return;
                const double p = double(b.pdf(wo, s.wi));
                worst_pdf = std::max(worst_pdf, rel(double(s.pdf), p));
                worst_weight = std::max(worst_weight, rel(double(s.weight.x), double(b.eval_cos(wo, s.wi).x) / p));
            };
            if (model == 0) test(phong::modified_phong_bsdf<T>(mat));
            else test(phong::blinn_phong_bsdf<T>(mat));
        }
    MESSAGE("largest relative difference: pdf " << worst_pdf << ", weight " << worst_weight);
    CHECK(worst_pdf <= tol);
    CHECK(worst_weight <= tol);
}

TEST_CASE_TEMPLATE("bsdf: reciprocity f(wo, wi) = f(wi, wo)", T, float, double)
{
    std::mt19937_64 rng(5);
    using phong::blinn_normalization;
    for (const T m : {T(0), T(1), T(30), T(1e3), T(1e5)}) {
        const auto mat = make_material<T>(T(0.2), T(0.8), m);
        const phong::modified_phong_bsdf<T> p(mat);
        for (int k = 0; k < 20000; ++k) {
            const vec3<T> a = random_upper<T>(rng);
            // b near the mirror of a half the time, where the lobe is large.
            vec3<T> b = random_upper<T>(rng);
            if (k % 2) b = phong::detail::normalize(vec3<T>(-a.x, -a.y, a.z) + b * T(1 / std::sqrt(double(m) + 1)));
            if (!(b.z > 0)) continue;
            // The modified Phong computes 1 - wi.r(wo) from wi and r(wo): the two orders round
            // differently, each within (1 + m x) ulps (x = 1 - cos a).
            const double fa = double(p.eval(a, b).x), fb = double(p.eval(b, a).x);
            CHECK(rel(fa, fb) <= 64 * double(std::numeric_limits<T>::epsilon()) * (1 + double(m) * 4e-3) + 1e-300);
            for (const auto kind : {blinn_normalization::exact, blinn_normalization::approximate, blinn_normalization::three_js}) {
                const phong::blinn_phong_bsdf<T> bl(mat, kind);
#if defined(__FAST_MATH__) // CI step 36: -ffast-math may round the two calls' sums differently
                CHECK(rel(double(bl.eval(a, b).x), double(bl.eval(b, a).x)) <= 4 * double(std::numeric_limits<T>::epsilon()));
#else
                CHECK(bl.eval(a, b).x == bl.eval(b, a).x); // h = (wo + wi) / |wo + wi|: the same bits
#endif
            }
        }
    }
}

TEST_CASE_TEMPLATE("bsdf: the lobe's sin a and 1 - cos a within 4 ulps of a long double reference at every m", T, float, double)
{
    // u over 1e6 values: the midpoints of 2^20 equal steps, and the edges (2^-k, 1 - 2^-k). Where
    // long double is IEEE binary128 (aarch64: in software, under qemu in CI) 2^18 steps.
    const int steps = std::numeric_limits<ld>::digits > 64 ? 1 << 18 : 1 << 20;
    std::vector<T> us;
    for (int i = 0; i < steps - 100; ++i) us.push_back(T((i + 0.5) / double(steps)));
    for (int k = 1; k < std::numeric_limits<T>::digits; ++k) {
        us.push_back(std::ldexp(T(1), -k * 4));
        us.push_back(T(1) - std::ldexp(T(1), -k));
    }
    us.push_back(std::nextafter(T(1), T(0)));
    us.push_back(std::numeric_limits<T>::denorm_min());
    for (const double m : {0.0, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6}) {
        std::uint64_t worst_omc = 0, worst_sin = 0, textbook_sin = 0;
        for (const T u : us) {
            const auto cone = phong::detail::bsdf::sample_cone(u, T(m));
            const ld omc = -std::expm1(std::log(ld(u)) / (ld(T(m)) + 1)); // exact but the final rounding
            const ld sn = std::sqrt(omc * (2 - omc));
            worst_omc = std::max(worst_omc, phong_test::ulp_distance(cone.one_minus_cos, T(omc)));
            worst_sin = std::max(worst_sin, phong_test::ulp_distance(cone.sin, T(sn)));
            // The textbook form: cos a = u^(1/(m+1)), sin a = sqrt(1 - cos^2 a).
            const T c = std::pow(u, T(1) / (T(m) + T(1)));
            textbook_sin = std::max(textbook_sin, phong_test::ulp_distance(std::sqrt(T(1) - c * c), T(sn)));
        }
        CAPTURE(m);
        MESSAGE("m = " << m << ": max ulp 1 - cos a " << worst_omc << ", sin a " << worst_sin << "; textbook sin a " << textbook_sin);
        CHECK(worst_omc <= 4);
        CHECK(worst_sin <= 4);
        if (sizeof(T) == 4 && m >= 1e3) CHECK(textbook_sin > 1000000); // 100 % wrong at worst (sin a = 0)
    }
}

TEST_CASE_TEMPLATE("bsdf: no NaN or inf at the edges", T, float, double)
{
    const T below_one = std::nextafter(T(1), T(0)), tiny = std::numeric_limits<T>::denorm_min();
    const T us[] = {T(0), tiny, T(1e-30), T(0.25), T(0.5), below_one, T(1)};
    const std::vector<vec3<T>> wos{{0, 0, 1}, {1, 0, 0}, {T(0.6), 0, T(0.8)}, direction<T>(1e-7, 1.0), {T(-1), 0, tiny},
                                   direction<T>(0.01, 4.0), {0, T(0.6), T(-0.8)}};
    const T huge = std::numeric_limits<T>::max() / 16;
    for (const T m : {T(0), T(1e-3), T(1), T(1e5), T(1e30), huge})
        for (const auto& k : {vec2<T>(0.3, 0.6), vec2<T>(0, 1), vec2<T>(1, 0), vec2<T>(0, 0)}) {
            const auto mat = make_material<T>(k.x, k.y, m);
            const phong::modified_phong_bsdf<T> p(mat);
            const phong::blinn_phong_bsdf<T> b(mat);
            for (const auto& wo : wos) {
                CHECK(finite3(p.albedo(wo)));
                CHECK(finite3(b.albedo(wo)));
                for (const T u0 : us)
                    for (const T u1 : us) {
                        const auto check = [&](const auto& bsdf) {
                            const auto s = bsdf.sample(wo, vec2<T>(u0, u1));
                            const bool ok = finite3(s.wi) && finite_bits(s.pdf) && s.pdf >= 0 && finite3(s.weight) && s.weight.x >= 0 &&
                                            finite3(bsdf.eval(wo, s.wi)) && finite_bits(bsdf.pdf(wo, s.wi));
                            if (!ok) MESSAGE("m " << m << " wo " << wo.x << " " << wo.y << " " << wo.z << " u " << u0 << " " << u1);
                            CHECK(ok);
                        };
                        check(p);
                        check(b);
                    }
            }
        }
}

namespace {
template <class X> bool rejected(const X& x, const char* field)
{
    const phong::validation r = phong::validate(x);
    return !static_cast<bool>(r) && std::string(r.message()).find(field) != std::string::npos;
}
} // namespace

TEST_CASE_TEMPLATE("bsdf: validate", T, float, double)
{
    const phong::material<T> def;
    CHECK(static_cast<bool>(phong::validate(phong::modified_phong_bsdf<T>(def))));
    CHECK(static_cast<bool>(phong::validate(phong::blinn_phong_bsdf<T>(def))));
    CHECK(static_cast<bool>(phong::validate(phong::blinn_phong_bsdf<T>(def, phong::blinn_normalization::approximate))));
    auto bright = def;
    bright.kd = vec3<T>(T(0.5), T(0.2), T(0.2));
    bright.ks = vec3<T>(T(0.6), T(0.2), T(0.2));
    CHECK(rejected(phong::modified_phong_bsdf<T>(bright), "material.kd + material.ks"));
    CHECK(rejected(phong::blinn_phong_bsdf<T>(bright), "material.kd + material.ks"));
    auto neg = def;
    neg.kd.y = T(-0.1);
    CHECK(rejected(phong::modified_phong_bsdf<T>(neg), "bsdf.kd"));
    neg = def;
    neg.shininess = std::numeric_limits<T>::quiet_NaN();
    CHECK(rejected(phong::blinn_phong_bsdf<T>(neg), "bsdf.shininess"));
    CHECK(rejected(phong::modified_phong_bsdf<T>(def, T(1.5)), "bsdf.specular_probability"));
    CHECK(rejected(phong::modified_phong_bsdf<T>(def, T(0)), "bsdf.specular_probability"));
    CHECK(rejected(phong::modified_phong_bsdf<T>(def, T(1)), "bsdf.specular_probability"));
    phong::blinn_phong_bsdf<T> changed(def);
    changed.shininess = T(100);
    CHECK(rejected(changed, "bsdf.norm"));
}

// Constant evaluation: eval, pdf and sample (its log, expm1, sqrt, sin and cos) in a static_assert.
namespace {
constexpr phong::material<double> ce_mat{};
constexpr phong::modified_phong_bsdf<double> ce_phong(ce_mat);
constexpr phong::blinn_phong_bsdf<double> ce_blinn(ce_mat);
constexpr glm::dvec3 ce_wo{0.6, 0.0, 0.8};
constexpr auto ce_sp = ce_phong.sample(ce_wo, glm::dvec2(0.1, 0.3)); // the specular lobe (p ~ 0.2)
constexpr auto ce_sb = ce_blinn.sample(ce_wo, glm::dvec2(0.9, 0.3)); // the diffuse lobe
static_assert(ce_sp.lobe == phong::bsdf_lobe::specular && ce_sp.pdf > 0);
static_assert(ce_sb.lobe == phong::bsdf_lobe::diffuse && ce_sb.pdf > 0);
static_assert(ce_phong.pdf(ce_wo, ce_sp.wi) == ce_sp.pdf);
static_assert(ce_blinn.eval(ce_wo, glm::dvec3(-0.6, 0.0, 0.8)).x > ce_blinn.eval(ce_wo, glm::dvec3(0, 0, 1)).x);
static_assert(phong::local_frame(glm::dvec3(0, 0, -1)).s.x == 1.0);
} // namespace

TEST_CASE("bsdf: constant evaluation agrees with run time")
{
    const auto rp = ce_phong.sample(ce_wo, glm::dvec2(0.1, 0.3));
    const auto rb = ce_blinn.sample(ce_wo, glm::dvec2(0.9, 0.3));
    for (int i = 0; i < 3; ++i) {
        CHECK(std::abs(rp.wi[i] - ce_sp.wi[i]) < 1e-14);
        CHECK(std::abs(rb.wi[i] - ce_sb.wi[i]) < 1e-14);
    }
    CHECK(rel(rp.pdf, ce_sp.pdf) < 1e-12);
    CHECK(rel(rb.weight.x, ce_sb.weight.x) < 1e-12);
}
