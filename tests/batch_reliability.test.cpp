// batch.hpp, issue 15 items 2 and 4: shade_batch is defined (UBSan-clean) for every parameter
// validate accepts, huge shininess and spot exponents included; and its aliasing rule (an output
// overlapping an input is a debug-build precondition failure, except exact in-place shading).
// The UBSan half runs under the asan preset (clang++, -fsanitize=undefined, baseline ISA: double
// lanes there have no vector float-to-integer conversion, the case xsimd's exp got wrong).
#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace phong;

namespace {

template <class T> using vec3 = glm::vec<3, T>;

/// Two points on the plane z = -3 with n = (0, 0, 1), seen from the origin (perspective):
///   point 0 at (0, 0, -3): v = (0, 0, 1); a light straight above it (directional (0, 0, 1), or
///     positional at (0, 0, 5) with the spot axis (0, 0, -1)) gives l = r = v exactly: n.l = 1,
///     r.v = 1, spot cosine 1, so every power is 1^m = 1;
///   point 1 at (4, 0, -3): v = (-4, 0, 3) / 5, r.v = 3/5 and (positional light) spot cosine
///     8 / sqrt(80) < 1, so any power with exponent >= 1e30 is 0 (0.6^1e30, underflow).
/// Strengths and coefficients are powers of two: the expected colours below are exact sums.
template <class T> struct two_points {
    std::vector<T> px{T(0), T(4)}, py{T(0), T(0)}, pz{T(-3), T(-3)};
    std::vector<T> nx{T(0), T(0)}, ny{T(0), T(0)}, nz{T(1), T(1)};
    std::vector<T> r = std::vector<T>(2, T(-1)), g = std::vector<T>(2, T(-1)), b = std::vector<T>(2, T(-1));
    material<T> mat{vec3<T>(T(0.25)), vec3<T>(T(0.5)), vec3<T>(T(0.125)), vec3<T>(T(0)), T(1), T(1)};
    light<T> L{};
    two_points(T shininess, bool positional_spot, T spot_exponent)
    {
        mat.shininess = shininess;
        L.ambient = vec3<T>(T(1));
        L.diffuse = vec3<T>(T(1));
        L.specular = vec3<T>(T(1));
        if (positional_spot) {
            L.position = {T(0), T(0), T(5), T(1)};
            L.spot.direction = {T(0), T(0), T(-1)};
            L.spot.exponent = spot_exponent;
            L.spot.cos_cutoff = T(0); // 90 degrees: point 1 is inside the cutoff, only the power decides
        } else {
            L.position = {T(0), T(0), T(1), T(0)};
        }
    }
    template <features F> void shade()
    {
        const light<T> lights[1] = {L};
        shade_batch<F>(soa3<T>{px, py, pz}, soa3<T>{nx, ny, nz}, mat, std::span<const light<T>>(lights),
                       soa_rgba<T>{r, g, b, {}});
    }
};

// ka La_i + kd Ld_i (n.l = 1) + ks Ls_i (power 1) = 0.25 + 0.5 + 0.125 at point 0.
template <class T> constexpr T lit_all = T(0.875);

template <features F, class T> void huge_shininess(T m)
{
    CAPTURE(m);
    two_points<T> p(m, false, T(0));
    REQUIRE(static_cast<bool>(validate(p.mat)));
    p.template shade<F>();
    CHECK(p.r[0] == lit_all<T>);
    // Point 1: n.l = 1 (directional light along n), the specular power 0.6^m = 0: ka + kd.
    CHECK(p.r[1] == T(0.75));
    CHECK(p.g[1] == p.r[1]);
    CHECK(p.b[1] == p.r[1]);
}

template <features F, class T> void huge_spot_exponent(T e)
{
    CAPTURE(e);
    two_points<T> p(T(8), true, e);
    REQUIRE(static_cast<bool>(validate(p.L)));
    p.template shade<F>();
    CHECK(p.r[0] == lit_all<T>);
    // Point 1: the spot factor (8 / sqrt(80))^e = 0 scales every term of the light (ambient
    // included: attenuate_ambient), and there is no scene ambient term.
    CHECK(p.r[1] == T(0));
    CHECK(p.b[1] == T(0));
}

constexpr features phong_stable{.scene_ambient = false, .light_ambient = true, .lights = light_kind::any,
                                .mode = evaluation::stable};
constexpr features phong_exact{.scene_ambient = false, .light_ambient = true, .lights = light_kind::any,
                               .mode = evaluation::exact};
constexpr features blinn_stable{.scene_ambient = false, .light_ambient = true, .specular = specular_model::blinn,
                                .lights = light_kind::any, .mode = evaluation::stable};
constexpr features blinn_exact{.scene_ambient = false, .light_ambient = true, .specular = specular_model::blinn,
                               .lights = light_kind::any, .mode = evaluation::exact};
constexpr features spot_stable{.scene_ambient = false, .light_ambient = true, .lights = light_kind::positional,
                               .spot = spot_model::opengl, .mode = evaluation::stable};
constexpr features spot_exact{.scene_ambient = false, .light_ambient = true, .lights = light_kind::positional,
                              .spot = spot_model::opengl, .mode = evaluation::exact};

} // namespace

// Issue 15 item 2. Before the clamp in phong::detail::math_traits<xsimd::batch>::exp, the double cases reported
// "runtime error: -6.7e+28 is outside the range of representable values of type 'long'" in
// xsimd's exp (asan preset).
TEST_CASE("shade_batch: shininess 1e30 (double) and 1e38 (float) in the stable mode are UBSan-clean and exact")
{
    huge_shininess<phong_stable, double>(1e30);
    huge_shininess<phong_stable, double>(std::numeric_limits<double>::max());
    huge_shininess<phong_stable, float>(1e38f);
    huge_shininess<phong_stable, float>(std::numeric_limits<float>::max());
    huge_shininess<blinn_stable, double>(1e30);
    huge_shininess<blinn_stable, float>(1e38f);
    huge_shininess<phong_exact, double>(1e30); // exact mode: pow(r.v, m)
    huge_shininess<phong_exact, float>(1e38f);
}

// Float lanes take m as min(m, 2^100) (exact::lane_shininess::bounded), so that m log2 x stays finite
// without a clamp: the same powers, 1 at c = 1 and 0 below, on both sides of the bound.
TEST_CASE("shade_batch: exact float shininess up to the largest float gives the powers 1 and 0")
{
    for (const float m : {0x1p31f, 0x1p100f, 0x1p101f, 1e38f, std::numeric_limits<float>::max()}) {
        huge_shininess<phong_exact, float>(m);
        huge_shininess<blinn_exact, float>(m);
    }
    huge_shininess<blinn_exact, double>(std::numeric_limits<double>::max());
}

// pow(c, 0) = 1 (shade<F>'s cosine_power): with shininess 0 the specular term is ks Ls wherever the
// pair is lit and the point sees the viewer, whatever the cosine, and nothing at a point without a
// view vector (at the eye). Materials with m = 0 and m = 8 alternate point by point, so that a step
// of lanes holds both (the batch decides per lane, once per step, where the power is taken).
// Plane points with n = (0, 0, 1) and the directional light l = n (n.l = 1 exactly):
//   (0, 0, -3): v = l, r.v = n.h = 1;
//   (4, 0, -3): r.v = 3/5 (Blinn: n.h = (1 + 3/5) / |l + v|);
//   (0, 0, 3):  v = -n, r.v = -1 (Blinn: l = -v, no halfway vector, n.h taken as 0): power 0^m;
//   (0, 0, 0):  at the eye, no view vector.
// ka La + kd Ld = 0.75 everywhere, ks Ls = 0.125: the colours are exact sums except c^8 at (4, 0, -3).
template <features F, class T> void zero_shininess()
{
    const T px0[4] = {T(0), T(4), T(0), T(0)}, pz0[4] = {T(-3), T(-3), T(3), T(0)};
    constexpr std::size_t n = 40; // two AVX-512 float steps and a tail
    std::vector<T> px(n), py(n, T(0)), pz(n), nx(n, T(0)), ny(n, T(0)), nz(n, T(1)), r(n, T(-1)), g(n, T(-1)), b(n, T(-1));
    std::vector<material<T>> mats(n, material<T>{vec3<T>(T(0.25)), vec3<T>(T(0.5)), vec3<T>(T(0.125)), vec3<T>(T(0)), T(0), T(1)});
    for (std::size_t i = 0; i < n; ++i) {
        px[i] = px0[(i / 2) % 4], pz[i] = pz0[(i / 2) % 4];
        if (i % 2) mats[i].shininess = T(8);
    }
    light<T> L{};
    L.position = {T(0), T(0), T(1), T(0)};
    L.ambient = L.diffuse = L.specular = vec3<T>(T(1));
    const light<T> lights[1] = {L};
    shade_batch<F>(soa3<T>{px, py, pz}, soa3<T>{nx, ny, nz}, std::span<const material<T>>(mats), std::span<const light<T>>(lights),
                   soa_rgba<T>{r, g, b, {}});
    for (std::size_t i = 0; i < n; ++i) {
        CAPTURE(i);
        const std::size_t where = (i / 2) % 4;
        const bool zero = i % 2 == 0;
        T expected = T(0.75);
        if (where == 0) expected = T(0.875);
        if (zero && where != 3) expected = T(0.875);
        if (!zero && where == 1) { // 0.125 c^8, c from the definitions
            const double c = F.specular == specular_model::blinn ? 1.6 / std::sqrt(0.8 * 0.8 + 1.6 * 1.6) : 0.6;
            CHECK(double(r[i]) == doctest::Approx(0.75 + 0.125 * std::pow(c, 8.0)).epsilon(1e-5));
        } else {
            CHECK(r[i] == expected);
        }
        CHECK(g[i] == r[i]);
        CHECK(b[i] == r[i]);
    }
    // One material for every point (the folded path): m = 0 throughout.
    shade_batch<F>(soa3<T>{px, py, pz}, soa3<T>{nx, ny, nz}, mats[0], std::span<const light<T>>(lights), soa_rgba<T>{r, g, b, {}});
    for (std::size_t i = 0; i < n; ++i) {
        CAPTURE(i);
        CHECK(r[i] == ((i / 2) % 4 == 3 ? T(0.75) : T(0.875)));
    }
}

TEST_CASE_TEMPLATE("shade_batch: shininess 0 turns the specular term on at every lit cosine, and off without a view vector", T, float, double)
{
    zero_shininess<phong_exact, T>();
    zero_shininess<blinn_exact, T>();
    zero_shininess<phong_stable, T>();
    zero_shininess<blinn_stable, T>();
}

TEST_CASE("shade_batch: spot exponents 1e300 (double) and 3e38 (float) are UBSan-clean and exact")
{
    huge_spot_exponent<spot_stable, double>(1e300);
    huge_spot_exponent<spot_exact, double>(1e300);
    huge_spot_exponent<spot_stable, float>(3e38f);
    huge_spot_exponent<spot_exact, float>(3e38f);
}

#if PHONG_HAS_XSIMD
TEST_CASE_TEMPLATE("phong::detail::math_traits<simd_batch>: exp, pow and pow_one_minus across the whole range", T, float, double)
{
    using V = simd_batch<T>;
    using M = phong::detail::math_traits<V>;
    constexpr T inf = std::numeric_limits<T>::infinity(), big = std::numeric_limits<T>::max();
    const auto lane0 = [](const V& v) {
        alignas(64) T out[batch_width<T>];
        v.store_aligned(out);
        return out[0];
    };
    // exp: 0 far below the underflow threshold, inf far above overflow, NaN kept.
    for (T x : {-inf, -big, T(-1e30), T(-1e4)}) {
        CAPTURE(x);
        CHECK(lane0(M::exp(V(x))) == T(0));
        CHECK(lane0(M::exp(V(-x))) == inf);
    }
    for (T x : {T(-50), T(-1), T(0), T(1), T(50)}) { // unchanged inside the range
        CAPTURE(x);
        CHECK(std::abs(lane0(M::exp(V(x))) - std::exp(x)) <= 4 * std::numeric_limits<T>::epsilon() * std::exp(x));
    }
    CHECK(std::isnan(lane0(M::exp(V(std::numeric_limits<T>::quiet_NaN())))));
    // pow(x, y) with y up to the largest T: 0 for x < 1, 1 for x = 1; pow_one_minus likewise.
    for (T y : {T(1e30), big}) {
        CAPTURE(y);
        CHECK(lane0(M::pow(V(T(0.5)), V(y))) == T(0));
        CHECK(lane0(M::pow(V(T(1)), V(y))) == T(1));
        CHECK(lane0(M::pow(V(T(0)), V(y))) == T(0));
        CHECK(lane0(M::pow_one_minus(V(T(0.5)), V(y))) == T(0));
        CHECK(lane0(M::pow_one_minus(V(T(0)), V(y))) == T(1));
    }
}
#endif

// ---------------------------------------------------------------------------------------------
// Issue 15 item 4: overlapping spans. The checks are preconditions in every build (issue 28: the
// O(1) memory-safety checks stay on under NDEBUG; the value checks are debug-only); a handler that
// records the message and returns lets the test go on (documented in detail/config.hpp).
// ---------------------------------------------------------------------------------------------

// The span-length and overlap checks run in every build (NDEBUG too: they keep memory safe).
namespace {

std::vector<std::string> reported;
void record(const char* message, const char*, int) { reported.emplace_back(message); }

struct recording_handler {
    precondition_handler previous;
    recording_handler() : previous(set_precondition_handler(&record)) { reported.clear(); }
    ~recording_handler() { set_precondition_handler(previous); }
    recording_handler(const recording_handler&) = delete;
    recording_handler& operator=(const recording_handler&) = delete;
};

bool overlap_reported()
{
    for (const std::string& m : reported)
        if (m.find("shade_batch: an output span overlaps ") == 0) return true;
    return false;
}

constexpr std::size_t points = 37; // two full steps of 16 lanes and a tail, or more steps of fewer

/// Points on a grid in front of the eye, one light; pure function of i.
template <class T> struct grid {
    std::vector<T> storage = std::vector<T>(7 * (points + 1));
    std::span<T> column(int c, std::size_t shift = 0) { return {storage.data() + c * (points + 1) + shift, points}; }
    grid()
    {
        for (std::size_t i = 0; i < points; ++i) {
            column(0)[i] = T(int(i % 7) - 3) / T(4);
            column(1)[i] = T(int(i % 5) - 2) / T(4);
            column(2)[i] = T(-4) - T(i % 3);
            column(3)[i] = T(0.25) * T(int(i % 3) - 1);
            column(4)[i] = T(0.125) * T(int(i % 4) - 2);
            column(5)[i] = T(1);
        }
    }
    soa3<T> positions() { return {column(0), column(1), column(2)}; }
    soa3<T> normals() { return {column(3), column(4), column(5)}; }
};

template <class T> const light<T> one_light[1] = {light<T>::with_strength({T(1), T(2), T(3), T(1)}, vec3<T>(T(1)))};
constexpr features plain{};

} // namespace

TEST_CASE_TEMPLATE("shade_batch: an output shifted by one element over an input is reported", T, float, double)
{
    recording_handler h;
    // r written over positions.x shifted by one: point i + 1's x is overwritten by point i's red
    // before the step that reads it (within a step only for the last lane; across steps always).
    grid<T> in;
    std::vector<T> g(points), b(points);
    shade_batch<plain>(in.positions(), in.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                       soa_rgba<T>{in.column(0, 1), g, b, {}});
    CHECK(overlap_reported());

    // Interleaved colours over the normals' storage.
    reported.clear();
    grid<T> in2;
    std::span<glm::vec<3, T>> colours(reinterpret_cast<glm::vec<3, T>*>(in2.column(3).data()), points / 3);
    soa3<T> pos{in2.column(0).first(points / 3), in2.column(1).first(points / 3), in2.column(2).first(points / 3)};
    soa3<T> nor{in2.column(3).first(points / 3), in2.column(4).first(points / 3), in2.column(5).first(points / 3)};
    shade_batch<plain>(pos, nor, material<T>{}, std::span<const light<T>>(one_light<T>), colours);
    CHECK(overlap_reported());

    // Two output channels on the same memory.
    reported.clear();
    grid<T> in3;
    std::vector<T> rg(points);
    shade_batch<plain>(in3.positions(), in3.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                       soa_rgba<T>{rg, rg, b, {}});
    CHECK(overlap_reported());

    // Per-point materials under the output.
    reported.clear();
    grid<T> in4;
    std::vector<material<T>> mats(points);
    std::span<T> over_materials(reinterpret_cast<T*>(mats.data()) + 1, points);
    shade_batch<plain>(in4.positions(), in4.normals(), std::span<const material<T>>(mats),
                       std::span<const light<T>>(one_light<T>), soa_rgba<T>{over_materials, g, b, {}});
    CHECK(overlap_reported());

    // The alpha channel counts only when F.alpha: here it overlaps the red channel.
    reported.clear();
    grid<T> in5;
    std::vector<T> ra(points + 3);
    constexpr features with_alpha{.alpha = true};
    shade_batch<with_alpha>(in5.positions(), in5.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                            soa_rgba<T>{std::span<T>(ra.data(), points), g, b, std::span<T>(ra.data() + 3, points)});
    CHECK(overlap_reported());
}

TEST_CASE_TEMPLATE("shade_batch: disjoint spans and exact in-place shading are not reported, and in place is correct",
                   T, float, double)
{
    recording_handler h;
    grid<T> in;
    std::vector<T> r(points), g(points), b(points), a(points);
    constexpr features with_alpha{.alpha = true};
    shade_batch<plain>(in.positions(), in.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                       soa_rgba<T>{r, g, b, a}); // a not written, not checked: F.alpha is false
    shade_batch<with_alpha>(in.positions(), in.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                            soa_rgba<T>{r, g, b, a});
    // Neighbouring columns of one array: adjacent, not overlapping.
    grid<T> adjacent;
    std::vector<T> rgb(3 * points);
    shade_batch<plain>(adjacent.positions(), adjacent.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                       soa_rgba<T>{std::span<T>(rgb.data(), points), std::span<T>(rgb.data() + points, points),
                                   std::span<T>(rgb.data() + 2 * points, points), {}});
    CHECK(reported.empty());

    // In place: r over positions.x, g over normals.z, b over positions.z. Same colours as r, g, b
    // above (computed out of place from the same inputs).
    grid<T> inplace;
    shade_batch<plain>(inplace.positions(), inplace.normals(), material<T>{}, std::span<const light<T>>(one_light<T>),
                       soa_rgba<T>{inplace.column(0), inplace.column(5), inplace.column(2), {}});
    CHECK(reported.empty());
    for (std::size_t i = 0; i < points; ++i) {
        CAPTURE(i);
        CHECK(inplace.column(0)[i] == r[i]);
        CHECK(inplace.column(5)[i] == g[i]);
        CHECK(inplace.column(2)[i] == b[i]);
    }
}

TEST_CASE("shade_batch: spans of different lengths are reported, naming the span, and nothing is written if the handler returns")
{
    recording_handler h;
    grid<float> in;
    std::vector<float> r(points, -1.0f), g(points, -1.0f), b(points, -1.0f);
    const soa3<float> short_y{in.column(0), in.column(1).first(points - 1), in.column(2)};
    shade_batch<plain>(short_y, in.normals(), material<float>{}, std::span<const light<float>>(one_light<float>),
                       soa_rgba<float>{r, g, b, {}});
    REQUIRE(reported.size() == 1);
    CHECK(reported[0] == std::string("shade_batch: .positions: x, y and z of different lengths"));
    for (std::size_t i = 0; i < points; ++i) CHECK(r[i] == -1.0f);

    // Each message names the span that is off.
    reported.clear();
    const soa3<float> short_normals{in.column(3).first(points - 1), in.column(4).first(points - 1), in.column(5).first(points - 1)};
    shade_batch<plain>(in.positions(), short_normals, material<float>{}, std::span<const light<float>>(one_light<float>),
                       soa_rgba<float>{r, g, b, {}});
    REQUIRE(reported.size() == 1);
    CHECK(reported[0] == std::string("shade_batch: .normals: not one normal per point"));
    reported.clear();
    shade_batch<plain>(in.positions(), in.normals(), material<float>{}, std::span<const light<float>>(one_light<float>),
                       soa_rgba<float>{r, std::span<float>(g).first(points - 1), b, {}});
    REQUIRE(reported.size() == 1);
    CHECK(reported[0] == std::string("shade_batch: the output is shorter than the points (N entries per channel)"));
    for (std::size_t i = 0; i < points; ++i) CHECK(r[i] == -1.0f);
}

#if !defined(NDEBUG) // the value checks: debug builds only
TEST_CASE("shade_batch: an invalid environment is reported with the field it names")
{
    recording_handler h;
    grid<float> in;
    std::vector<float> r(points), g(points), b(points);
    environment<float> env;
    env.ambient = glm::vec3(0.1f, -0.5f, 0.1f);
    shade_batch<plain>(in.positions(), in.normals(), material<float>{}, std::span<const light<float>>(one_light<float>),
                       soa_rgba<float>{r, g, b, {}}, env);
    REQUIRE(reported.size() == 1);
    CHECK(std::string(reported[0]).find("environment.ambient") != std::string::npos);
}

TEST_CASE("shade_batch: an invalid material or light is reported with its index in its span and the field")
{
    recording_handler h;
    grid<float> in;
    std::vector<float> r(points), g(points), b(points);
    std::vector<material<float>> per_point(points);
    per_point[5].kd = glm::vec3(0.5f, -1.0f, 0.5f);
    std::vector<light<float>> lights(3, one_light<float>[0]);
    lights[1].position.w = 0.5f;
    shade_batch<plain>(in.positions(), in.normals(), std::span<const material<float>>(per_point), std::span<const light<float>>(lights),
                       soa_rgba<float>{r, g, b, {}});
    REQUIRE(reported.size() == 2);
    CHECK(reported[0].rfind("shade_batch: materials[5]: material.kd: ", 0) == 0);
    CHECK(reported[1].rfind("shade_batch: lights[1]: light.position.w: ", 0) == 0);

    reported.clear();
    std::vector<material<float>> table(3);
    table[2].shininess = -2.0f;
    const std::vector<std::uint32_t> ids(points, 0);
    const std::vector<glm::vec3> p(points, glm::vec3(0.0f, 0.0f, -2.0f)), n(points, glm::vec3(0.0f, 0.0f, 1.0f));
    std::vector<glm::vec3> out(points);
    shade_batch<plain>(aos_points<float>{.positions = p, .normals = n}, material_table<float>{.materials = table, .ids = ids},
                       std::span<const light<float>>(one_light<float>), out);
    REQUIRE(reported.size() == 1);
    CHECK(reported[0].rfind("shade_batch: material_table.materials[2]: material.shininess: ", 0) == 0);
}

TEST_CASE("shade_batch: a material id past the table is reported; if the handler returns, it takes the last entry")
{
    recording_handler h;
    // Diffuse only, a white directional light along the unit normal: each colour is its kd.
    constexpr features F{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::directional};
    const std::vector<light<float>> lights{light<float>::with_strength({0.0f, 0.0f, 1.0f, 0.0f}, glm::vec3(1.0f))};
    std::vector<material<float>> table(2);
    table[0].kd = glm::vec3(0.25f);
    table[1].kd = glm::vec3(0.5f);
    const std::size_t count = batch_width<float> + 1;
    const std::vector<glm::vec3> p(count, glm::vec3(0.0f, 0.0f, -2.0f)), n(count, glm::vec3(0.0f, 0.0f, 1.0f));
    std::vector<std::uint32_t> ids(count, 0);
    ids[1] = 7; // past the table
    std::vector<glm::vec3> out(count);
    shade_batch<F>(aos_points<float>{.positions = p, .normals = n}, material_table<float>{.materials = table, .ids = ids}, lights, out);
    REQUIRE(reported.size() == 1);
    CHECK(reported[0] == std::string("shade_batch: material_table.ids[1]: a material id past the table"));
    CHECK(out[0] == glm::vec3(0.25f));
    CHECK(out[1] == glm::vec3(0.5f)); // clamped to the last entry
    CHECK(out[count - 1] == glm::vec3(0.25f));
}
#endif
