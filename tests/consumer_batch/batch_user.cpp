// A renderer's translation unit using an installed phong's batch path: compiled by
// .ci/steps/15-install-consumer.sh with g++ and clang++, -Wall -Wextra -Wpedantic -Werror
// -march=native and -O1 / -O3, phong's headers not treated as system headers. It instantiates
// shade_batch with several feature sets (exact and stable; Phong, Blinn, diffuse only; every view
// model), SoA and AoS inputs, with and without light masks, a material table, and checks each point against the
// scalar shade<F> with phong::masked() (relative 1e-3 of the largest channel: the batch differs
// from scalar by a few ulp times the shininess, see phong/batch.hpp; the geometry keeps every
// point far from the model's gates). Exit status 0 on success.
#include <phong/batch.hpp>
#include <phong/phong.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <vector>

#if !defined(PHONG_EXPECT_XSIMD)
#  error "PHONG_EXPECT_XSIMD: 1 when the installed package uses xsimd (PHONG_USE_XSIMD), else 0"
#endif
static_assert(PHONG_HAS_XSIMD == PHONG_EXPECT_XSIMD, "PHONG_USE_XSIMD did not reach the compile definitions");

namespace {

using namespace phong;

template <class T> struct hits {
    std::vector<glm::vec<3, T>> p, n, v;
    std::vector<T> px, py, pz, nx, ny, nz, vx, vy, vz;
    std::vector<std::uint64_t> masks;
};

/// Points in front of the eye, normals and views toward it, lights in front: n.l, n.v and
/// |l + v| all well away from 0, so scalar and batch agree to a few ulp per point.
template <class T> hits<T> make_hits(std::size_t count)
{
    hits<T> h;
    std::uint32_t state = 12345;
    const auto next = [&state] { // [0, 1)
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / double(1u << 24);
    };
    for (std::size_t i = 0; i < count; ++i) {
        const double x = 2 * next() - 1, y = 2 * next() - 1, z = -2 - 4 * next();
        h.p.push_back(glm::vec<3, T>(T(x), T(y), T(z)));
        h.n.push_back(glm::vec<3, T>(T(0.2 * x), T(0.2 * y), T(1)));
        h.v.push_back(glm::vec<3, T>(T(-0.1 * x), T(-0.1 * y), T(1)));
        h.px.push_back(h.p[i].x), h.py.push_back(h.p[i].y), h.pz.push_back(h.p[i].z);
        h.nx.push_back(h.n[i].x), h.ny.push_back(h.n[i].y), h.nz.push_back(h.n[i].z);
        h.vx.push_back(h.v[i].x), h.vy.push_back(h.v[i].y), h.vz.push_back(h.v[i].z);
        h.masks.push_back(std::uint64_t(i % 4)); // none, light 0, light 1, both
    }
    return h;
}

template <class T, int N> bool close(const glm::vec<N, T>& got, const glm::vec<N, T>& want, const char* what, std::size_t i)
{
    double scale = 1e-30, diff = 0;
    for (int k = 0; k < N; ++k) {
        scale = std::max(scale, double(std::fabs(want[k])));
        diff = std::max(diff, double(std::fabs(got[k] - want[k])));
    }
    if (diff <= 1e-3 * scale) return true;
    std::printf("batch_user: %s point %zu: relative difference %g\n", what, i, diff / scale);
    return false;
}

/// |got - want| <= roundings * eps * |want| in every channel (non-negative sums of terms).
template <class T, int N> bool within_roundings(const glm::vec<N, T>& got, const glm::vec<N, T>& want, int roundings)
{
    for (int k = 0; k < N; ++k)
        if (!(std::fabs(double(got[k]) - double(want[k])) <= roundings * double(std::numeric_limits<T>::epsilon()) * std::fabs(double(want[k]))))
            return false;
    return true;
}

/// Every layout for feature set F on T: SoA and AoS points, with and without masks (and the
/// older soa3 overload where F has no per-point views), against shade<F> point by point.
template <features F, class T> bool check(const char* name)
{
    constexpr bool given = F.view == view_model::given;
    const std::size_t count = 2 * batch_width<T> + 3; // two full steps and a tail
    const hits<T> h = make_hits<T>(count);
    std::vector<light<T>> lights(2);
    lights[0] = light<T>::with_strength({T(3), T(2), T(2), T(1)}, glm::vec<3, T>(T(1)));
    lights[1] = light<T>::with_strength({T(-3), T(1), T(3), T(1)}, glm::vec<3, T>(T(0.5), T(0.75), T(1)));
    for (light<T>& L : lights) L.ambient = glm::vec<3, T>(T(0.25));
    const material<T> mat{.ka = glm::vec<3, T>(T(0.2)), .kd = glm::vec<3, T>(T(0.6)), .ks = glm::vec<3, T>(T(0.3)), .shininess = T(16)};
    environment<T> env{.ambient = glm::vec<3, T>(T(0.5))};
    if constexpr (F.view == view_model::fixed_direction) env.eye = glm::vec<4, T>(T(0.1), T(0.2), T(1), T(0));
    if constexpr (F.view == view_model::eye_point) env.eye = glm::vec<4, T>(T(0.5), T(-0.5), T(1), T(1));

    bool ok = true;
    for (int masked_lights = 0; masked_lights < 2; ++masked_lights) {
        const std::span<const std::uint64_t> masks = masked_lights ? std::span<const std::uint64_t>(h.masks) : std::span<const std::uint64_t>();
        soa_points<T> soa{.positions = {h.px, h.py, h.pz}, .normals = {h.nx, h.ny, h.nz}, .light_masks = masks};
        aos_points<T> aos{.positions = h.p, .normals = h.n, .light_masks = masks};
        if constexpr (given) {
            soa.views = {h.vx, h.vy, h.vz};
            aos.views = h.v;
        }
        std::vector<color<F, T>> from_soa(count), from_aos(count), from_table(count);
        shade_batch<F>(soa, mat, lights, from_soa, env);
        shade_batch<F>(aos, mat, lights, from_aos, env);
        // A material table (here: two copies of mat) with one id per point, mixed and uniform steps.
        const std::vector<material<T>> table{mat, mat};
        std::vector<std::uint32_t> ids(count);
        for (std::size_t i = 0; i < count; ++i) ids[i] = i < batch_width<T> ? 1u : std::uint32_t(i % 2);
        shade_batch<F>(aos, material_table<T>{.materials = table, .ids = ids}, lights, from_table, env);
        std::vector<color<F, T>> from_soa3(count);
        if constexpr (!given) {
            if (!masked_lights)
                shade_batch<F>(soa3<T>{h.px, h.py, h.pz}, soa3<T>{h.nx, h.ny, h.nz}, mat, std::span<const light<T>>(lights),
                               std::span<color<F, T>>(from_soa3), env);
        }
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint64_t visible = masked_lights ? h.masks[i] : ~std::uint64_t(0);
            // A span: clang++ 14 with libstdc++ 12 cannot form ranges::ref_view<std::vector>.
            const std::span<const light<T>> all_lights(lights);
            color<F, T> want;
            if constexpr (given) want = shade<F>(h.p[i], h.n[i], h.v[i], mat, masked(all_lights, visible), env);
            else want = shade<F>(h.p[i], h.n[i], mat, masked(all_lights, visible), env);
            ok = close(from_soa[i], want, name, i) && ok;
            // One material is folded into the lights (ka La_i, kd Ld_i, ks Ls_i) once per call; a
            // table's materials multiply the sums per step: the same terms, the material product
            // rounded before instead of after the sum, so within a few roundings, not bit for bit.
            if (!within_roundings(from_table[i], from_aos[i], 16)) {
                std::printf("batch_user: %s point %zu: material_table differs from one material\n", name, i);
                ok = false;
            }
            if (!(from_aos[i] == from_soa[i])) {
                std::printf("batch_user: %s point %zu: AoS differs from SoA\n", name, i);
                ok = false;
            }
            if (!given && !masked_lights && !(from_soa3[i] == from_soa[i])) {
                std::printf("batch_user: %s point %zu: soa_points differs from soa3\n", name, i);
                ok = false;
            }
        }
    }
    std::printf("batch_user: %-28s %s, %zu lanes: %s\n", name, sizeof(T) == 4 ? "float " : "double", batch_width<T>, ok ? "ok" : "FAILED");
    return ok;
}

constexpr features blinn_given{.specular = specular_model::blinn, .lights = light_kind::positional, .view = view_model::given};
constexpr features blinn_fixed_stable{.specular = specular_model::blinn, .view = view_model::fixed_direction, .mode = evaluation::stable};
constexpr features diffuse_given{.scene_ambient = false, .specular = specular_model::none, .view = view_model::given};

} // namespace

int main()
{
    bool ok = true;
    ok = check<presets::raytracer_phong, float>("raytracer_phong (given)") && ok;
    ok = check<presets::with_mode(presets::raytracer_phong, evaluation::stable), double>("raytracer_phong stable") && ok;
    ok = check<blinn_given, float>("blinn given") && ok;
    ok = check<diffuse_given, double>("diffuse given") && ok;
    ok = check<presets::diffuse_only, float>("diffuse_only (eye_at_origin)") && ok;
    ok = check<presets::glsl_ads, double>("glsl_ads (eye_at_origin)") && ok;
    ok = check<presets::classic_phong, float>("classic_phong (eye_point)") && ok;
    ok = check<presets::with_mode(presets::classic_phong, evaluation::stable), float>("classic_phong stable") && ok;
    ok = check<presets::blinn_phong_per_light_ambient, float>("blinn per-light ambient") && ok;
    ok = check<blinn_fixed_stable, float>("blinn fixed_direction stable") && ok;
    return ok ? 0 : 1;
}
