// Test support: the reference model. phong's whole lighting model (every feature and policy that
// shade<F> documents) evaluated in a wide type from the exact values of the float/double inputs.
// Written independently of the library, directly from the formulas in the seeds and the policies
// stated in shade.hpp's doc comment, so it serves as the oracle for values and for error reports.
#pragma once

#include "wide.hpp"

#include <phong/terms/attenuation.hpp>
#include <phong/inputs/features.hpp>
#include <phong/inputs/light.hpp>
#include <phong/inputs/material.hpp>
#include <phong/sum/shade.hpp>

#include <span>
#include <vector>

namespace phong_test {

/// The reference colour: rgb and alpha in the wide type.
struct wcolor {
    wide r = 0, g = 0, b = 0, a = 1;
    wide operator[](int i) const { return i == 0 ? r : i == 1 ? g : i == 2 ? b : a; }
};

/// The model at one point, in the wide type. T is the library's scalar type (its attenuation cap
/// phong::detail::attenuation_denominator_min<T> is a parameter of the model).
template <class T>
wcolor reference_shade(const phong::features& F, const glm::vec<3, T>& position, const glm::vec<3, T>& normal,
                       const phong::material<T>& mat, std::span<const phong::light<T>> lights,
                       const phong::environment<T>& env = {}, bool front_facing = true)
{
    using namespace phong;
    const wvec3 Q = widen(position);
    const wvec3 eye_xyz{wide(env.eye.x), wide(env.eye.y), wide(env.eye.z)};
    const wide eye_w = wide(env.eye.w);

    // v: toward the viewer.
    wvec3 v;
    if (F.view == view_model::eye_at_origin) v = wnormalize(-Q);
    else if (F.view == view_model::fixed_direction) v = wnormalize(eye_xyz);
    else v = wnormalize(eye_xyz - Q * eye_w);

    // n: unit, conditionally negated.
    wvec3 n = wnormalize(widen(normal));
    if (F.two_sided == facing::view && wdot(n, v) < 0) n = -n;
    if (F.two_sided == facing::flag && !front_facing) n = -n;
    const bool defined = wdot(n, n) > 0 && wdot(v, v) > 0;

    const wide m = wide(mat.shininess);
    wvec3 sum_ambient, sum_diffuse, sum_specular;
    for (const light<T>& L : lights) {
        const wvec3 Lxyz{wide(L.position.x), wide(L.position.y), wide(L.position.z)};
        const wide w = F.lights == light_kind::directional ? wide(0)
                     : F.lights == light_kind::positional  ? wide(1)
                                                           : wide(L.position.w);
        const wvec3 d = Lxyz - Q * w;
        const wide len = wlength(d);
        const wvec3 l = len > 0 ? d * (wide(1) / len) : wvec3{};
        const bool lit = defined && len > 0;
        const wide nl = wdot(n, l);

        wide f = 1;
        if (F.attenuation != attenuation_model::none && F.lights != light_kind::directional && w > 0) {
            const wide dist = len / w;
            const wide floor = wide(phong::detail::attenuation_denominator_min<T>);
            if (F.attenuation == attenuation_model::polynomial) {
                const wide denom = wide(L.attenuation.constant) + wide(L.attenuation.linear) * dist +
                                   wide(L.attenuation.quadratic) * dist * dist;
                f = 1 / wmax(denom, floor);
            } else {
                const wide ratio = dist / wide(L.attenuation.range);
                const wide window = wclamp(1 - ratio * ratio * ratio * ratio, 0, 1);
                f = window * window / wmax(dist * dist, floor);
            }
        }
        const bool has_cone = !(L.spot.direction.x == 0 && L.spot.direction.y == 0 && L.spot.direction.z == 0); // zero axis: no cone
        if (F.spot != spot_model::none && has_cone) {
            const wvec3 s = wnormalize(widen(L.spot.direction)); // the model reads the axis's direction
            const wide c = -wdot(l, s);
            if (F.spot == spot_model::opengl) {
                const wide cut = wide(L.spot.cos_cutoff);
                const wide e = wide(L.spot.exponent);
                f *= cut <= -1 ? wide(1) : (c >= cut ? (e == 0 ? wide(1) : wpow(wmax(c, 0), e)) : wide(0));
            } else {
                const wide inner = wide(L.spot.cos_inner), outer = wide(L.spot.cos_outer);
                wide t;
                if (inner > outer && F.spot == spot_model::linear) t = wclamp((c - outer) / (inner - outer), 0, 1);
                else if (inner > outer) t = wclamp((c - outer) / (inner - outer), 0, 1), t = t * t * (3 - 2 * t);
                else t = c >= outer ? 1 : 0;
                f *= t;
            }
        }

        if (F.light_ambient) sum_ambient = sum_ambient + widen(L.ambient) * (F.attenuate_ambient ? f : wide(1));
        if (F.diffuse && lit) sum_diffuse = sum_diffuse + widen(L.diffuse) * (f * wmax(nl, 0));
        if (F.specular != specular_model::none && lit && (!F.specular_gate || nl > 0)) {
            wide base;
            if (F.specular == specular_model::phong) {
                const wvec3 r = n * (2 * nl) - l; // reflect(-l, n)
                base = wclamp(wdot(r, v), 0, 1);
            } else {
                const wvec3 h = wnormalize(l + v); // l = -v: h = 0, n.h = 0
                base = wclamp(wdot(n, h), 0, 1);
            }
            const wide s = m == 0 ? wide(1) : (base == 0 ? wide(0) : wpow(base, m));
            sum_specular = sum_specular + widen(L.specular) * (f * s);
        }
    }

    wvec3 c;
    if (F.emission) c = c + widen(mat.emission);
    wvec3 ambient;
    if (F.scene_ambient) ambient = ambient + widen(env.ambient);
    if (F.light_ambient) ambient = ambient + sum_ambient;
    c = c + widen(mat.ka) * ambient;
    if (F.diffuse) c = c + widen(mat.kd) * sum_diffuse;
    if (F.specular != specular_model::none) c = c + widen(mat.ks) * sum_specular;
    return {c.x, c.y, c.z, F.alpha ? wide(mat.alpha) : wide(1)};
}

} // namespace phong_test
