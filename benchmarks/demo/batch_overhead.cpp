// shade_batch's per-point overhead outside the kernel, in instructions (docs/batch.md): one call
// over N = 16384 points laid out like a ray tracer's primary hits (aos_points: positions, unit
// normals, views, shadow masks; some steps partly shadowed), the ray tracer's features, with the
// materials either copied per point by id (the demo's way before material_table) or as a
// material_table. Built for AVX2 (callgrind cannot decode AVX-512); run under callgrind:
//   valgrind --tool=callgrind --callgrind-out-file=cg.out phong_batch_overhead <lights> <ids: 0 uniform per 1024 points, 1 mixed> <0 copy, 1 table>
//   callgrind_annotate --inclusive=yes cg.out | grep -E 'shade_hits|shade_lanes'
// shade_hits is the whole call (copy included), shade_lanes the kernel; the difference over N is
// the overhead per point. -DPHONG_OVERHEAD_NO_TABLE builds it against a phong without material_table.
// SPDX-License-Identifier: MIT
#include <phong/batch.hpp>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using namespace phong;
constexpr features F = [] {
    features f = presets::raytracer_phong;
    f.specular_gate = false;
    f.unit_inputs = true;
    return f;
}();

struct hits {
    std::vector<glm::vec3> P, n, v;
    std::vector<std::uint64_t> masks;
    std::vector<std::uint32_t> ids;
};

[[gnu::noinline]] void shade_hits(const hits& h, const std::vector<material<float>>& table, const std::vector<light<float>>& lights,
                                  bool use_table, std::vector<material<float>>& scratch, std::vector<glm::vec3>& out)
{
    const aos_points<float> points{.positions = h.P, .normals = h.n, .views = h.v, .light_masks = h.masks};
#if !defined(PHONG_OVERHEAD_NO_TABLE)
    if (use_table) {
        shade_batch<F>(points, material_table<float>{.materials = table, .ids = h.ids}, lights, out, environment<float>{});
        return;
    }
#endif
    (void)use_table;
    scratch.resize(h.ids.size());
    for (std::size_t i = 0; i < h.ids.size(); ++i) scratch[i] = table[h.ids[i]];
    shade_batch<F>(points, std::span<const material<float>>(scratch), lights, out, environment<float>{});
}

} // namespace

int main(int argc, char** argv)
{
    const int K = argc > 1 ? std::atoi(argv[1]) : 1;
    const bool mixed = argc > 2 && std::atoi(argv[2]) != 0;
    const bool use_table = argc > 3 && std::atoi(argv[3]) != 0;
    const std::size_t N = 16384;
    hits h;
    for (std::size_t i = 0; i < N; ++i) {
        const float x = float(i % 128) / 64.0f - 1.0f, y = float(i / 128) / 64.0f - 1.0f;
        h.P.push_back(glm::vec3(x, y, -3.0f));
        h.n.push_back(glm::normalize(glm::vec3(0.3f * x, 0.3f * y, 1.0f)));
        h.v.push_back(glm::normalize(glm::vec3(-0.1f * x, -0.1f * y, 1.0f)));
        h.masks.push_back((i / 512) % 4 == 3 && i % 3 == 0 ? 0 : ~std::uint64_t(0)); // a quarter of the steps partly shadowed
        h.ids.push_back(mixed ? std::uint32_t(i % 3) : std::uint32_t((i / 1024) % 3));
    }
    std::vector<material<float>> table(3);
    for (std::size_t j = 0; j < table.size(); ++j) table[j].shininess = float(10 + 20 * j);
    std::vector<light<float>> lights;
    for (int j = 0; j < K; ++j) lights.push_back(light<float>::with_strength({float(j) - 1.0f, 2.0f, 2.0f, 1.0f}, glm::vec3(0.5f)));
    std::vector<material<float>> scratch;
    std::vector<glm::vec3> out(N);
    shade_hits(h, table, lights, use_table, scratch, out);
    std::printf("%.9g %.9g\n", double(out[N / 2].r), double(out[N - 1].b));
    return 0;
}
