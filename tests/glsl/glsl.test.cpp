// The GLSL twin (include/phong/glsl/phong.glsl) on a real OpenGL implementation: Mesa llvmpipe,
// headless through EGL's surfaceless platform (tests/glsl/gl.hpp), in OpenGL 3.3 core (GLSL 330)
// and OpenGL ES 3.0 (GLSL 300 es).
//  * llvmpipe's own error: its sqrt, 1 / x, 1 / sqrt(x), inversesqrt and pow against a double
//    reference, checked against the allowances below (published in docs/glsl.md);
//  * agreement: for every preset, random and edge cases through the twin in a vertex shader (read
//    back by transform feedback) against a long-double evaluation of the model written here from
//    its formulas, within the exact mode's published bound (phong/accuracy.hpp's exact_bound, from
//    each case's conditioning) widened by llvmpipe's allowances; phong::shade<F> in float exact
//    mode held to the unwidened bound on the same cases, and the twin's distance to it reported;
//    every channel of every case finite and non-negative;
//  * seed 003's phong.vert, verbatim (tests/glsl/seed003_phong.vert), against the twin's
//    phong_shade_vertex with presets::glsl_ads and against phong::shade_vertex;
//  * phong::glsl::defines(F) against the preset defines, and phong::glsl::source().
// No EGL display (no Mesa EGL): the test fails, naming what is missing, unless
// PHONG_GLSL_ALLOW_SKIP=1 says a skip is fine.
#include "gl.hpp"
#include "seed003.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include "../support/accuracy_analysis.hpp"
#include <phong/glsl.hpp>
#include <phong/phong.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace {

using phong::features;
using phong::specular_model;
namespace acc = phong::accuracy;
constexpr double u = 0x1p-24; // float's unit roundoff

/// A context of the given API, or an empty optional where none can be made and a skip is allowed
/// (PHONG_GLSL_ALLOW_SKIP=1); otherwise the failure is a test failure naming what is missing.
std::unique_ptr<glt::context> open(glt::api a)
{
    try {
        auto c = std::make_unique<glt::context>(a);
        MESSAGE(glt::api_name(a) << ": " << c->renderer() << ", " << c->version() << " (EGL " << c->platform() << ")");
        return c;
    } catch (const std::exception& e) {
        if (glt::skip_allowed()) {
            MESSAGE("SKIPPED (PHONG_GLSL_ALLOW_SKIP=1): " << std::string(e.what()));
            return nullptr;
        }
        const std::string what = std::string(e.what()) +
                                 " (Mesa: set EGL_PLATFORM=surfaceless; Debian: libegl-mesa0 libgl1-mesa-dri; PHONG_EGL_PLATFORM=device for a GPU without the surfaceless platform; PHONG_GLSL_ALLOW_SKIP=1 to skip)";
        FAIL(what);
        return nullptr;
    }
}

// ---- llvmpipe's own error -----------------------------------------------------------------

/// The driver's error, in units of float's u: the largest relative error of sqrt(x), 1 / x and
/// 1 / sqrt(x) (the exact mode's operations), of inversesqrt(x) (the fast mode's), and of pow(x, m)
/// per unit of (1 + |m log2 x| + m): a pow through exp2(m log2 x) loses about |m log2 x| u to the
/// rounding of the product, and m times log2's absolute error, which near x = 1 is not relative.
struct driver_error {
    double sqrt_u = 0, reciprocal_u = 0, rsqrt_u = 0, inversesqrt_u = 0, pow_per_y_u = 0;
    double pow_worst_rel = 0, pow_worst_x = 0, pow_worst_m = 0;
    bool flushes_subnormals = false; ///< a product in float's subnormal range comes out 0
    int samples = 0;
};

/// The allowances the agreement tests use, published in docs/glsl.md: the measured error must stay
/// within them (a driver that does worse fails here, with its figures).
constexpr double allowed_operation_u = 2.0;   // sqrt, 1 / x: within 2 u; 1 / sqrt(x): within 4 u (two operations)
constexpr double allowed_inversesqrt_u = 4.0; // the fast mode's inversesqrt
constexpr double allowed_pow_per_y_u = 4.0;   // pow(x, m): within 4 (1 + |m log2 x| + m) u

driver_error measure_driver(const glt::context& c)
{
    const std::string body = R"(
uniform highp sampler2D inputs;
out vec4 result;
void main() {
    vec4 a = texelFetch(inputs, ivec2(gl_VertexID % 1024, gl_VertexID / 1024), 0);
    result = vec4(sqrt(a.x), 1.0 / a.x, 1.0 / sqrt(a.x), inversesqrt(a.x));
    if (a.z > 0.5) result = vec4(pow(a.y, a.w), (a.y * 1e-20) * 1e-20, 0.0, 0.0);
    gl_Position = vec4(0.0);
}
)";
    const std::string text = std::string(glt::version_line(c.which())) + "\n" + body;
    glt::feedback_program program(c, text, "result");
    std::mt19937_64 rng(20261127);
    constexpr int rows = 64, count = 1024 * rows;
    std::vector<float> texels(std::size_t(count) * 4);
    for (int i = 0; i < count; ++i) {
        float* t = &texels[std::size_t(i) * 4];
        const bool power = i % 2 == 1;
        // x over float's normal range for the roots and reciprocals (log-uniform, 2^-120 .. 2^120),
        // a base in (0, 1] and m in [0, 1000] (and [0, 10] for half of them) for pow.
        // (one draw per statement: the same samples whatever order a compiler evaluates arguments in)
        const double mantissa0 = 1.0 + double(rng() >> 11) * 0x1p-53;
        const int exponent0 = int(rng() % 241) - 120;
        t[0] = float(std::ldexp(mantissa0, exponent0));
        const double mantissa1 = 1.0 + double(rng() >> 11) * 0x1p-53;
        const int exponent1 = -int(rng() % 24);
        const double x = std::ldexp(mantissa1, exponent1) / 2;
        t[1] = float(std::min(x, 1.0));
        t[2] = power ? 1.0f : 0.0f;
        t[3] = float(double(rng() >> 11) * 0x1p-53 * ((i / 2) % 2 ? 1000 : 10));
    }
    glt::float_texture tex(c, 1024, rows, texels);
    const std::vector<float> out = program.run(count, 4, [&] { c.gl().glUniform1i(program.uniform("inputs"), 0); });
    driver_error e;
    const auto rel = [](double computed, double exact) { return std::fabs(computed - exact) / std::fabs(exact) / u; };
    for (int i = 0; i < count; ++i) {
        const float* t = &texels[std::size_t(i) * 4];
        const float* r = &out[std::size_t(i) * 4];
        if (t[2] > 0.5f) {
            const double x = t[1], m = t[3], exact = std::pow(x, m);
            if (r[1] == 0.0f && x * 1e-40 > 0x1p-149) e.flushes_subnormals = true;
            if (exact < 0x1p-120) continue; // beyond float's normal range: flushed to 0 by the driver, absolute error below 2^-120
            const double y = std::fabs(m * std::log2(x));
            const double err = rel(r[0], exact);
            const double per_y = err / (1 + y + m);
            if (per_y > e.pow_per_y_u) e.pow_per_y_u = per_y, e.pow_worst_rel = err * u, e.pow_worst_x = x, e.pow_worst_m = m;
        } else {
            const double x = t[0];
            e.sqrt_u = std::max(e.sqrt_u, rel(r[0], std::sqrt(x)));
            e.reciprocal_u = std::max(e.reciprocal_u, rel(r[1], 1 / x));
            e.rsqrt_u = std::max(e.rsqrt_u, rel(r[2], 1 / std::sqrt(x)));
            e.inversesqrt_u = std::max(e.inversesqrt_u, rel(r[3], 1 / std::sqrt(x)));
        }
        ++e.samples;
    }
    return e;
}

// ---- scenes and the long-double model ---------------------------------------------------------

constexpr int max_lights = 4;

struct scene {
    glm::vec3 position, normal, view;
    bool front_facing = true;
    phong::material<float> material;
    phong::environment<float> environment;
    std::vector<phong::light<float>> lights;
};

using ld = long double;
struct ld3 {
    ld x = 0, y = 0, z = 0;
};
ld3 L3(const glm::vec3& v) { return {v.x, v.y, v.z}; }
ld3 operator+(ld3 a, ld3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
ld3 operator-(ld3 a, ld3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
ld3 operator*(ld3 a, ld s) { return {a.x * s, a.y * s, a.z * s}; }
ld dot(ld3 a, ld3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// The model in long double, from its formulas (docs/models.md, features.hpp), with the exact
/// mode's bound of each channel from each light's conditioning (acc::exact_*_bound<float>).
/// widen: the driver's allowance (operations' factor, pow per unit of |m log2 c|) for the twin.
struct reference {
    std::array<ld, 4> color{};       // rgb(a)
    std::array<double, 3> bound{};   // relative bound per channel (+inf: none)
    std::array<double, 3> widened{}; // the same with the driver's allowance
    double allowance = 0;            // absolute underflow allowance
};

/// Squared lengths below this have no relative bound on a driver that flushes subnormals: a
/// product of their components may lose up to the smallest normal float, 2^-126 (phong's exact bound
/// assumes gradual underflow). Above it, such a loss is below 2^-26 relative: ftz_extra covers it.
constexpr double ftz_min_square = 0x1p-100;

template <features F>
reference evaluate(const scene& s, double operation_factor, double pow_per_y_u, bool flushes = false)
{
    reference out;
    const ld3 Q = L3(s.position), N = L3(s.normal);
    const ld nn = dot(N, N);
    ld3 n = nn > 0 ? N * (1 / std::sqrt(nn)) : ld3{};
    ld3 e;
    if constexpr (F.view == phong::view_model::eye_at_origin) e = Q * -1;
    else if constexpr (F.view == phong::view_model::given) e = L3(s.view);
    else if constexpr (F.view == phong::view_model::eye_point)
        e = ld3{s.environment.eye.x, s.environment.eye.y, s.environment.eye.z} - Q * ld(s.environment.eye.w);
    else e = ld3{s.environment.eye.x, s.environment.eye.y, s.environment.eye.z};
    const ld ee = dot(e, e);
    const ld3 v = ee > 0 ? e * (1 / std::sqrt(ee)) : ld3{};
    bool two_sided_ambiguous = false;
    if constexpr (F.two_sided == phong::facing::view) {
        const ld nv0 = dot(n, v);
        if (nv0 < 0) n = n * -1;
        two_sided_ambiguous = std::fabs(double(nv0)) < 64 * u;
    } else if constexpr (F.two_sided == phong::facing::flag) {
        if (!s.front_facing) n = n * -1;
    }
    const ld nv = dot(n, v);
    constexpr bool gated = F.specular_gate || F.specular == specular_model::none;
    const bool view_in_range = F.view == phong::view_model::fixed_direction ? true : acc::exact_square_in_range<float>(ee);
    std::array<ld, 3> ambient{}, diffuse{}, specular{};
    std::array<double, 3> worst{}, worst_widened{};
    double f_max = 0, k_max = 0;
    const int K = int(s.lights.size());
    for (const phong::light<float>& L : s.lights) {
        const ld w = F.lights == phong::light_kind::positional ? 1 : F.lights == phong::light_kind::directional ? 0 : ld(L.position.w);
        const ld3 d = ld3{L.position.x, L.position.y, L.position.z} - Q * w;
        const ld dd = dot(d, d), len = std::sqrt(dd);
        const ld3 l = dd > 0 ? d * (1 / len) : ld3{};
        ld f = 1, den = 1;
        const bool attenuated = F.attenuation == phong::attenuation_model::polynomial && w > 0;
        if (attenuated) {
            den = ld(L.attenuation.constant) + ld(L.attenuation.linear) * len + ld(L.attenuation.quadratic) * len * len;
            f = 1 / std::max(den, ld(phong::detail::attenuation_denominator_min<float>));
        }
        // The window and the spot, beyond the exact bound's features: their own conditioning
        // (shade.hpp: "a spot adds its own conditioning: the cone cosine's few eps of rounding times
        // the spot's slope"), with the cone cosine's error E = 16 u (l: rho + 6 u, the axis
        // normalized: 3 u, the dot product: 3 u, rounded up), and the window's ratio's 8 u. +inf where
        // the cosine is within E of an edge of the cone, or the window within 2^-10 of closing.
        double f_extra = 0;
        const double inf = std::numeric_limits<double>::infinity();
        if (F.attenuation == phong::attenuation_model::windowed && w > 0) {
            const ld r = len / ld(L.attenuation.range), r4 = r * r * r * r;
            const ld window = std::clamp(1 - r4, ld(0), ld(1));
            f = window * window / std::max(len * len, ld(phong::detail::attenuation_denominator_min<float>));
            if (window > 0x1p-10) f_extra += double(8 * r4 / window) * 8 * u + 8 * u;
            else if (r4 < 1 + 64 * u) f_extra = inf; // closing: no relative bound
            // else beyond the range by more than the ratio's error: f = 0 on both sides
        }
        const bool has_cone = !(L.spot.direction.x == 0 && L.spot.direction.y == 0 && L.spot.direction.z == 0); // zero axis: no cone
        if (F.spot != phong::spot_model::none && has_cone) {
            const ld3 axis = L3(L.spot.direction);
            const ld c = -dot(l, axis * (1 / std::sqrt(dot(axis, axis))));
            const double E = 16 * u;
            ld spot = 1;
            if constexpr (F.spot == phong::spot_model::opengl) {
                if (L.spot.cos_cutoff > -1) {
                    spot = c >= L.spot.cos_cutoff ? (L.spot.exponent == 0 ? 1 : std::pow(std::clamp(c, ld(0), ld(1)), ld(L.spot.exponent))) : 0;
                    if (std::fabs(double(c - L.spot.cos_cutoff)) <= E) f_extra = inf; // at the cone's edge
                    else if (spot > 0 && L.spot.exponent > 0) {
                        if (c <= E) f_extra = inf;
                        else {
                            const double y = std::fabs(L.spot.exponent * std::log2(double(c)));
                            f_extra += L.spot.exponent * E / double(c) + pow_per_y_u * (1 + y + L.spot.exponent) * u;
                        }
                    }
                }
            } else {
                const ld width = ld(L.spot.cos_inner) - ld(L.spot.cos_outer);
                if (width > 0) {
                    const ld t = std::clamp((c - L.spot.cos_outer) / width, ld(0), ld(1));
                    const bool linear = F.spot == phong::spot_model::linear;
                    spot = linear ? t : t * t * (3 - 2 * t);
                    if (c < L.spot.cos_outer - 4 * E || c > L.spot.cos_inner + 4 * E) {
                        // outside the outer cone (0) or inside the inner one (1), beyond the cosine's error: exact
                    } else if (t * width <= ld(E) * 8) {
                        f_extra = inf; // at the outer edge: no relative bound
                    } else if (t < 1) {
                        // the spot's relative slope in c times the cosine's error E (smoothstep: 6 (1 - t) /
                        // (width t (3 - 2 t)); the linear edge: 1 / (width t)), plus the quotient's and clamp's rounding
                        const ld slope = linear ? 1 / (width * t) : 6 * (1 - t) / (width * t * (3 - 2 * t));
                        f_extra += double(slope) * E * 2 + 16 * u;
                    }
                } else {
                    spot = c >= L.spot.cos_outer ? 1 : 0;
                    if (std::fabs(double(c - L.spot.cos_outer)) <= E) f_extra = inf;
                }
            }
            f *= spot;
        }
        f_max = std::max(f_max, double(f));
        for (int ch = 0; ch < 3; ++ch) {
            k_max = std::max({k_max, double(L.diffuse[ch]), double(L.specular[ch]), double(L.ambient[ch])});
            if constexpr (F.light_ambient) ambient[ch] += ld(L.ambient[ch]) * (F.attenuate_ambient ? f : 1);
        }
        const ld nl = dot(n, l);
        const bool lit = nn > 0 && dd > 0 && (!gated || nl > 0);
        // A driver that flushes subnormals: the smallest squared length this pair reads.
        const double min_square = double(std::min({nn, dd, F.view == phong::view_model::fixed_direction ? ld(1) : ee}));
        const bool ftz_out = flushes && min_square < ftz_min_square;
        // The flushed part of a product, relative, times the slope of what the light's f reads
        // (a spot's cone cosine: f_extra / u bounds that slope times 16).
        const double ftz_extra = flushes ? 8 * 0x1p-126 / std::max(min_square, 0x1p-126) * (1 + f_extra / u) : 0;
        // conditioning (phong/accuracy.hpp)
        acc::pair_conditioning k;
        k.nl = double(nl);
        k.nv = double(nv);
        k.attenuated = attenuated;
        k.in_range = acc::exact_square_in_range<float>(nn) && view_in_range && acc::exact_square_in_range<float>(dd) &&
                     (!attenuated || acc::exact_denominator_in_range<float>(den));
        k.m = s.material.shininess;
        ld c = 0;
        if constexpr (F.specular == specular_model::phong) {
            c = dot(n * (2 * nl) - l, v);
            k.specular = specular_model::phong;
        } else if constexpr (F.specular == specular_model::blinn) {
            const ld3 h = l + v;
            const ld sigma = std::sqrt(dot(h, h));
            c = sigma > 0 ? dot(n, h) / sigma : 0;
            k.specular = specular_model::blinn;
            k.blinn_sum = double(sigma);
        } else {
            k.specular = specular_model::none;
        }
        k.c = double(c);
        // The light's ambient term ka La_i f (attenuated): f's error, lit or not.
        double ambient_bound = 0;
        if (F.light_ambient && F.attenuate_ambient && (attenuated || f_extra > 0)) {
            acc::pair_conditioning ka = k;
            ka.nl = 1;
            ka.specular = specular_model::none;
            ka.in_range = true;
            ambient_bound = acc::detail::compose(acc::exact_diffuse_bound<float>(ka), f_extra);
            for (int ch = 0; ch < 3; ++ch)
                if (s.material.ka[ch] * L.ambient[ch] > 0) {
                    worst[ch] = std::max(worst[ch], ambient_bound);
                    double widened = ambient_bound * operation_factor + ftz_extra;
                    if (ftz_out && f_extra > 0) widened = std::max(widened, 1.0); // l (the spot's) may be lost to flushing
                    worst_widened[ch] = std::max(worst_widened[ch], widened);
                }
        }
        if (!lit) continue; // both sides add no diffuse or specular
        ld power = 0;
        if (ee > 0) power = k.m == 0 ? 1 : (c > 0 ? std::pow(std::min(c, ld(1)), ld(k.m)) : 0);
        double diffuse_bound = acc::exact_diffuse_bound<float>(k);
        acc::pair_conditioning ks = k;
        if (!gated) ks.nl = 1; // no gate: the specular term does not depend on n.l's sign (n.l enters E_c: 1 is the larger)
        double specular_bound = F.specular == specular_model::none || !(ee > 0) ? 0 : acc::exact_specular_bound<float>(ks);
        const double y = (c > 0 && k.m > 0) ? std::fabs(k.m * std::log2(double(std::min(c, ld(1))))) : 0;
        if (two_sided_ambiguous) diffuse_bound = specular_bound = std::numeric_limits<double>::infinity();
        if (f_extra > 0) { // the window's and the spot's own error, on every term the light scales
            diffuse_bound = acc::detail::compose(diffuse_bound, f_extra);
            specular_bound = acc::detail::compose(specular_bound, f_extra);
        }
        for (int ch = 0; ch < 3; ++ch) {
            const ld kd = ld(s.material.kd[ch]) * ld(L.diffuse[ch]), kspec = ld(s.material.ks[ch]) * ld(L.specular[ch]);
            if (F.diffuse) diffuse[ch] += ld(L.diffuse[ch]) * f * std::max(nl, ld(0));
            if (F.specular != specular_model::none) specular[ch] += ld(L.specular[ch]) * f * power;
            double term = 0, term_widened = 0;
            if (F.diffuse && kd > 0) {
                term = std::max(term, diffuse_bound);
                term_widened = std::max(term_widened, diffuse_bound * operation_factor + ftz_extra);
            }
            if (F.specular != specular_model::none && kspec > 0) {
                term = std::max(term, specular_bound);
                const double pow_extra = k.m > 0 ? pow_per_y_u * (1 + y + k.m) * u : 0;
                term_widened = std::max(term_widened, specular_bound * operation_factor + pow_extra + ftz_extra * (1 + k.m));
            }
            if (ftz_out && term_widened > 0) term_widened = std::max(term_widened, 1.0); // the vector may be lost
            worst[ch] = std::max(worst[ch], term);
            worst_widened[ch] = std::max(worst_widened[ch], term_widened);
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        ld I = 0;
        if constexpr (F.emission) I += s.material.emission[ch];
        ld amb = 0;
        if constexpr (F.scene_ambient) amb += s.environment.ambient[ch];
        if constexpr (F.light_ambient) amb += ambient[ch];
        I += ld(s.material.ka[ch]) * amb;
        if constexpr (F.diffuse) I += ld(s.material.kd[ch]) * diffuse[ch];
        if constexpr (F.specular != specular_model::none) I += ld(s.material.ks[ch]) * specular[ch];
        out.color[std::size_t(ch)] = I;
        out.bound[std::size_t(ch)] = acc::exact_bound<float>(worst[ch], K);
        out.widened[std::size_t(ch)] =
            acc::detail::compose(worst_widened[ch], acc::detail::g<float>(K + 5) * operation_factor);
    }
    out.color[3] = s.material.alpha;
    out.allowance = acc::exact_absolute_allowance<float>(K, f_max, std::max({k_max, 1.0}));
    return out;
}

// ---- the cases ------------------------------------------------------------------------------

struct generator {
    std::mt19937_64 rng;
    explicit generator(std::uint64_t seed) : rng(seed) {}
    float uniform(float lo, float hi) { return lo + (hi - lo) * float(double(rng() >> 11) * 0x1p-53); }
    glm::vec3 box(float r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
    glm::vec3 colour(float hi = 1) { return {uniform(0, hi), uniform(0, hi), uniform(0, hi)}; }
    glm::vec3 direction()
    {
        for (;;) {
            const glm::vec3 v = box(1);
            const float vv = glm::dot(v, v);
            if (vv > 0.01f && vv <= 1) return v / std::sqrt(vv);
        }
    }
};

/// Lights from this index on get no cone in random scenes (a test of PHONG_SPOT_LIGHTS sets it).
int cone_lights = max_lights;

/// A random scene: a point in front of the eye, a normal of any length, 1-4 lights (positional or
/// directional as F allows) with polynomial falloff, m in [0, 200] (some 0, some integers).
template <features F>
scene random_scene(generator& g)
{
    scene s;
    s.position = g.box(4) + glm::vec3(0, 0, -6);
    // One draw per statement (argument and operand order is the compiler's): the same cases with
    // every compiler.
    s.normal = g.direction();
    s.normal *= g.uniform(0.2f, 3.0f);
    s.view = g.direction();
    s.view *= g.uniform(0.5f, 2.0f);
    s.front_facing = g.rng() % 4 != 0;
    s.material.ka = g.colour();
    s.material.kd = g.colour();
    s.material.ks = g.colour();
    s.material.emission = g.colour(0.2f);
    const int kind = int(g.rng() % 8);
    s.material.shininess = kind == 0 ? 0.0f : kind < 3 ? float(1 + g.rng() % 128) : g.uniform(0.5f, 200);
    s.material.alpha = g.uniform(0, 1);
    s.environment.ambient = g.colour(0.5f);
    s.environment.eye = g.rng() % 3 == 0 ? glm::vec4(g.direction(), 0) : glm::vec4(g.box(2), 1);
    if constexpr (F.unit_inputs) { // the precondition: unit normal and view vector
        s.normal = glm::normalize(s.normal);
        s.view = glm::normalize(s.view);
    }
    const int K = 1 + int(g.rng() % max_lights);
    for (int i = 0; i < K; ++i) {
        phong::light<float> L;
        const bool directional = F.lights == phong::light_kind::directional ||
                                 (F.lights == phong::light_kind::any && g.rng() % 3 == 0);
        L.position = directional ? glm::vec4(g.direction(), 0) : glm::vec4(g.box(8) + glm::vec3(0, 0, -4), 1);
        L.ambient = g.colour(0.3f);
        L.diffuse = g.colour();
        L.specular = g.colour();
        L.attenuation = {g.uniform(0.2f, 1), g.uniform(0, 0.3f), g.uniform(0, 0.05f),
                         g.rng() % 4 == 0 ? std::numeric_limits<float>::infinity() : g.uniform(4, 30)};
        if constexpr (F.spot != phong::spot_model::none) {
            // An axis roughly toward the point, so that the point is inside some cones and outside others.
            const glm::vec3 toward_point = directional ? -glm::vec3(L.position) : s.position - glm::vec3(L.position);
            const glm::vec3 axis = glm::normalize(glm::normalize(toward_point) + g.box(0.6f)) ;
            if constexpr (F.spot == phong::spot_model::opengl) {
                const float exponent = g.rng() % 4 == 0 ? 0.0f : g.uniform(0, 64);
                const float cutoff = g.rng() % 5 == 0 ? 180.0f : g.uniform(10, 90);
                L.spot = phong::spot_cone<float>::opengl(axis, exponent, cutoff);
            } else {
                const float inner = g.uniform(0, 40);
                L.spot = phong::spot_cone<float>::smooth(axis, inner, g.rng() % 6 == 0 ? inner : inner + g.uniform(0, 40));
            }
            // One light in five has no cone: every spot field 0, as uniforms left unset are; and
            // every light from cone_lights on (the twin's PHONG_SPOT_LIGHTS).
            if (g.rng() % 5 == 0 || i >= cone_lights) L.spot = phong::spot_cone<float>{glm::vec3(0), 0, 0, 0, 0};
        }
        s.lights.push_back(L);
    }
    return s;
}

/// The edge cases of the model's policy, applied to a random scene (kind 0 .. edge_kinds - 1):
/// a light at the point; a zero normal; Blinn's l = -v; the point at the eye (or a zero given v);
/// m = 0; c0 = 0 with the light at the point (the attenuation cap); coordinates scaled by 1e18
/// and by 1e-18; a directional light with xyz = 0; the normal facing away from the viewer.
constexpr int edge_kinds = 10;
template <features F>
void make_edge(scene& s, int kind)
{
    phong::light<float>& L0 = s.lights[0];
    const glm::vec3 eye3(s.environment.eye);
    const auto view_dir = [&]() -> glm::vec3 { // from Q toward the viewer, unnormalized
        if constexpr (F.view == phong::view_model::eye_at_origin) return -s.position;
        else if constexpr (F.view == phong::view_model::given) return s.view;
        else if constexpr (F.view == phong::view_model::eye_point) return eye3 - s.environment.eye.w * s.position;
        else return eye3;
    };
    if (F.unit_inputs && (kind == 1 || kind == 3 || kind == 6 || kind == 7)) kind = 4; // would break the unit precondition
    switch (kind) {
    case 0: L0.position = glm::vec4(s.position, 1); break;
    case 1: s.normal = glm::vec3(0); break;
    case 2: { // l = -v: the light on the line from the viewer through Q, beyond Q
        if (L0.position.w == 0) L0.position = glm::vec4(-view_dir(), 0);
        else L0.position = glm::vec4(s.position - view_dir(), 1);
        break;
    }
    case 3:
        if constexpr (F.view == phong::view_model::eye_at_origin) s.position = glm::vec3(0);
        else if constexpr (F.view == phong::view_model::given) s.view = glm::vec3(0);
        else if constexpr (F.view == phong::view_model::eye_point) s.environment.eye = glm::vec4(s.position, 1);
        break;
    case 4: s.material.shininess = 0; break;
    case 5:
        L0.position = glm::vec4(s.position, 1);
        L0.attenuation = {0, 0, 1, std::numeric_limits<float>::infinity()};
        break;
    case 6:
    case 7: {
        const float k = kind == 6 ? 1e18f : 1e-18f;
        s.position *= k;
        s.normal *= k;
        s.environment.eye = glm::vec4(glm::vec3(s.environment.eye) * k, s.environment.eye.w);
        for (auto& L : s.lights) L.position = glm::vec4(glm::vec3(L.position) * k, L.position.w);
        break;
    }
    case 8:
        if constexpr (F.lights == phong::light_kind::any) L0.position = glm::vec4(0, 0, 0, 0);
        else L0.position = glm::vec4(s.position, 1);
        break;
    default: s.normal = F.unit_inputs ? glm::normalize(-view_dir()) : -view_dir(); break;
    }
}

/// Texels per case (RGBA32F, one row per case): the layout the test shader reads.
constexpr int texels_per_case = 9 + 6 * max_lights;

void pack(const scene& s, float* t)
{
    const auto put = [&](int i, glm::vec4 v) { t[4 * i] = v.x, t[4 * i + 1] = v.y, t[4 * i + 2] = v.z, t[4 * i + 3] = v.w; };
    const phong::material<float>& m = s.material;
    put(0, glm::vec4(s.position, s.front_facing ? 1.0f : 0.0f));
    put(1, glm::vec4(s.normal, float(s.lights.size())));
    put(2, glm::vec4(s.view, m.shininess));
    put(3, glm::vec4(m.ka, m.alpha));
    put(4, glm::vec4(m.kd, 0));
    put(5, glm::vec4(m.ks, 0));
    put(6, glm::vec4(m.emission, 0));
    put(7, glm::vec4(s.environment.ambient, 0));
    put(8, s.environment.eye);
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const phong::light<float>& L = s.lights[i];
        const int b = 9 + 6 * int(i);
        put(b, L.position);
        put(b + 1, glm::vec4(L.ambient, L.attenuation.range));
        put(b + 2, glm::vec4(L.diffuse, L.attenuation.constant));
        put(b + 3, glm::vec4(L.specular, L.attenuation.linear));
        put(b + 4, glm::vec4(L.spot.direction, L.attenuation.quadratic));
        put(b + 5, glm::vec4(L.spot.exponent, L.spot.cos_cutoff, L.spot.cos_inner, L.spot.cos_outer));
    }
}

/// The test's vertex shader after the twin: case gl_VertexID read from the texture, shaded by
/// phong_shade, the colour captured as `result` (alpha 0 without PHONG_ALPHA).
const char* const case_shader = R"(
uniform highp sampler2D cases;
out vec4 result;
vec4 at(int i) { return texelFetch(cases, ivec2(i, gl_VertexID), 0); }
void main() {
    phong_material mat;
    mat.ka = at(3).xyz; mat.alpha = at(3).w; mat.kd = at(4).xyz; mat.ks = at(5).xyz; mat.emission = at(6).xyz;
    mat.shininess = at(2).w;
    phong_environment env;
    env.ambient = at(7).xyz;
    env.eye = at(8);
    int count = int(at(1).w);
    phong_light lights[PHONG_MAX_LIGHTS];
    for (int i = 0; i < PHONG_MAX_LIGHTS; ++i) {
        int b = 9 + 6 * i;
        lights[i].position = at(b);
        lights[i].ambient = at(b + 1).xyz; lights[i].attenuation.range = at(b + 1).w;
        lights[i].diffuse = at(b + 2).xyz; lights[i].attenuation.constant = at(b + 2).w;
        lights[i].specular = at(b + 3).xyz; lights[i].attenuation.linear = at(b + 3).w;
        lights[i].spot.direction = at(b + 4).xyz; lights[i].attenuation.quadratic = at(b + 4).w;
        lights[i].spot.exponent = at(b + 5).x; lights[i].spot.cos_cutoff = at(b + 5).y;
        lights[i].spot.cos_inner = at(b + 5).z; lights[i].spot.cos_outer = at(b + 5).w;
    }
    phong_color c = phong_shade(at(0).xyz, at(1).xyz, at(2).xyz, mat, lights, count, env, at(0).w > 0.5);
#if PHONG_ALPHA
    result = c;
#else
    result = vec4(c, 0.0);
#endif
    gl_Position = vec4(0.0);
}
)";

/// Which twin a run tests: the GLSL one, or the HLSL one (tests/glsl/case.hlsl through
/// glslangValidator's HLSL front end, spirv-val, and spirv-cross back to GLSL for this context).
enum class language { glsl, hlsl };

/// Runs a command; throws naming it (with its log) when it fails.
[[maybe_unused]] void run_tool(const std::string& command, const std::string& log)
{
    if (std::system(command.c_str()) == 0) return;
    std::ifstream in(log, std::ios::binary);
    throw std::runtime_error("failed: " + command + "\n" + std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

/// The HLSL twin's test shader with `defines`, as GLSL for context c: case.hlsl compiled by
/// glslangValidator -D -e main -V (HLSL to SPIR-V), validated by spirv-val, translated by
/// spirv-cross to the context's GLSL version. Throws when a tool is missing or fails.
std::string hlsl_as_glsl(const glt::context& c, const std::string& defines)
{
#if defined(PHONG_GLSLANG_VALIDATOR) && defined(PHONG_SPIRV_VAL) && defined(PHONG_SPIRV_CROSS)
    static int serial = 0;
    const std::string base = std::string(PHONG_HLSL_WORK_DIR) + "/case" + std::to_string(serial++);
    {
        std::ofstream out(base + ".hlsl", std::ios::binary);
        out << defines << "#include \"case.hlsl\"\n"; // found through -I (glslang takes no absolute include path)
        if (!out) throw std::runtime_error("cannot write " + base + ".hlsl");
    }
    const std::string quiet = " >" + base + ".log 2>&1";
    run_tool(std::string(PHONG_GLSLANG_VALIDATOR) + " -D -e main -V -S vert -I" + PHONG_INCLUDE_DIR + " -I" + PHONG_CASE_HLSL_DIR + " " + base +
             ".hlsl -o " + base + ".spv" + quiet, base + ".log");
    run_tool(std::string(PHONG_SPIRV_VAL) + " " + base + ".spv" + quiet, base + ".log");
    const bool es = c.which() == glt::api::gles30;
    run_tool(std::string(PHONG_SPIRV_CROSS) + " " + base + ".spv" + (es ? " --es --version 300" : " --no-es --version 330") + " --output " +
             base + ".glsl" + quiet, base + ".log");
    std::ifstream in(base + ".glsl", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
#else
    (void)c, (void)defines;
    throw std::runtime_error("the HLSL twin's tools were not found at configure time (glslangValidator, spirv-val, spirv-cross: "
                             "apt-get install glslang-tools spirv-tools spirv-cross)");
#endif
}

/// The twin's colours of `scenes` in context c with the given defines (chunks of 4096 cases).
std::vector<float> run_twin(const glt::context& c, const std::string& defines, const std::vector<scene>& scenes,
                            language lang = language::glsl)
{
    const std::string text = lang == language::glsl
                                 ? phong::glsl::shader(glt::version_line(c.which()), defines, phong::glsl::source(), case_shader)
                                 : hlsl_as_glsl(c, defines);
    glt::feedback_program program(c, text, lang == language::glsl ? "result" : "_entryPointOutput_result");
    std::vector<float> out;
    constexpr std::size_t chunk = 4096;
    for (std::size_t first = 0; first < scenes.size(); first += chunk) {
        const std::size_t n = std::min(chunk, scenes.size() - first);
        std::vector<float> texels(n * texels_per_case * 4, 0.0f);
        for (std::size_t i = 0; i < n; ++i) pack(scenes[first + i], &texels[i * texels_per_case * 4]);
        glt::float_texture tex(c, texels_per_case, int(n), texels);
        const std::vector<float> r = program.run(int(n), 4, [&] { // the sampler (any name spirv-cross gave it) reads unit 0, its default
            if (lang == language::glsl) c.gl().glUniform1i(program.uniform("cases"), 0);
        });
        out.insert(out.end(), r.begin(), r.end());
    }
    return out;
}

/// phong::shade<F> on the CPU, float, as rgba (alpha 0 without F.alpha).
template <features F>
glm::vec4 cpu_shade(const scene& s)
{
    const std::span<const phong::light<float>> lights(s.lights);
    if constexpr (F.view == phong::view_model::given) {
        const auto c = phong::shade<F>(s.position, s.normal, s.view, s.material, lights, s.environment, s.front_facing);
        if constexpr (F.alpha) return c;
        else return glm::vec4(c, 0);
    } else {
        const auto c = phong::shade<F>(s.position, s.normal, s.material, lights, s.environment, s.front_facing);
        if constexpr (F.alpha) return c;
        else return glm::vec4(c, 0);
    }
}

/// What one preset's run measured.
struct tally {
    int cases = 0, edge_cases = 0, channels = 0, bounded = 0, unbounded = 0, failures = 0, non_finite = 0, cpu_failures = 0;
    double worst_rel = 0, worst_rel_cpu = 0, worst_rel_twin_cpu = 0, worst_rel_edge = 0;
    double worst_ratio = 0; // worst error / its widened bound
};

driver_error measured; // llvmpipe's error, measured once per process (the first context's)
bool measured_once = false;

/// defines: the twin's feature defines (the CPU side is F, whose exact mode's bound the widened
/// bound starts from, also for the twin's fast mode).
template <features F>
tally agree(const glt::context& c, const std::string& defines, int random_cases, std::uint64_t seed, language lang = language::glsl)
{
    if (!measured_once) {
        measured = measure_driver(c);
        measured_once = true;
    }
    const double factor = std::max({1.0, measured.sqrt_u, measured.reciprocal_u, measured.rsqrt_u / 2, measured.inversesqrt_u / 2});
    generator g(seed);
    std::vector<scene> scenes;
    const int edges = random_cases / 3;
    for (int i = 0; i < random_cases + edges; ++i) {
        scene s = random_scene<F>(g);
        if (i >= random_cases) make_edge<F>(s, (i - random_cases) % edge_kinds);
        scenes.push_back(s);
    }
    const std::vector<float> twin = run_twin(c, defines, scenes, lang);
    tally t;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const scene& s = scenes[i];
        const bool edge = int(i) >= random_cases;
        ++(edge ? t.edge_cases : t.cases);
        const reference r = evaluate<F>(s, factor, measured.pow_per_y_u * 1.0001, measured.flushes_subnormals);
        const glm::vec4 cpu = cpu_shade<F>(s);
        for (int ch = 0; ch < (F.alpha ? 4 : 3); ++ch) {
            const double gpu = twin[i * 4 + std::size_t(ch)];
            ++t.channels;
            if (!std::isfinite(gpu) || gpu < 0) {
                ++t.non_finite;
                ++t.failures;
                MESSAGE("case " << i << " channel " << ch << ": " << gpu << " (not finite and >= 0)");
                continue;
            }
            const double I = double(r.color[std::size_t(ch)]);
            const double err = std::fabs(gpu - I), err_cpu = std::fabs(double(cpu[ch]) - I);
            const double scale = std::max(std::fabs(I), 1e-30);
            if (ch == 3) { // alpha: the material's, exactly
                if (gpu != double(s.material.alpha)) {
                    ++t.failures;
                    MESSAGE("case " << i << ": alpha " << gpu);
                }
                continue;
            }
            const double bound = r.bound[std::size_t(ch)], widened = r.widened[std::size_t(ch)];
            if (!(widened < std::numeric_limits<double>::infinity())) {
                ++t.unbounded;
                continue;
            }
            ++t.bounded;
            const double allowed = widened * std::fabs(I) + r.allowance;
            const double rel = err / scale;
            if (edge) t.worst_rel_edge = std::max(t.worst_rel_edge, std::min(rel, 1.0));
            else t.worst_rel = std::max(t.worst_rel, rel);
            if (allowed > 0) t.worst_ratio = std::max(t.worst_ratio, err / allowed);
            if (!edge) t.worst_rel_twin_cpu = std::max(t.worst_rel_twin_cpu, std::fabs(gpu - double(cpu[ch])) / scale);
            if (!edge) t.worst_rel_cpu = std::max(t.worst_rel_cpu, err_cpu / scale);
            if (err > allowed) {
                ++t.failures;
                if (t.failures <= 5)
                    MESSAGE("case " << i << " (" << (edge ? "edge" : "random") << ") channel " << ch << ": twin " << gpu << ", model "
                                    << I << ", cpu " << cpu[ch] << ", error " << err << " > allowed " << allowed);
            }
            if (err_cpu > bound * std::fabs(I) + r.allowance) ++t.cpu_failures;
        }
    }
    return t;
}

/// define: the preset's define (nullptr: every field of F, phong::glsl::defines(F)); extra: more
/// defines after it (PHONG_MODE_FAST: the twin's fast mode, GLSL's inversesqrt).
template <features F>
void check_preset(glt::api a, const char* name, const char* define, std::uint64_t seed, const std::string& extra = "",
                  language lang = language::glsl)
{
    const auto c = open(a);
    if (!c) return;
    const std::string defines = (define ? std::string("#define ") + define + "\n#define PHONG_MAX_LIGHTS " + std::to_string(max_lights) + "\n"
                                        : phong::glsl::defines(F, max_lights)) + extra;
    const tally t = agree<F>(*c, defines, 3000, seed, lang);
    MESSAGE(std::string(lang == language::hlsl ? "HLSL twin, " : "") << glt::api_name(a) << ", " << std::string(name) << std::string(extra.find("PHONG_MODE_FAST") == std::string::npos ? "" : ", fast mode") << ": " << t.cases << " random + " << t.edge_cases << " edge cases, " << t.channels
                             << " channels (" << t.bounded << " with a bound, " << t.unbounded
                             << " without: a gate or a two-sided flip within rounding); worst relative error against the model: twin "
                             << t.worst_rel << " (random), " << t.worst_rel_edge << " (edge, capped at 1), phong::shade float "
                             << t.worst_rel_cpu << "; twin against phong::shade " << t.worst_rel_twin_cpu
                             << "; worst error / widened bound " << t.worst_ratio);
    CHECK(t.non_finite == 0);
    CHECK(t.failures == 0);
    CHECK(t.cpu_failures == 0); // the reference written here agrees with phong::shade within the published bound
    CHECK(t.bounded > t.channels / 2);
}

} // namespace

TEST_CASE("llvmpipe's own error: sqrt, 1/x, 1/sqrt, inversesqrt and pow against a double reference")
{
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30}) {
        const auto c = open(a);
        if (!c) return;
        const driver_error e = measure_driver(*c);
        MESSAGE(glt::api_name(a) << ", " << e.samples << " samples: sqrt " << e.sqrt_u << " u, 1/x " << e.reciprocal_u << " u, 1/sqrt(x) "
                                 << e.rsqrt_u << " u, inversesqrt " << e.inversesqrt_u << " u, pow " << e.pow_per_y_u
                                 << " (1 + |m log2 x| + m) u (worst relative " << e.pow_worst_rel << " at x = " << e.pow_worst_x
                                 << ", m = " << e.pow_worst_m << "); subnormal products "
                                 << std::string(e.flushes_subnormals ? "flushed to 0" : "kept"));
        CHECK(e.samples > 40000);
        CHECK(e.sqrt_u <= allowed_operation_u);
        CHECK(e.reciprocal_u <= allowed_operation_u);
        CHECK(e.rsqrt_u <= 2 * allowed_operation_u);
        CHECK(e.inversesqrt_u <= allowed_inversesqrt_u);
        CHECK(e.pow_per_y_u <= allowed_pow_per_y_u);
    }
}

/// Every preset through the twin in context API a (seeds per API: different cases in each).
void check_presets(glt::api a, std::uint64_t seed)
{
    check_preset<phong::presets::classic_phong>(a, "classic_phong", "PHONG_PRESET_CLASSIC_PHONG", seed * 10 + 1);
    check_preset<phong::presets::blinn_phong_per_light_ambient>(a, "blinn_phong_per_light_ambient",
                                                                "PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT", seed * 10 + 2);
    check_preset<phong::presets::raytracer_phong>(a, "raytracer_phong", "PHONG_PRESET_RAYTRACER_PHONG", seed * 10 + 3);
    check_preset<phong::presets::glsl_ads>(a, "glsl_ads", "PHONG_PRESET_GLSL_ADS", seed * 10 + 4);
    check_preset<phong::presets::diffuse_only>(a, "diffuse_only", "PHONG_PRESET_DIFFUSE_ONLY", seed * 10 + 5);
}

TEST_CASE("the twin agrees with the model, every preset, GLSL 330 core") { check_presets(glt::api::gl33_core, 1); }
TEST_CASE("the twin agrees with the model, every preset, GLSL 300 es") { check_presets(glt::api::gles30, 2); }
/// Feature sets no preset has, to run every branch of the twin: spot cones (OpenGL and smooth),
/// windowed falloff, emission, per-light ambient with and without attenuation, lights of any kind
/// and directional, every view model, two-sided by flag and by view, ungated Phong, unit inputs.
constexpr features spot_windowed_blinn{.scene_ambient = true, .light_ambient = true, .diffuse = true,
                                       .specular = specular_model::blinn, .specular_gate = true, .lights = phong::light_kind::any,
                                       .attenuation = phong::attenuation_model::windowed, .spot = phong::spot_model::opengl,
                                       .attenuate_ambient = true, .two_sided = phong::facing::flag,
                                       .view = phong::view_model::fixed_direction, .emission = true, .alpha = false};
constexpr features smooth_spot_phong{.scene_ambient = false, .light_ambient = true, .diffuse = true,
                                     .specular = specular_model::phong, .specular_gate = false, .lights = phong::light_kind::positional,
                                     .attenuation = phong::attenuation_model::polynomial, .spot = phong::spot_model::smooth,
                                     .attenuate_ambient = false, .two_sided = phong::facing::view,
                                     .view = phong::view_model::eye_point, .emission = false, .alpha = true};
constexpr features directional_spot_diffuse{.scene_ambient = true, .light_ambient = false, .diffuse = true,
                                            .specular = specular_model::none, .specular_gate = true,
                                            .lights = phong::light_kind::directional, .attenuation = phong::attenuation_model::none,
                                            .spot = phong::spot_model::opengl, .attenuate_ambient = true,
                                            .two_sided = phong::facing::none, .view = phong::view_model::eye_at_origin};
constexpr features raytracer_unit_inputs = [] {
    features f = phong::presets::raytracer_phong;
    f.unit_inputs = true;
    return f;
}();

TEST_CASE("the twin agrees with the model beyond the presets: spots, windowed falloff, every view model, unit inputs (330, 300 es)")
{
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30}) {
        const std::uint64_t seed = a == glt::api::gles30 ? 60 : 50;
        check_preset<spot_windowed_blinn>(a, "OpenGL spot, windowed, Blinn, fixed direction, two-sided flag", nullptr, seed + 1);
        check_preset<smooth_spot_phong>(a, "smooth spot, polynomial, ungated Phong, eye point, two-sided view", nullptr, seed + 2);
        check_preset<directional_spot_diffuse>(a, "directional, OpenGL spot, diffuse only", nullptr, seed + 3);
        check_preset<raytracer_unit_inputs>(a, "raytracer_phong with unit_inputs", nullptr, seed + 4);
    }
}

TEST_CASE("the twin's fast mode (inversesqrt) agrees with the model: Phong and Blinn presets, GLSL 330 core and 300 es")
{
    const std::string fast = "#define PHONG_MODE PHONG_MODE_FAST\n";
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30}) {
        const std::uint64_t seed = a == glt::api::gles30 ? 40 : 30;
        check_preset<phong::presets::glsl_ads>(a, "glsl_ads", "PHONG_PRESET_GLSL_ADS", seed + 1, fast);
        check_preset<phong::presets::blinn_phong_per_light_ambient>(a, "blinn_phong_per_light_ambient",
                                                                    "PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT", seed + 2, fast);
    }
}

/// The tutorial-shaped feature set (docs/glsl.md's world-space recipe): per-light ambient,
/// ungated Phong, lights of any kind, polynomial falloff, the linear cone edge, the eye a point.
constexpr features linear_spot_tutorial{.scene_ambient = false, .light_ambient = true, .diffuse = true,
                                        .specular = specular_model::phong, .specular_gate = false, .lights = phong::light_kind::any,
                                        .attenuation = phong::attenuation_model::polynomial, .spot = phong::spot_model::linear,
                                        .attenuate_ambient = true, .two_sided = phong::facing::none,
                                        .view = phong::view_model::eye_point};

TEST_CASE("the twin's linear cone edge agrees with the model, lights with and without a cone (330, 300 es)")
{
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30})
        check_preset<linear_spot_tutorial>(a, "linear spot, per-light ambient, ungated Phong, any lights, eye point", nullptr,
                                           a == glt::api::gles30 ? 71 : 70);
}

TEST_CASE("PHONG_SPOT_LIGHTS: only the first lights' cones are read; the same colours as the model (330, 300 es)")
{
    // Lights from index 1 on have no cone in these scenes (their spot fields 0); the twin reads
    // only light 0's cone. A second run puts a cone on every light but still reads only light 0's:
    // it must differ from the model where a later light's cone matters (the define is a promise).
    cone_lights = 1;
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30})
        check_preset<linear_spot_tutorial>(a, "linear spot, PHONG_SPOT_LIGHTS 1", nullptr, a == glt::api::gles30 ? 73 : 72,
                                           "#define PHONG_SPOT_LIGHTS 1\n");
    cone_lights = max_lights;
    const auto c = open(glt::api::gl33_core);
    if (!c) return;
    generator g(74);
    std::vector<scene> scenes;
    for (int i = 0; i < 256; ++i) scenes.push_back(random_scene<linear_spot_tutorial>(g));
    const std::string defines = phong::glsl::defines(linear_spot_tutorial, max_lights);
    const std::vector<float> all = run_twin(*c, defines, scenes), first = run_twin(*c, defines + "#define PHONG_SPOT_LIGHTS 1\n", scenes);
    CHECK(all != first);
}

/// Every feature set the GLSL twin is tested with, through the HLSL twin (the same seeds: the same
/// cases as the GLSL runs of the same API).
void check_hlsl(glt::api a, std::uint64_t preset_seed, std::uint64_t extra_seed, std::uint64_t fast_seed, std::uint64_t linear_seed)
{
    const language h = language::hlsl;
    check_preset<phong::presets::classic_phong>(a, "classic_phong", "PHONG_PRESET_CLASSIC_PHONG", preset_seed * 10 + 1, "", h);
    check_preset<phong::presets::blinn_phong_per_light_ambient>(a, "blinn_phong_per_light_ambient",
                                                                "PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT", preset_seed * 10 + 2, "", h);
    check_preset<phong::presets::raytracer_phong>(a, "raytracer_phong", "PHONG_PRESET_RAYTRACER_PHONG", preset_seed * 10 + 3, "", h);
    check_preset<phong::presets::glsl_ads>(a, "glsl_ads", "PHONG_PRESET_GLSL_ADS", preset_seed * 10 + 4, "", h);
    check_preset<phong::presets::diffuse_only>(a, "diffuse_only", "PHONG_PRESET_DIFFUSE_ONLY", preset_seed * 10 + 5, "", h);
    check_preset<spot_windowed_blinn>(a, "OpenGL spot, windowed, Blinn, fixed direction, two-sided flag", nullptr, extra_seed + 1, "", h);
    check_preset<smooth_spot_phong>(a, "smooth spot, polynomial, ungated Phong, eye point, two-sided view", nullptr, extra_seed + 2, "", h);
    check_preset<directional_spot_diffuse>(a, "directional, OpenGL spot, diffuse only", nullptr, extra_seed + 3, "", h);
    check_preset<raytracer_unit_inputs>(a, "raytracer_phong with unit_inputs", nullptr, extra_seed + 4, "", h);
    const std::string fast = "#define PHONG_MODE PHONG_MODE_FAST\n";
    check_preset<phong::presets::glsl_ads>(a, "glsl_ads", "PHONG_PRESET_GLSL_ADS", fast_seed + 1, fast, h);
    check_preset<phong::presets::blinn_phong_per_light_ambient>(a, "blinn_phong_per_light_ambient",
                                                                "PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT", fast_seed + 2, fast, h);
    check_preset<linear_spot_tutorial>(a, "linear spot, per-light ambient, ungated Phong, any lights, eye point", nullptr, linear_seed, "", h);
    cone_lights = 1;
    check_preset<linear_spot_tutorial>(a, "linear spot, PHONG_SPOT_LIGHTS 1", nullptr, linear_seed + 2, "#define PHONG_SPOT_LIGHTS 1\n", h);
    cone_lights = max_lights;
}

TEST_CASE("the HLSL twin (glslang's HLSL front end, spirv-val, spirv-cross to GLSL 330) agrees with the model, every feature set")
{
    check_hlsl(glt::api::gl33_core, 1, 50, 30, 70);
}

TEST_CASE("the HLSL twin (glslang's HLSL front end, spirv-val, spirv-cross to GLSL 300 es) agrees with the model, every feature set")
{
    check_hlsl(glt::api::gles30, 2, 60, 40, 71);
}

TEST_CASE("seed 003's phong.vert, verbatim, against the twin's phong_shade_vertex and phong::shade_vertex (GLSL 410)")
{
    const auto c = open(glt::api::gl41_core);
    if (!c) return;
    if (!measured_once) measured = measure_driver(*c), measured_once = true;
    const double factor = std::max({1.0, measured.sqrt_u, measured.reciprocal_u, measured.rsqrt_u / 2});
    constexpr features F = phong::presets::glsl_ads;
    glt::feedback_program seed(*c, glt::seed003_source(PHONG_SEED003_VERT), "LightIntensity");
    glt::feedback_program twin(*c, glt::twin_ads_source(), "LightIntensity");
    generator g(3003);
    constexpr int sets = 16, per_set = 256;
    int cases = 0, failures_twin = 0, failures_seed = 0, non_finite = 0;
    double worst_twin = 0, worst_seed = 0, worst_seed_twin = 0, worst_cpu_twin = 0;
    for (int k = 0; k < sets; ++k) {
        glt::ads_uniforms uni;
        const glm::vec3 axis = g.direction();
        const glm::vec3 offset = g.box(1);
        const float angle = g.uniform(0, 6.28f);
        const glm::vec3 scale = g.box(0.75f) + glm::vec3(1.25f); // in [0.5, 2]
        uni.model_view = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6) + offset) * glm::rotate(glm::mat4(1), angle, axis) *
                         glm::scale(glm::mat4(1), scale);
        uni.normal_matrix = phong::normal_matrix(uni.model_view);
        uni.projection = glm::perspective(0.8f, 1.3f, 0.1f, 100.0f);
        uni.light.position = glm::vec4(g.box(6) + glm::vec3(0, 0, -3), 1);
        uni.light.ambient = g.colour(0.3f);
        uni.light.diffuse = g.colour();
        uni.light.specular = g.colour();
        uni.material.ka = g.colour();
        uni.material.kd = g.colour();
        uni.material.ks = g.colour();
        uni.material.shininess = k % 4 == 0 ? float(1 + g.rng() % 100) : g.uniform(1, 200); // the seed's range (f in 1..200)
        std::vector<glm::vec3> positions, normals;
        for (int i = 0; i < per_set; ++i) positions.push_back(g.box(1.5f)), normals.push_back(g.direction());
        glt::vertex_buffers vb(*c, positions, normals);
        const auto bind = [&](const glt::feedback_program& p, bool is_seed) {
            return [&, is_seed] {
                vb.attach();
                glt::set_ads_uniforms(*c, p, uni, is_seed);
            };
        };
        const std::vector<float> out_seed = seed.run(per_set, 3, bind(seed, true));
        const std::vector<float> out_twin = twin.run(per_set, 3, bind(twin, false));
        const std::array lights{uni.light};
        for (int i = 0; i < per_set; ++i) {
            ++cases;
            const glm::vec3 cpu = phong::shade_vertex<F>(positions[std::size_t(i)], normals[std::size_t(i)], uni.model_view,
                                                         uni.normal_matrix, uni.material, lights);
            // The model at the eye coordinates the CPU computes (float, as the shaders do); the
            // shaders' own rounding of ModelView * p and NormalMatrix * n (a few u of Q and n) is
            // covered by doubling the bound.
            scene s;
            s.position = glm::vec3(uni.model_view * glm::vec4(positions[std::size_t(i)], 1));
            s.normal = uni.normal_matrix * normals[std::size_t(i)];
            s.material = uni.material;
            s.lights = {uni.light};
            const reference r = evaluate<F>(s, factor, measured.pow_per_y_u * 1.0001, measured.flushes_subnormals);
            for (int ch = 0; ch < 3; ++ch) {
                const double a = out_seed[std::size_t(i) * 3 + std::size_t(ch)], b = out_twin[std::size_t(i) * 3 + std::size_t(ch)];
                if (!std::isfinite(a) || !std::isfinite(b)) {
                    ++non_finite;
                    continue;
                }
                const double I = double(r.color[std::size_t(ch)]), scale = std::max(std::fabs(I), 1e-30);
                const double allowed = 2 * r.widened[std::size_t(ch)] * std::fabs(I) + r.allowance;
                worst_twin = std::max(worst_twin, std::fabs(b - I) / scale);
                worst_seed = std::max(worst_seed, std::fabs(a - I) / scale);
                worst_seed_twin = std::max(worst_seed_twin, std::fabs(a - b) / scale);
                worst_cpu_twin = std::max(worst_cpu_twin, std::fabs(double(cpu[ch]) - b) / scale);
                if (!(std::fabs(b - I) <= allowed)) ++failures_twin;
                if (!(std::fabs(a - I) <= allowed)) ++failures_seed;
            }
        }
    }
    MESSAGE("seed 003's phong.vert and the twin, " << cases << " vertices in " << sets
                                                   << " uniform sets: worst relative error against the model: twin " << worst_twin
                                                   << ", seed " << worst_seed << "; seed against twin " << worst_seed_twin
                                                   << "; twin against phong::shade_vertex " << worst_cpu_twin << "; outside the bound: twin "
                                                   << failures_twin << ", seed " << failures_seed);
    CHECK(cases == sets * per_set);
    CHECK(non_finite == 0);
    CHECK(failures_twin == 0);
    CHECK(failures_seed == 0);
}

TEST_CASE("phong::glsl::defines(F) selects the same model as the preset's define; source() reads phong.glsl")
{
    const std::string text = phong::glsl::source();
    CHECK(text.find("phong_shade(") != std::string::npos);
    CHECK(text.rfind("#version", 0) != 0); // no #version line: the including program's comes first
    CHECK(text.find("\n#version") == std::string::npos);
    CHECK_THROWS_AS(phong::glsl::source("/nonexistent"), std::runtime_error);
    CHECK_THROWS_AS(phong::glsl::defines(phong::presets::with_mode(phong::presets::glsl_ads, phong::evaluation::stable)),
                    std::invalid_argument);
    const auto c = open(glt::api::gl33_core);
    if (!c) return;
    // A feature set no preset has (spot cones, windowed falloff, emission, two-sided by flag, any
    // lights): the same colours bit for bit from defines(F) and from the same fields written by hand,
    // and each preset's defines(F) against its preset define.
    generator g(77);
    std::vector<scene> scenes;
    for (int i = 0; i < 512; ++i) scenes.push_back(random_scene<phong::presets::classic_phong>(g));
    const auto same = [&](const std::string& a, const std::string& b) {
        const std::vector<float> x = run_twin(*c, a, scenes), y = run_twin(*c, b, scenes);
        return x == y;
    };
    const std::string max = "#define PHONG_MAX_LIGHTS " + std::to_string(max_lights) + "\n";
    CHECK(same(phong::glsl::defines(phong::presets::classic_phong, max_lights), "#define PHONG_PRESET_CLASSIC_PHONG\n" + max));
    CHECK(same(phong::glsl::defines(phong::presets::blinn_phong_per_light_ambient, max_lights),
               "#define PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT\n" + max));
    CHECK(same(phong::glsl::defines(phong::presets::raytracer_phong, max_lights), "#define PHONG_PRESET_RAYTRACER_PHONG\n" + max));
    CHECK(same(phong::glsl::defines(phong::presets::glsl_ads, max_lights), "#define PHONG_PRESET_GLSL_ADS\n" + max));
    CHECK(same(phong::glsl::defines(phong::presets::diffuse_only, max_lights), "#define PHONG_PRESET_DIFFUSE_ONLY\n" + max));
    CHECK(same(phong::glsl::defines(phong::features{}, max_lights), max));
    CHECK_FALSE(same(phong::glsl::defines(phong::presets::glsl_ads, max_lights), "#define PHONG_PRESET_DIFFUSE_ONLY\n" + max));
}

namespace {
/// The recipe's fragment shader (tests/glsl/recipe.frag = docs/glsl.md's block, checked by
/// .ci/steps/55-glsl.sh) on one pixel: a point at the centre of the 1x1 framebuffer, its eye-space
/// position and normal from uniforms; the pixel (RGBA8) against phong::shade<classic_phong>.
int recipe_failures(const glt::context& c, int scenes, double& worst)
{
    const glt::functions& gl = c.gl();
    const std::string version = glt::version_line(c.which());
    const std::string vertex = version + R"(
uniform vec3 q;
uniform vec3 n;
out vec3 ec_position;
out vec3 ec_normal;
void main() { ec_position = q; ec_normal = n; gl_Position = vec4(0.0, 0.0, 0.0, 1.0); gl_PointSize = 1.0; }
)";
    const std::string fragment = phong::glsl::shader(version, "#define PHONG_PRESET_CLASSIC_PHONG\n", phong::glsl::source(),
                                                     glt::seed003_source(PHONG_RECIPE_FRAG));
    glt::feedback_program p(c, vertex, nullptr, fragment);
    constexpr features F = phong::presets::classic_phong;
    generator g(4242);
    int failures = 0;
    for (int k = 0; k < scenes; ++k) {
        scene s = random_scene<F>(g);
        // Colours within [0, 1] (the pixel is 8-bit): small coefficients.
        s.material.ka *= 0.2f, s.material.kd *= 0.2f, s.material.ks *= 0.2f, s.environment.ambient *= 0.5f;
        gl.glUseProgram(p.id());
        const auto v3 = [&](const std::string& name, const glm::vec3& v) { gl.glUniform3fv(p.uniform(name.c_str()), 1, &v.x); };
        const auto f1 = [&](const std::string& name, float v) { gl.glUniform1f(p.uniform(name.c_str()), v); };
        v3("q", s.position);
        v3("n", s.normal);
        v3("material.ka", s.material.ka), v3("material.kd", s.material.kd), v3("material.ks", s.material.ks);
        v3("material.emission", s.material.emission);
        f1("material.shininess", s.material.shininess), f1("material.alpha", s.material.alpha);
        v3("environment.ambient", s.environment.ambient);
        gl.glUniform4fv(p.uniform("environment.eye"), 1, &s.environment.eye.x);
        gl.glUniform1i(p.uniform("light_count"), int(s.lights.size()));
        for (std::size_t i = 0; i < s.lights.size(); ++i) {
            const std::string L = "lights[" + std::to_string(i) + "].";
            const phong::light<float>& l = s.lights[i];
            gl.glUniform4fv(p.uniform((L + "position").c_str()), 1, &l.position.x);
            v3(L + "ambient", l.ambient), v3(L + "diffuse", l.diffuse), v3(L + "specular", l.specular);
            f1(L + "attenuation.constant", l.attenuation.constant), f1(L + "attenuation.linear", l.attenuation.linear);
            f1(L + "attenuation.quadratic", l.attenuation.quadratic);
        }
        GLuint vao = 0;
        gl.glGenVertexArrays(1, &vao);
        gl.glBindVertexArray(vao);
        gl.glViewport(0, 0, 1, 1);
        gl.glClearColor(0, 0, 0, 0);
        gl.glClear(GL_COLOR_BUFFER_BIT);
        gl.glDrawArrays(GL_POINTS, 0, 1);
        unsigned char pixel[4] = {0, 0, 0, 0};
        gl.glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        gl.glBindVertexArray(0);
        gl.glDeleteVertexArrays(1, &vao);
        const glm::vec4 cpu = cpu_shade<F>(s);
        for (int ch = 0; ch < 4; ++ch) {
            const double expected = std::clamp(double(cpu[ch]), 0.0, 1.0), got = pixel[ch] / 255.0;
            worst = std::max(worst, std::fabs(got - expected));
            if (std::fabs(got - expected) > 0.5 / 255 + 1e-4) ++failures;
        }
    }
    if (gl.glGetError() != GL_NO_ERROR) ++failures;
    return failures;
}
} // namespace

namespace {
/// The defines of tests/glsl/recipe_world.frag: its comment lines "//   #define ...".
std::string world_recipe_defines(const std::string& text)
{
    std::istringstream in(text);
    std::string line, defines;
    while (std::getline(in, line))
        if (line.rfind("//   #define ", 0) == 0) defines += line.substr(5) + "\n";
    return defines;
}

/// A 1x1 RGBA8 texture of colour c (each channel a multiple of 1/255) on texture unit `unit`.
GLuint texel_texture(const glt::functions& gl, int unit, const unsigned char c[4])
{
    GLuint id = 0;
    gl.glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    gl.glGenTextures(1, &id);
    gl.glBindTexture(GL_TEXTURE_2D, id);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, c);
    gl.glActiveTexture(GL_TEXTURE0);
    return id;
}

/// tests/glsl/recipe_world.frag as written, one pixel per scene (a directional light, two point
/// lights and a spot with the linear edge; the first three with their spot uniforms never set), the
/// maps 1x1 textures: the pixel against phong::shade<linear_spot_tutorial> with those lights'
/// cones all zero (no cone) and the spot's. dark: pixels where the lights without a cone
/// contribute more than 4 levels to phong::shade but the pixel is below it by that much.
int world_recipe_failures(const glt::context& c, int scenes, double& worst, int& lit_by_coneless)
{
    const glt::functions& gl = c.gl();
    const std::string version = glt::version_line(c.which());
    const std::string vertex = version + R"(
uniform vec3 q;
uniform vec3 n;
out vec3 world_position;
out vec3 world_normal;
out vec2 uv;
void main() { world_position = q; world_normal = n; uv = vec2(0.5); gl_Position = vec4(0.0, 0.0, 0.0, 1.0); gl_PointSize = 1.0; }
)";
    const std::string body = glt::seed003_source(PHONG_RECIPE_WORLD_FRAG);
    const std::string fragment = phong::glsl::shader(version, world_recipe_defines(body), phong::glsl::source(), body);
    glt::feedback_program p(c, vertex, nullptr, fragment);
    constexpr features F = linear_spot_tutorial;
    generator g(4343);
    int failures = 0;
    for (int k = 0; k < scenes; ++k) {
        unsigned char diffuse[4], specular[4];
        for (int ch = 0; ch < 4; ++ch) diffuse[ch] = (unsigned char)(g.rng() % 256), specular[ch] = (unsigned char)(g.rng() % 256);
        const GLuint t0 = texel_texture(gl, 0, diffuse), t1 = texel_texture(gl, 1, specular);
        phong::material<float> m;
        m.ka = m.kd = glm::vec3(diffuse[0], diffuse[1], diffuse[2]) / 255.0f;
        m.ks = glm::vec3(specular[0], specular[1], specular[2]) / 255.0f;
        m.shininess = g.uniform(1, 64);
        const glm::vec3 q = g.box(2), n = g.direction();
        const glm::vec4 eye(g.box(1) + glm::vec3(0, 0, 4), 1);
        std::vector<phong::light<float>> lights(4);
        const phong::spot_cone<float> none{glm::vec3(0), 0, 0, 0, 0}; // uniforms left at 0
        for (int i = 0; i < 4; ++i) {
            phong::light<float>& L = lights[std::size_t(i)];
            L.position = i == 0 ? glm::vec4(g.direction(), 0) : glm::vec4(q + g.box(3), 1);
            L.ambient = g.colour(0.1f), L.diffuse = g.colour(0.4f), L.specular = g.colour(0.4f);
            L.attenuation = {1, 0.09f, 0.032f, std::numeric_limits<float>::infinity()};
            L.spot = none;
        }
        // The spot: toward the point, its edges at 10-20 and 20-30 degrees.
        const glm::vec3 axis = glm::normalize(glm::normalize(q - glm::vec3(lights[3].position)) + g.box(0.3f));
        const float inner = g.uniform(10, 20);
        lights[3].spot = phong::spot_cone<float>::smooth(axis, inner, inner + g.uniform(2, 10));
        gl.glUseProgram(p.id());
        const auto v3 = [&](const std::string& name, const glm::vec3& v) { gl.glUniform3fv(p.uniform(name.c_str()), 1, &v.x); };
        const auto f1 = [&](const std::string& name, float v) { gl.glUniform1f(p.uniform(name.c_str()), v); };
        v3("q", q), v3("n", n);
        gl.glUniform1i(p.uniform("diffuse_map"), 0);
        gl.glUniform1i(p.uniform("specular_map"), 1);
        f1("shininess", m.shininess);
        gl.glUniform4fv(p.uniform("environment.eye"), 1, &eye.x);
        gl.glUniform1i(p.uniform("light_count"), 4);
        for (int i = 0; i < 4; ++i) {
            const std::string L = "lights[" + std::to_string(i) + "].";
            const phong::light<float>& l = lights[std::size_t(i)];
            gl.glUniform4fv(p.uniform((L + "position").c_str()), 1, &l.position.x);
            v3(L + "ambient", l.ambient), v3(L + "diffuse", l.diffuse), v3(L + "specular", l.specular);
            f1(L + "attenuation.constant", l.attenuation.constant), f1(L + "attenuation.linear", l.attenuation.linear);
            f1(L + "attenuation.quadratic", l.attenuation.quadratic);
            if (i == 3) { // only the spot's cone is set: the others' spot uniforms keep their default, 0
                v3(L + "spot.direction", l.spot.direction);
                f1(L + "spot.cos_inner", l.spot.cos_inner), f1(L + "spot.cos_outer", l.spot.cos_outer);
            }
        }
        GLuint vao = 0;
        gl.glGenVertexArrays(1, &vao);
        gl.glBindVertexArray(vao);
        gl.glViewport(0, 0, 1, 1);
        gl.glClearColor(0, 0, 0, 0);
        gl.glClear(GL_COLOR_BUFFER_BIT);
        gl.glDrawArrays(GL_POINTS, 0, 1);
        unsigned char pixel[4] = {0, 0, 0, 0};
        gl.glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        gl.glBindVertexArray(0);
        gl.glDeleteVertexArrays(1, &vao);
        gl.glDeleteTextures(1, &t0), gl.glDeleteTextures(1, &t1);
        phong::environment<float> env;
        env.ambient = glm::vec3(0);
        env.eye = eye;
        const glm::vec3 cpu = phong::shade<F>(q, n, m, std::span<const phong::light<float>>(lights), env);
        const glm::vec3 spot_only = phong::shade<F>(q, n, m, std::span<const phong::light<float>>(lights).subspan(3), env);
        for (int ch = 0; ch < 3; ++ch) {
            const double expected = std::clamp(double(cpu[ch]), 0.0, 1.0), got = pixel[ch] / 255.0;
            worst = std::max(worst, std::fabs(got - expected));
            if (std::fabs(got - expected) > 0.5 / 255 + 1e-4) ++failures;
            if (std::clamp(double(cpu[ch]), 0.0, 1.0) - std::clamp(double(spot_only[ch]), 0.0, 1.0) > 4 / 255.0) ++lit_by_coneless;
        }
    }
    if (gl.glGetError() != GL_NO_ERROR) ++failures;
    return failures;
}
} // namespace

TEST_CASE("docs/glsl.md's world-space recipe: mixed lights, texture maps, spot uniforms left at 0 (no cone), against phong::shade (330 core, 300 es)")
{
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30}) {
        const auto c = open(a);
        if (!c) return;
        double worst = 0;
        int lit = 0;
        const int failures = world_recipe_failures(*c, 64, worst, lit);
        MESSAGE(glt::api_name(a) << ": recipe_world.frag, 64 scenes, worst |pixel - phong::shade| " << worst * 255
                                 << " / 255; channels where the lights without a cone add more than 4 levels: " << lit);
        CHECK(failures == 0);
        CHECK(lit > 64); // the cone-less lights (spot uniforms at 0) light the point, not only the spot
    }
}

TEST_CASE("docs/glsl.md's recipe: the fragment shader as written, one pixel per scene, against phong::shade (330 core, 300 es)")
{
    for (glt::api a : {glt::api::gl33_core, glt::api::gles30}) {
        const auto c = open(a);
        if (!c) return;
        double worst = 0;
        const int failures = recipe_failures(*c, 64, worst);
        MESSAGE(glt::api_name(a) << ": recipe.frag, 64 scenes, worst |pixel - phong::shade| " << worst * 255 << " / 255");
        CHECK(failures == 0);
    }
}
