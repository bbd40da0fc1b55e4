// Stable float (the wider route: float evaluated in double, rounded once) with spot lights and a
// fixed-direction (orthographic) eye: the colour is the correct rounding of the model but for
// near-ties, within 1 ulp, as for every other class. The model reads the spot axis's direction
// (the axis a float spot_cone holds is unit only to float precision); the reference is the
// __float128 evaluation of the model (tests/support/reference.hpp).
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/reference.hpp"

#include <phong/accuracy.hpp>
#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <span>

using namespace phong;
using namespace phong_test;

namespace {
constexpr features spot_features(spot_model spot, specular_model specular, view_model view)
{
    features f = accuracy::measured_features(evaluation::stable, specular);
    f.spot = spot;
    f.view = view;
    return f;
}

template <features F> double worst_ulp(std::uint64_t seed, int scenes)
{
    scene_gen<float> g(seed);
    double worst = 0;
    for (int i = 0; i < scenes; ++i) {
        const scene<float> s = g.make(F, 1 + i % 3, 1, 200);
        if (!well_conditioned(F, s)) continue; // away from the cutoff, the gate and the other discontinuities
        const glm::vec3 c = shade<F>(s.position, s.normal, s.mat, s.lights, s.env);
        const wcolor r = reference_shade(F, s.position, s.normal, s.mat, std::span<const light<float>>(s.lights), s.env);
        for (int k = 0; k < 3; ++k) {
            if (!(r[k] >= wide(std::numeric_limits<float>::min()))) continue; // below float's normal range
            worst = std::max(worst, error_ulp(c[k], r[k]));
        }
    }
    return worst;
}
} // namespace

TEST_CASE("stable float with spot lights and a fixed-direction eye: within 1 ulp of the model")
{
    CHECK(worst_ulp<spot_features(spot_model::opengl, specular_model::phong, view_model::eye_at_origin)>(11, 4000) <= 1.0);
    CHECK(worst_ulp<spot_features(spot_model::smooth, specular_model::blinn, view_model::eye_at_origin)>(12, 4000) <= 1.0);
    CHECK(worst_ulp<spot_features(spot_model::opengl, specular_model::blinn, view_model::fixed_direction)>(13, 4000) <= 1.0);
    CHECK(worst_ulp<spot_features(spot_model::smooth, specular_model::phong, view_model::fixed_direction)>(14, 4000) <= 1.0);
}
