// The test case of shade_batch's inputs beyond G-buffers (tests/batch_inputs.test.cpp and
// tests/batch_material_table.test.cpp): points with their own view vectors, facing flags,
// materials and light masks, in the AoS and SoA layouts.
#pragma once

#include "generators.hpp"

#include <phong/batch.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace phong_test {

/// Stable Blinn-Phong with every optional term a batch step carries per point: per-point views,
/// no specular gate, a smooth spot, facing flags, emission and alpha.
inline constexpr phong::features given_view_stable_blinn_all_terms{
    .specular = phong::specular_model::blinn, .specular_gate = false, .spot = phong::spot_model::smooth,
    .two_sided = phong::facing::flag, .view = phong::view_model::given, .emission = true, .alpha = true,
    .mode = phong::evaluation::stable};

/// N points with their own view vectors, facing flags, materials and light masks, in both layouts.
template <class T> struct batch_case {
    scene<T> base;
    std::vector<glm::vec<3, T>> p, n, v;
    std::vector<T> px, py, pz, nx, ny, nz, vx, vy, vz;
    std::vector<phong::material<T>> mats;
    std::vector<std::uint64_t> masks;
    std::unique_ptr<bool[]> front;

    batch_case(scene_gen<T>& gen, const phong::features& F, std::size_t count, int lights) : base(gen.make(F, lights))
    {
        front.reset(new bool[count + 1]);
        for (std::size_t i = 0; i < count; ++i) {
            p.push_back(gen.point());
            const glm::vec<3, T> dir = gen.direction();
            const glm::vec<3, T> view = gen.direction();
            // unit_inputs: unit by precondition; else any length (shade normalizes).
            n.push_back(F.unit_inputs ? dir : dir * gen.uniform(0.25, 4));
            v.push_back(F.unit_inputs ? view : view * gen.uniform(0.25, 4));
            px.push_back(p[i].x), py.push_back(p[i].y), pz.push_back(p[i].z);
            nx.push_back(n[i].x), ny.push_back(n[i].y), nz.push_back(n[i].z);
            vx.push_back(v[i].x), vy.push_back(v[i].y), vz.push_back(v[i].z);
            mats.push_back(gen.material(1, 100));
            // Random visibility, now and then none or all, with bits past the light list set
            // (ignored, as by masked()).
            const int kind = gen.integer(0, 9);
            std::uint64_t bits = kind == 0 ? 0 : kind == 1 ? ~std::uint64_t(0) : 0;
            if (kind > 1)
                for (int j = 0; j < 64; ++j) bits |= std::uint64_t(gen.coin()) << j;
            masks.push_back(bits);
            front[i] = gen.coin();
        }
    }
    std::size_t size() const { return p.size(); }
    phong::soa_points<T> soa(bool given, bool masked) const
    {
        return {phong::soa3<T>{px, py, pz}, phong::soa3<T>{nx, ny, nz}, given ? phong::soa3<T>{vx, vy, vz} : phong::soa3<T>{},
                std::span<const bool>(front.get(), size()),
                masked ? std::span<const std::uint64_t>(masks) : std::span<const std::uint64_t>()};
    }
    phong::aos_points<T> aos(bool given, bool masked) const
    {
        return {p, n, given ? std::span<const glm::vec<3, T>>(v) : std::span<const glm::vec<3, T>>(),
                std::span<const bool>(front.get(), size()),
                masked ? std::span<const std::uint64_t>(masks) : std::span<const std::uint64_t>()};
    }
    /// Point i alone, AoS (the oracle of a long call: each point shaded in a call of its own).
    phong::aos_points<T> point_alone(std::size_t i, bool given, bool masked) const
    {
        return {std::span(&p[i], 1), std::span(&n[i], 1), given ? std::span(&v[i], 1) : std::span<const glm::vec<3, T>>(),
                std::span<const bool>(front.get() + i, 1), masked ? std::span(&masks[i], 1) : std::span<const std::uint64_t>()};
    }
    /// The scene of point i as shade<F> sees it, for the conditioning test: a given view vector
    /// becomes an eye point at Q + v (eye_point), where the same v results.
    scene<T> point_scene(std::size_t i, const phong::features& F, bool per_point_material) const
    {
        scene<T> s = base;
        s.position = p[i];
        s.normal = n[i];
        s.front_facing = front[i];
        if (per_point_material) s.mat = mats[i];
        if (F.view == phong::view_model::given) s.env.eye = glm::vec<4, T>(p[i] + v[i], T(1));
        return s;
    }
};

} // namespace phong_test
