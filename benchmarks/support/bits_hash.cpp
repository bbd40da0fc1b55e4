// The exact bits of phong's outputs, hashed: benchmarks/bits_hash.sh builds this program and prints
// one FNV-1a 64-bit hash per (entry point, feature set, mode, type), so that a change meant to keep
// the results (a refactoring, a new include layout) can be checked bit for bit against the
// hashes of the code before it.
//
// Entry points: shade<F> (a run-time span, a std::array unrolled, masked() and weighted() lists),
// shade_terms<F> (every term and alpha), shade_incident<F> (a span and masked(), the view given or
// fixed: presets that read a position take the view vector as given), shade_batch<F> (soa3 with one
// material and SoA output, soa3 with per-point materials and interleaved output, soa_points with
// masks and a material table, aos_points with one material and interleaved output, aos_points with
// per-point materials and SoA output).
// Feature sets: every preset of features.hpp, each Phong/Blinn preset also with the other specular
// model, and five more that reach the fields no preset sets (any light kind, both attenuation and
// both spot models, two-sided by view and by flag, fixed_direction, emission, unit_inputs,
// directional lights, stable_twofold_above). Modes: exact, stable (float: the wider route),
// stable with twofold precision, fast. Types: float and double.
// Scene: a fixed pseudo-random set of points (positions, normals of any length, views; a few
// degenerate ones: zero normal, a point at a light, at the eye, NaN and inf inputs), six lights of
// every kind (positional, directional, attenuated, both spot cones, per-light ambient) and a few
// materials (shininess 0 to 1e4).
//
// Build: BITS_HASH_MODE selects the mode compiled into this executable (0 exact, 1 stable,
// 2 stable twofold, 3 fast), so the script compiles the modes in parallel.
#include <phong/batch.hpp>
#include <phong/sum/incident.hpp>
#include <phong/phong.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <span>
#include <vector>

#ifndef BITS_HASH_MODE
#  define BITS_HASH_MODE 0
#endif
// BITS_HASH_SETS: a bit mask of the feature sets compiled (bit i: the i-th run_set in main), all by
// default; a subset builds faster, and its lines are those of the full run.
#ifndef BITS_HASH_SETS
#  define BITS_HASH_SETS 0xffffffffu
#endif

namespace {

using phong::features;
using phong::evaluation;
using phong::specular_model;
using phong::view_model;

constexpr std::size_t points_count = 3000;
constexpr std::size_t light_count = 6;

/// FNV-1a, 64 bits, over the bytes of every value hashed.
struct fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n)
    {
        const auto* c = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
    }
    template <class T> void value(T x) { bytes(&x, sizeof x); }
    template <int L, class T, glm::qualifier Q> void value(const glm::vec<L, T, Q>& v)
    {
        for (int k = 0; k < L; ++k) value(v[k]);
    }
};

/// splitmix64: a fixed, portable sequence.
struct rng {
    std::uint64_t s;
    std::uint64_t next()
    {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1p-53; }
};

template <class T> struct scene {
    using vec3 = glm::vec<3, T>;
    std::vector<vec3> position, normal, unit_normal, view, unit_view;
    std::vector<bool> front;
    std::vector<std::uint64_t> masks;
    std::vector<phong::light<T>> lights;
    std::vector<T> weights;
    std::vector<phong::material<T>> materials; // the table
    std::vector<std::uint32_t> ids;
    std::vector<phong::material<T>> per_point;
    phong::environment<T> env;
};

template <class T> scene<T> make_scene()
{
    using vec3 = glm::vec<3, T>;
    scene<T> sc;
    rng r{0x5eed5eedull};
    const auto rvec = [&](double lo, double hi) { return glm::dvec3(r.uniform(lo, hi), r.uniform(lo, hi), r.uniform(lo, hi)); };
    const auto unit = [&](glm::dvec3 v) { return vec3(v / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z)); };

    // lights: positional, directional, attenuated (polynomial and range), both spot cones, ambient
    phong::light<T> L;
    L.position = {T(2), T(3), T(4), T(1)};
    L.diffuse = {T(0.9), T(0.8), T(0.7)};
    L.specular = {T(1), T(1), T(0.9)};
    sc.lights.push_back(L);
    L = {};
    L.position = {T(-0.3), T(0.8), T(0.5), T(0)};
    L.diffuse = {T(0.4), T(0.5), T(0.6)};
    L.specular = {T(0.3), T(0.3), T(0.3)};
    L.ambient = {T(0.05), T(0.05), T(0.1)};
    sc.lights.push_back(L);
    L = {};
    L.position = {T(-3), T(1), T(2), T(1)};
    L.attenuation = {T(1), T(0.09), T(0.032), T(12)};
    L.ambient = {T(0.1), T(0.02), T(0.02)};
    sc.lights.push_back(L);
    L = {};
    L.position = {T(0), T(5), T(0.5), T(1)};
    L.spot = phong::spot_cone<T>::opengl(vec3(T(0.1), T(-1), T(0.05)), T(8), T(50));
    L.attenuation = {T(0.5), T(0.1), T(0.01), T(30)};
    sc.lights.push_back(L);
    L = {};
    L.position = {T(1), T(-4), T(3), T(1)};
    L.spot = phong::spot_cone<T>::smooth(vec3(T(-0.2), T(1), T(-0.4)), T(20), T(45));
    L.specular = {T(2), T(2), T(2)};
    sc.lights.push_back(L);
    L = {};
    L.position = {T(0.5), T(0.5), T(1.5), T(1)}; // close to the points
    L.ambient = {T(0.2), T(0.2), T(0.2)};
    L.attenuation = {T(0), T(0), T(1), T(4)};
    sc.lights.push_back(L);
    sc.weights = {T(1), T(0.5), T(0), T(0.25), T(1), T(0.75)};

    const T shininess[] = {T(0), T(1), T(8), T(32), T(100.5), T(1e4)};
    for (int k = 0; k < 6; ++k) {
        phong::material<T> m;
        m.ka = vec3(rvec(0, 0.3));
        m.kd = vec3(rvec(0.2, 0.9));
        m.ks = vec3(rvec(0, 1));
        m.emission = vec3(rvec(0, 0.1));
        m.shininess = shininess[k];
        m.alpha = T(r.uniform(0, 1));
        sc.materials.push_back(m);
    }
    sc.env.ambient = {T(0.1), T(0.1), T(0.12)};
    sc.env.eye = {T(0.3), T(-0.2), T(6), T(1)};

    for (std::size_t i = 0; i < points_count; ++i) {
        glm::dvec3 p = rvec(-2, 2);
        p.z = r.uniform(-1, 1);
        glm::dvec3 n = rvec(-1, 1);
        n.z = std::abs(n.z) + 0.05;
        n *= r.uniform(0.2, 3); // any length
        glm::dvec3 v = glm::dvec3(sc.env.eye) - p + rvec(-0.5, 0.5);
        sc.position.push_back(vec3(p));
        sc.normal.push_back(vec3(n));
        sc.unit_normal.push_back(unit(n));
        sc.view.push_back(vec3(v * r.uniform(0.1, 4)));
        sc.unit_view.push_back(unit(v));
        sc.front.push_back(r.next() % 4 != 0);
        sc.masks.push_back(r.next());
        sc.ids.push_back(std::uint32_t(r.next() % sc.materials.size()));
        sc.per_point.push_back(sc.materials[r.next() % sc.materials.size()]);
    }
    // degenerate points (the unit copies stay unit: unit_inputs' precondition)
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    sc.normal[1] = vec3(T(0));
    sc.position[2] = vec3(sc.lights[0].position);
    sc.position[3] = vec3(sc.env.eye);
    sc.view[3] = vec3(T(0));
    sc.position[4] = vec3(nan, T(0), T(0));
    sc.normal[5] = vec3(T(0), inf, T(1));
    sc.view[6] = vec3(T(0), T(0), -inf);
    sc.position[7] = vec3(T(1e30), T(-1e30), T(1e25));
    sc.position[8] = vec3(T(1e-30), T(0), T(-1e-30));
    sc.normal[9] = -sc.normal[9]; // back-facing
    sc.view[10] = -vec3(sc.lights[0].position) + sc.position[10]; // l = -v for light 0
    return sc;
}

template <class T> const scene<T>& the_scene()
{
    static const scene<T> sc = make_scene<T>();
    return sc;
}

/// Feature sets: the presets, the Phong/Blinn swaps, and five that reach the other fields.
constexpr features swap_specular(features f)
{
    f.specular = f.specular == specular_model::phong ? specular_model::blinn : specular_model::phong;
    return f;
}
constexpr features all_terms = [] {
    features f{};
    f.light_ambient = true;
    f.specular = specular_model::blinn;
    f.attenuation = phong::attenuation_model::polynomial;
    f.spot = phong::spot_model::opengl;
    f.attenuate_ambient = false;
    f.two_sided = phong::facing::view;
    f.view = view_model::eye_point;
    f.emission = true;
    f.alpha = true;
    return f;
}();
constexpr features fixed_flag = [] {
    features f{};
    f.specular_gate = false;
    f.attenuation = phong::attenuation_model::windowed;
    f.spot = phong::spot_model::smooth;
    f.two_sided = phong::facing::flag;
    f.view = view_model::fixed_direction;
    f.alpha = true;
    return f;
}();
constexpr features unit_given = [] {
    features f = phong::presets::raytracer_phong;
    f.unit_inputs = true;
    return f;
}();
constexpr features directional_blinn = [] {
    features f{};
    f.scene_ambient = false;
    f.light_ambient = true;
    f.specular = specular_model::blinn;
    f.lights = phong::light_kind::directional;
    f.spot = phong::spot_model::smooth;
    return f;
}();
constexpr features hybrid = [] {
    features f = phong::presets::classic_phong;
    f.stable_twofold_above = 64;
    f.specular = specular_model::blinn;
    return f;
}();

constexpr features in_mode(features f)
{
#if BITS_HASH_MODE == 0
    f.mode = evaluation::exact;
#elif BITS_HASH_MODE == 1
    f.mode = evaluation::stable;
#elif BITS_HASH_MODE == 2
    f.mode = evaluation::stable;
    f.precision = phong::stable_precision::twofold;
#else
    f.mode = evaluation::fast;
#endif
    return f;
}
constexpr const char* mode_name = BITS_HASH_MODE == 0 ? "exact" : BITS_HASH_MODE == 1 ? "stable" : BITS_HASH_MODE == 2 ? "stable-twofold" : "fast";

/// shade_incident reads no position: F with the view given, unless fixed.
constexpr features incident_of(features f)
{
    if (f.view != view_model::fixed_direction) f.view = view_model::given;
    return f;
}

template <class T> const char* type_name() { return std::is_same_v<T, float> ? "float" : "double"; }

void print(const char* entry, const char* set, const char* type, const fnv& h)
{
    std::printf("%-28s %-30s %-15s %-6s %016llx\n", entry, set, mode_name, type, static_cast<unsigned long long>(h.h));
}

/// The point's normal and view as F takes them (unit_inputs: the unit copies).
template <features F, class T> glm::vec<3, T> normal_at(const scene<T>& sc, std::size_t i)
{
    return F.unit_inputs ? sc.unit_normal[i] : sc.normal[i];
}
template <features F, class T> glm::vec<3, T> view_at(const scene<T>& sc, std::size_t i)
{
    return F.unit_inputs ? sc.unit_view[i] : sc.view[i];
}
template <features F, class T> bool skip_point(const scene<T>& sc, std::size_t i)
{
    (void)sc;
    return F.unit_inputs && i < 11; // the degenerate points break unit_inputs' precondition
}

/// shade<F> with the lights passed as `lights_of(i)` returns them.
template <features F, class T, class Lights>
fnv hash_shade(const scene<T>& sc, Lights&& lights_of)
{
    fnv h;
    for (std::size_t i = 0; i < points_count; ++i) {
        if (skip_point<F>(sc, i)) continue;
        const phong::material<T>& m = sc.per_point[i];
        if constexpr (F.view == view_model::given)
            h.value(phong::shade<F>(sc.position[i], normal_at<F>(sc, i), view_at<F>(sc, i), m, lights_of(i), sc.env, sc.front[i]));
        else h.value(phong::shade<F>(sc.position[i], normal_at<F>(sc, i), m, lights_of(i), sc.env, sc.front[i]));
    }
    return h;
}

template <features F, class T> void run_shade(const char* set)
{
    const scene<T>& sc = the_scene<T>();
    std::array<phong::light<T>, light_count> arr{};
    for (std::size_t k = 0; k < light_count; ++k) arr[k] = sc.lights[k];
    const std::span<const phong::light<T>> span(sc.lights);
    print("shade/span", set, type_name<T>(), hash_shade<F>(sc, [&](std::size_t) { return span; }));
    print("shade/array", set, type_name<T>(), hash_shade<F>(sc, [&](std::size_t) -> const auto& { return arr; }));
    print("shade/masked", set, type_name<T>(), hash_shade<F>(sc, [&](std::size_t i) { return phong::masked(span, sc.masks[i]); }));
    print("shade/weighted", set, type_name<T>(),
          hash_shade<F>(sc, [&](std::size_t) { return phong::weighted(span, std::span<const T>(sc.weights)); }));

    fnv h;
    for (std::size_t i = 0; i < points_count; ++i) {
        if (skip_point<F>(sc, i)) continue;
        phong::shading_terms<phong::detail::arithmetic_t<F, T>> t;
        if constexpr (F.view == view_model::given)
            t = phong::shade_terms<F>(sc.position[i], normal_at<F>(sc, i), view_at<F>(sc, i), sc.per_point[i], span, sc.env, sc.front[i]);
        else t = phong::shade_terms<F>(sc.position[i], normal_at<F>(sc, i), sc.per_point[i], span, sc.env, sc.front[i]);
        h.value(t.emission);
        h.value(t.ambient);
        h.value(t.diffuse);
        h.value(t.specular);
        h.value(t.alpha);
    }
    print("shade_terms", set, type_name<T>(), h);
}

template <features F, class T> void run_incident(const char* set)
{
    constexpr features G = incident_of(F);
    const scene<T>& sc = the_scene<T>();
    const std::span<const phong::light<T>> span(sc.lights);
    phong::environment<T> env = sc.env;
    if constexpr (G.unit_inputs && G.view == view_model::fixed_direction) env.eye = glm::vec<4, T>(T(0), T(0.6), T(0.8), T(0));
    fnv plain, with_mask;
    std::array<phong::incident<T>, light_count> in{};
    for (std::size_t i = 0; i < points_count; ++i) {
        if (skip_point<F>(sc, i) || !std::isfinite(sc.position[i].x)) continue;
        for (std::size_t k = 0; k < light_count; ++k) { // l and d from the point, in double, rounded once
            const glm::dvec4 P(sc.lights[k].position);
            const glm::dvec3 d = glm::dvec3(P) - P.w * glm::dvec3(sc.position[i]);
            const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
            in[k].direction = len > 0 ? glm::vec<3, T>(d / len) : glm::vec<3, T>(T(0), T(0), T(1));
            in[k].distance = T(glm::length(glm::dvec3(P) - glm::dvec3(sc.position[i])));
        }
        const glm::vec<3, T> n = normal_at<F>(sc, i);
        glm::vec<3, T> v = view_at<F>(sc, i);
        if constexpr (!F.unit_inputs && F.view != view_model::given) v = glm::vec<3, T>(sc.env.eye) - sc.position[i];
        const phong::material<T>& m = sc.per_point[i];
        if constexpr (G.view == view_model::given) {
            plain.value(phong::shade_incident<G>(n, v, m, span, in, env, sc.front[i]));
            with_mask.value(phong::shade_incident<G>(n, v, m, phong::masked(span, sc.masks[i]), in, env, sc.front[i]));
        } else {
            plain.value(phong::shade_incident<G>(n, m, span, in, env, sc.front[i]));
            with_mask.value(phong::shade_incident<G>(n, m, phong::masked(span, sc.masks[i]), in, env, sc.front[i]));
        }
    }
    print("shade_incident/span", set, type_name<T>(), plain);
    print("shade_incident/masked", set, type_name<T>(), with_mask);
}

template <class T> struct soa_out {
    std::vector<T> r, g, b, a;
    soa_out() : r(points_count), g(points_count), b(points_count), a(points_count) {}
    phong::soa_rgba<T> rgba() { return {r, g, b, a}; }
    void hash(fnv& h, bool alpha) const
    {
        for (std::size_t i = 0; i < points_count; ++i) {
            h.value(r[i]);
            h.value(g[i]);
            h.value(b[i]);
            if (alpha) h.value(a[i]);
        }
    }
};

template <features F, class T> void run_batch(const char* set)
{
    if constexpr (F.unit_inputs) {
        (void)set; // the degenerate points would break the precondition: not run
    } else {
        const scene<T>& sc = the_scene<T>();
        const std::span<const phong::light<T>> lights(sc.lights);
        std::vector<T> px, py, pz, nx, ny, nz, vx, vy, vz;
        for (std::size_t i = 0; i < points_count; ++i) {
            px.push_back(sc.position[i].x), py.push_back(sc.position[i].y), pz.push_back(sc.position[i].z);
            nx.push_back(sc.normal[i].x), ny.push_back(sc.normal[i].y), nz.push_back(sc.normal[i].z);
            vx.push_back(sc.view[i].x), vy.push_back(sc.view[i].y), vz.push_back(sc.view[i].z);
        }
        const phong::soa3<T> P{px, py, pz}, N{nx, ny, nz}, V{vx, vy, vz};
        const std::unique_ptr<bool[]> front(new bool[points_count]);
        for (std::size_t i = 0; i < points_count; ++i) front[i] = sc.front[i];
        const std::span<const bool> ff(front.get(), points_count);
        const std::span<const phong::material<T>> per_point(sc.per_point);
        using C = phong::color<F, T>;
        const auto hash_colors = [](const std::vector<C>& c) {
            fnv h;
            for (const C& x : c) h.value(x);
            return h;
        };
        if constexpr (F.view != view_model::given) {
            soa_out<T> o;
            phong::shade_batch<F>(P, N, sc.materials[3], lights, o.rgba(), sc.env, ff);
            fnv h;
            o.hash(h, F.alpha);
            print("shade_batch/soa3-one-soa", set, type_name<T>(), h);
            std::vector<C> c(points_count);
            phong::shade_batch<F>(P, N, per_point, lights, std::span<C>(c), sc.env, ff);
            print("shade_batch/soa3-each-aos", set, type_name<T>(), hash_colors(c));
        }
        const std::span<const std::uint64_t> masks(sc.masks);
        const phong::soa_points<T> sp{P, N, F.view == view_model::given ? V : phong::soa3<T>{}, ff, masks};
        {
            soa_out<T> o;
            phong::shade_batch<F>(sp, phong::material_table<T>{sc.materials, sc.ids}, lights, o.rgba(), sc.env);
            fnv h;
            o.hash(h, F.alpha);
            print("shade_batch/soa-masks-table", set, type_name<T>(), h);
        }
        const std::span<const glm::vec<3, T>> views = F.view == view_model::given ? std::span<const glm::vec<3, T>>(sc.view)
                                                                                   : std::span<const glm::vec<3, T>>{};
        const phong::aos_points<T> ap{sc.position, sc.normal, views, ff, {}};
        {
            std::vector<C> c(points_count);
            phong::shade_batch<F>(ap, sc.materials[2], lights, std::span<C>(c), sc.env);
            print("shade_batch/aos-one-aos", set, type_name<T>(), hash_colors(c));
        }
        {
            soa_out<T> o;
            phong::shade_batch<F>(ap, per_point, lights, o.rgba(), sc.env);
            fnv h;
            o.hash(h, F.alpha);
            print("shade_batch/aos-each-soa", set, type_name<T>(), h);
        }
    }
}

template <features F0, unsigned Index> void run_set(const char* set)
{
    if constexpr (((BITS_HASH_SETS) >> Index & 1u) != 0) {
        constexpr features F = in_mode(F0);
        run_shade<F, float>(set);
        run_shade<F, double>(set);
        run_incident<F, float>(set);
        run_incident<F, double>(set);
        run_batch<F, float>(set);
        run_batch<F, double>(set);
    } else {
        (void)set;
    }
}

} // namespace

int main()
{
    namespace p = phong::presets;
    run_set<p::classic_phong, 0>("classic_phong");
    run_set<swap_specular(p::classic_phong), 1>("classic_phong+blinn");
    run_set<p::blinn_phong_per_light_ambient, 2>("blinn_phong_per_light_ambient");
    run_set<swap_specular(p::blinn_phong_per_light_ambient), 3>("blinn_per_light_ambient+phong");
    run_set<p::raytracer_phong, 4>("raytracer_phong");
    run_set<swap_specular(p::raytracer_phong), 5>("raytracer_phong+blinn");
    run_set<p::glsl_ads, 6>("glsl_ads");
    run_set<swap_specular(p::glsl_ads), 7>("glsl_ads+blinn");
    run_set<p::diffuse_only, 8>("diffuse_only");
    run_set<all_terms, 9>("all_terms");
    run_set<fixed_flag, 10>("fixed_flag");
    run_set<unit_given, 11>("raytracer_phong+unit_inputs");
    run_set<directional_blinn, 12>("directional_blinn");
    run_set<hybrid, 13>("classic_blinn+twofold_above");
    return 0;
}
