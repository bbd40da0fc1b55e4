// No subnormal number in ordinary scenes: shade_batch and shade<F>, every mode, float and double,
// neither make nor read one. On x86 cores in the default floating-point environment (MXCSR's
// flush-to-zero and denormals-are-zero off: Intel's cores take a microcode assist of about a
// hundred cycles for each subnormal operand or result), so a scene that makes them runs several
// times slower than with -ffast-math's start-up code (docs/batch.md). The check needs no Intel
// core: MXCSR's sticky flags record every event on any x86-64 core. DE (bit 1): an SSE/AVX
// instruction read a subnormal operand; UE (bit 4): a result underflowed (subnormal, or 0 from
// below the smallest normal). Both clear over a call means no assist could have happened in it.
//
// The scenes: the benchmark scenes (benchmarks/support/inputs.hpp: typical, the stiff highlight
// with m = 1e4 and the stiff grazing set, K = 1, 4, 16 lights; plain, directional and attenuated
// spot lights) and the demo renderer's scene (benchmarks/demo/raycast.hpp), through four feature
// sets (glsl_ads's Phong and Blinn, with attenuation and spots, classic_phong: two-sided, ungated,
// the eye as a point). Before the power floor (detail::ieee::power_floor_log2), every float
// scene here set both flags on every route but the scalar stable one; double's the highlight.
// x86-64 only (other targets have no MXCSR): skipped elsewhere.
#include "../benchmarks/support/inputs.hpp"
#include "raycast.hpp"

#include <phong/batch.hpp>
#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <span>
#include <string>
#include <vector>

#if defined(__x86_64__) || defined(_M_X64)
#  include <xmmintrin.h>
#  define PHONG_TEST_MXCSR 1
#else
#  define PHONG_TEST_MXCSR 0
#endif

namespace {

#if PHONG_TEST_MXCSR
constexpr unsigned mxcsr_flags = 0x3Fu;           // IE DE ZE OE UE PE
constexpr unsigned mxcsr_subnormal = 0x02u | 0x10u; // DE, UE
constexpr unsigned mxcsr_ftz_daz = 0x8000u | 0x0040u;

/// The default floating-point environment for the scope (FTZ and DAZ off, whatever the process
/// had), restored at its end.
struct default_environment {
    unsigned saved = _mm_getcsr();
    default_environment() { _mm_setcsr(saved & ~(mxcsr_ftz_daz | mxcsr_flags)); }
    ~default_environment() { _mm_setcsr(saved); }
};

/// Clears the sticky flags, runs f, and returns DE | UE as raised by f. The memory clobbers keep
/// the compiler from moving f's stores (every result is stored) across the MXCSR accesses.
template <class Fn> unsigned subnormal_flags(Fn&& f)
{
    asm volatile("" ::: "memory");
    _mm_setcsr(_mm_getcsr() & ~mxcsr_flags);
    asm volatile("" ::: "memory");
    f();
    asm volatile("" ::: "memory");
    const unsigned raised = _mm_getcsr() & mxcsr_subnormal;
    asm volatile("" ::: "memory");
    return raised;
}

// (one literal per case: g++ 12 -O3 reports a false -Warray-bounds in std::string's append of
// two literals here when the surrounding code is not force-inlined)
std::string describe(unsigned flags)
{
    const bool de = (flags & 0x02u) != 0, ue = (flags & 0x10u) != 0;
    if (de && ue) return "DE (a subnormal operand was read) UE (a result underflowed)";
    if (de) return "DE (a subnormal operand was read)";
    return ue ? "UE (a result underflowed)" : "none";
}

constexpr phong::features blinn_ads = [] {
    phong::features f = phong::presets::glsl_ads;
    f.specular = phong::specular_model::blinn;
    return f;
}();
constexpr phong::features spot_ads = [] {
    phong::features f = phong::presets::glsl_ads;
    f.attenuation = phong::attenuation_model::polynomial;
    f.spot = phong::spot_model::opengl;
    return f;
}();

std::string mode_name(phong::evaluation e)
{
    return e == phong::evaluation::exact ? "exact" : e == phong::evaluation::stable ? "stable" : "fast";
}

/// One benchmark scene through shade_batch (SoA in and out) and shade<F> at every point.
template <phong::features F0, phong::evaluation Mode, class T>
void check_benchmark_scene(const std::string& preset, phong_bench::input_set set, std::size_t K, phong_bench::light_style style)
{
    using namespace phong_bench;
    constexpr phong::features F = phong::presets::with_mode(F0, Mode);
    constexpr std::size_t N = 1024;
    const scene sc = make_scene(set, K);
    const points<T> pts = make_points<T>(set, N, K);
    const std::vector<phong::light<T>> lights = lights_of<T>(sc, style);
    const phong::material<T> mat = material_of<T>(sc);
    const phong::environment<T> env = environment_of<T>(sc);
    std::vector<T> px(N), py(N), pz(N), nx(N), ny(N), nz(N), r(N), g(N), b(N), a(N);
    for (std::size_t i = 0; i < N; ++i) {
        px[i] = pts.position[i].x, py[i] = pts.position[i].y, pz[i] = pts.position[i].z;
        nx[i] = pts.normal[i].x, ny[i] = pts.normal[i].y, nz[i] = pts.normal[i].z;
    }
    using S = std::span<const T>;
    const std::span<const phong::light<T>> L(lights);
    const unsigned batch = subnormal_flags([&] {
        phong::shade_batch<F>(phong::soa3<T>{S(px), S(py), S(pz)}, phong::soa3<T>{S(nx), S(ny), S(nz)}, mat, L,
                              phong::soa_rgba<T>{r, g, b, a}, env);
    });
    std::vector<T> scalar(N);
    const unsigned each = subnormal_flags([&] {
        for (std::size_t i = 0; i < N; ++i) scalar[i] = phong::shade<F>(pts.position[i], pts.normal[i], mat, L, env)[0];
    });
    INFO(preset, " ", mode_name(Mode), " ", std::string(sizeof(T) == 4 ? "float" : "double"), " ", std::string(name(set)), " K = ", K,
         " light style ", int(style));
    INFO("shade_batch: ", describe(batch), "; shade<F>: ", describe(each));
    CHECK(batch == 0u);
    CHECK(each == 0u);
    // The colours are the scene's: finite and, for the typical set, lit (not a vacuous pass).
    if (set == input_set::typical) CHECK(r[N / 2] > T(0));
}

template <phong::features F0, class T> void check_modes(const std::string& preset)
{
    using namespace phong_bench;
    const light_style style = F0.spot == phong::spot_model::none ? light_style::plain : light_style::attenuated_spot;
    for (input_set set : {input_set::typical, input_set::highlight, input_set::grazing})
        for (std::size_t K : {1u, 4u, 16u}) {
            check_benchmark_scene<F0, phong::evaluation::exact, T>(preset, set, K, style);
            check_benchmark_scene<F0, phong::evaluation::stable, T>(preset, set, K, style);
            check_benchmark_scene<F0, phong::evaluation::fast, T>(preset, set, K, style);
            if (F0.lights == phong::light_kind::any && set != input_set::grazing) {
                check_benchmark_scene<F0, phong::evaluation::exact, T>(preset, set, K, light_style::directional);
                check_benchmark_scene<F0, phong::evaluation::stable, T>(preset, set, K, light_style::directional);
                check_benchmark_scene<F0, phong::evaluation::fast, T>(preset, set, K, light_style::directional);
            }
        }
}

/// The demo's scene (five objects, a positional, a directional and a spot light, attenuation,
/// two-sided by the view), its renderer's shading pass (shade<F> with the lights that reach each
/// hit) and shade_batch over the same hits (every light, one material per point).
template <phong::features F0, phong::evaluation Mode> void check_demo_scene(bool perspective)
{
    using namespace phong_demo;
    constexpr phong::features F = phong::presets::with_mode(F0, Mode);
    const scene sc = demo_scene();
    const camera cam = demo_camera(perspective, 96, 72);
    std::vector<hit_record> gbuffer;
    intersect(sc, cam, gbuffer); // the renderer's own geometry: outside the checked calls
    // The frame's setup, once per frame: outside too. (clang++ 16 -O3 -march=native computes
    // eye_from_projection's row rescaling in 2 lanes of a 4-lane register whose other lanes hold
    // stale bits, here a subnormal: DE once per frame, no cost worth an assertion.)
    const phong::environment<float> env = frame_environment(sc, cam);
    image img;
    const unsigned pass = subnormal_flags([&] { shade_pass<F>(sc, cam, env, gbuffer, img); });

    std::vector<float> px, py, pz, nx, ny, nz;
    std::vector<phong::material<float>> mats;
    for (const hit_record& h : gbuffer) {
        if (h.object < 0) continue;
        px.push_back(h.position.x), py.push_back(h.position.y), pz.push_back(h.position.z);
        nx.push_back(h.normal.x), ny.push_back(h.normal.y), nz.push_back(h.normal.z);
        mats.push_back(sc.objects[std::size_t(h.object)].material);
    }
    const std::size_t N = px.size();
    std::vector<float> r(N), g(N), b(N);
    using S = std::span<const float>;
    const unsigned batch = subnormal_flags([&] {
        phong::shade_batch<F>(phong::soa3<float>{S(px), S(py), S(pz)}, phong::soa3<float>{S(nx), S(ny), S(nz)},
                              std::span<const phong::material<float>>(mats), std::span<const phong::light<float>>(sc.lights),
                              phong::soa_rgba<float>{r, g, b, {}}, env);
    });
    INFO("demo scene, ", std::string(F0.specular == phong::specular_model::blinn ? "blinn " : "phong "), mode_name(Mode),
         std::string(perspective ? " perspective" : " orthographic"));
    INFO("shade<F> pass: ", describe(pass), "; shade_batch: ", describe(batch));
    CHECK(N > 1000u);
    CHECK(pass == 0u);
    CHECK(batch == 0u);
}
#endif

} // namespace

#if PHONG_TEST_MXCSR
TEST_CASE("MXCSR's flags see a subnormal result and operand (the check below can fail)")
{
    const default_environment fp;
    volatile float tiny = 1e-30f, small = 1e-10f;
    float product = 0;
    CHECK((subnormal_flags([&] { product = tiny * small; }) & 0x10u) != 0u); // 1e-40: a subnormal result, UE
    volatile float sub = product;
    float sum = 0;
    CHECK((subnormal_flags([&] { sum = sub + 1.0f; }) & 0x02u) != 0u); // reading it: DE
    volatile float normal = 0.5f;
    CHECK(subnormal_flags([&] { sum = normal * normal; }) == 0u);
    CHECK(sum > 0.0f);
}

TEST_CASE_TEMPLATE("no subnormal operand or result: shade_batch and shade<F> on the benchmark scenes, every mode", T, float, double)
{
    const default_environment fp;
    check_modes<phong::presets::glsl_ads, T>("glsl_ads");
    check_modes<blinn_ads, T>("glsl_ads blinn");
    check_modes<spot_ads, T>("glsl_ads attenuated spot");
    check_modes<phong::presets::classic_phong, T>("classic_phong");
}

TEST_CASE("no subnormal operand or result: the demo scene, its renderer's shade<F> pass and shade_batch, every mode")
{
    const default_environment fp;
    for (bool perspective : {true, false}) {
        check_demo_scene<phong_demo::phong_lighting, phong::evaluation::exact>(perspective);
        check_demo_scene<phong_demo::phong_lighting, phong::evaluation::stable>(perspective);
        check_demo_scene<phong_demo::phong_lighting, phong::evaluation::fast>(perspective);
        check_demo_scene<phong_demo::blinn_lighting, phong::evaluation::exact>(perspective);
        check_demo_scene<phong_demo::blinn_lighting, phong::evaluation::stable>(perspective);
        check_demo_scene<phong_demo::blinn_lighting, phong::evaluation::fast>(perspective);
    }
}
#else
TEST_CASE("no subnormal operand or result (MXCSR flags: x86-64 only)" * doctest::skip())
{
}
#endif
