// phong: `features`, the compile-time description of what a scene needs.
// SPDX-License-Identifier: MIT
//
// A structural aggregate, passed as a non-type template parameter to shade<F>(...). Every
// optional term of the model sits behind `if constexpr` on one of these fields, so a term a
// scene leaves out is not in the compiled code (checked by an instruction count, see
// benchmarks/feature_cost.sh). Kept in its own header because shade.hpp, batch.hpp and the
// presets all read it.
#pragma once

#include "../core/config.hpp"

namespace phong {

/// Which specular term: none, reflection-based (classic Phong/003: max(r.v, 0)^m with
/// r = reflect(-l, n)) or halfway-based (the ray tracer model, Blinn: max(n.h, 0)^m with h = normalize(l + v)).
enum class specular_model : unsigned char { none, phong, blinn };

/// What the light positions' w may be. `any`: read at run time (w = 1 positional, w = 0
/// directional, one branch-free rule). `positional`: w = 1 assumed. `directional`: w = 0 assumed,
/// so no distance and no attenuation are computed.
enum class light_kind : unsigned char { any, positional, directional };

/// Distance attenuation f_i(Q). `none`: f = 1. `polynomial`: OpenGL / classic Phong,
/// f = 1 / (c0 + c1 d + c2 d^2). `windowed`: inverse square with a smooth window that reaches
/// exactly 0 at the light's range (Filament, three.js): f = clamp(1 - (d/range)^4, 0, 1)^2 / d^2.
enum class attenuation_model : unsigned char { none, polynomial, windowed };

/// Spot cone. `opengl`: max(-l.s, 0)^e inside the cutoff, 0 outside (cutoff 180 = no spot).
/// `smooth`: smoothstep from the outer to the inner cone (Filament, three.js). `linear`: a
/// straight ramp in the cosine from the outer to the inner cone (LearnOpenGL, Unity, Godot).
/// With any of them, a light whose spot axis is zero has no cone (spot = 1).
enum class spot_model : unsigned char { none, opengl, smooth, linear };

/// Two-sided lighting: how the normal is conditionally negated. `none`: used as given. `view`:
/// negated when it faces away from the viewer, n.v < 0 (classic Phong's "conditionally negated").
/// `flag`: negated when the caller says the point is back-facing (e.g. gl_FrontFacing).
enum class facing : unsigned char { none, view, flag };

/// Where the viewer is, and so how the view vector v (from the point toward the viewer) is found.
///  * `eye_at_origin` (the default): the eye at the origin of the shading coordinates,
///    v = normalize(-Q). Rasterizers shading in eye coordinates (classic Phong, 003).
///  * `given`: v is passed to each shade call (shade<F>(Q, n, v, ...)): a ray tracer's -ray.dir,
///    right for primary, reflected and refracted rays alike; a rasterizer's per-vertex or
///    per-pixel vector. The one to use whenever the renderer already has v.
///  * `fixed_direction`: one direction for every point, environment::eye.xyz (normalized once per
///    call; used as given with unit_inputs): orthographic cameras (classic Phong's
///    normalize(-M02/M00, -M12/M11, 1); view.hpp), a screen-space rasterizer's view along +z.
///  * `eye_point`: the general homogeneous rule v = normalize(E.xyz - E.w Q) for environment::eye
///    E (w = 1: an eye point such as the ray tracer model's ray start, for primary rays only; w = 0: a
///    direction). eye_from_projection() derives E from any projection matrix.
enum class view_model : unsigned char {
    eye_at_origin,
    fixed_direction,
    eye_point,
    given,
};

/// How the terms are evaluated (accuracy against speed; bounds in phong/accuracy.hpp).
/// `exact`: the formulas as written, guarded so they never give NaN/Inf for finite input.
/// `stable`: a few ulp or better on stiff and extreme inputs (phong/accuracy.hpp), by one of two
/// routes (features::precision): float evaluated in double, or power-of-two rescaled vectors with
/// the unit vectors n, l, v (h), n.l and the chords r - v, n - h carried twofold (to ~eps^2, from the
/// exact L - Q; detail/twofold.hpp) and the half-chord exponent exp(m log1p(-|r - v|^2/2)).
/// The twofold route's 1 - cosine carries ~eps^2 absolute, which the power multiplies by m: for
/// m beyond ~1/eps^2 (2.8e14 float, 8e31 double) a highlight's factor is as uncertain as the
/// inputs' last bits (exactly parallel vectors may give 0 instead of 1).
/// `fast`: the exact mode's formulas and guards (the same NaN and degenerate-input policy) with the
/// specular power and the light vector's 1/|d| taken by the approximations of phong/core/fast_math.hpp
/// (fast::pow_unit, fast::rsqrt): for colours that end in 8-bit or half-float pixels.
enum class evaluation : unsigned char { exact, stable, fast };

/// Where the stable mode's extra precision comes from (phong/accuracy.hpp has the bounds).
/// `wider`: float is evaluated in double with the exact mode's formulas and rounded once. Every
/// float input is exact in double, no square of a float overflows or underflows there, and double
/// carries 29 more bits than float, so the colour is float's correct rounding of the model but for
/// near-ties (about 0.5 ulp). The default: the most accurate choice, for CPUs and for GPUs whose
/// double runs at half float's rate (data-centre GPUs; docs/cuda.md compares the two).
/// T without a wider hardware type (double, double SIMD batches) takes `twofold`. `twofold`: T
/// arithmetic with power-of-two rescaled vectors and twofold unit vectors, n.l and chords
/// (detail/twofold.hpp); for GPUs whose double runs at a small fraction of float's rate (consumer
/// GPUs, 1/32 or 1/64 of float's; docs/cuda.md). Float SIMD
/// batches on x86 (shade_batch) read neither: their geometry runs in double lanes and the power
/// in float (detail/simd/stable_lanes.hpp), held to the twofold bounds; steps with a shininess above
/// 2^20 in any lane take the twofold route.
enum class stable_precision : unsigned char { wider, twofold };

/// Everything shade<F> can compute. Defaults: classic Phong's classic model with one ambient term,
/// reflection-based specular gated on n.l > 0, perspective view, exact evaluation.
struct features {
    bool scene_ambient = true;   ///< ka * La (classic Phong), the same as the ray tracer model's IG = GlobalAmbient * ka
    bool light_ambient = false;  ///< per-light ambient lightamb * ka (the ray tracer model Iamb, the GLSL ADS shader La * Ka)
    bool diffuse = true;         ///< kd * max(n.l, 0)
    specular_model specular = specular_model::phong; ///< the specular term: none, Phong (r.v) or Blinn (n.h)
    bool specular_gate = true;   ///< specular only where n.l > 0 (GLSL ADS); the ray tracer model has no gate
    light_kind lights = light_kind::any;  ///< which lights the list holds (any: w read per light)
    attenuation_model attenuation = attenuation_model::none; ///< the distance falloff f_i
    spot_model spot = spot_model::none;   ///< the spot cone factor
    bool attenuate_ambient = true; ///< f_i and the spot also scale the per-light ambient (OpenGL)
    facing two_sided = facing::none;      ///< how a back face is lit (none, by the view, by a flag)
    view_model view = view_model::eye_at_origin; ///< where the view vector comes from
    bool emission = false;       ///< material emission added
    bool alpha = false;          ///< return rgba with the material's alpha appended
    evaluation mode = evaluation::exact;  ///< exact, stable or fast arithmetic
    stable_precision precision = stable_precision::wider; ///< stable mode only: wider (float in double) or twofold
    /// Stable mode with twofold precision only: 0 (the default) carries every pair twofold, the accuracy that
    /// phong/accuracy.hpp publishes. M > 0 rounds each component once for pairs with shininess
    /// m <= M (Blinn: unless l + v nearly cancels), at a lower cost, at an error that
    /// grows like sqrt(m) eps (figures: docs/accuracy.md, tests/stable_hybrid.test.cpp); every
    /// target of the stable mode is met. Higher m stays twofold.
    /// Not read by float SIMD batches on x86 (their double-lane route is more accurate than
    /// either depth) but for steps with m above 2^20, which take the twofold route.
    unsigned stable_twofold_above = 0;
    /// The normal (and, for view_model::given, the view vector; for fixed_direction,
    /// environment::eye.xyz) come at unit length: used as
    /// given, with no normalization and no length guards (checked in debug builds). For the
    /// exact mode; the stable mode normalizes anyway (its accuracy needs the exact unit vectors).
    /// Pre: unit length within 1e-3, finite. A zero or NaN vector breaks the precondition: the
    /// NaN policy (NaN in, NaN out) is then not kept.
    bool unit_inputs = false;

    /// The same feature set with one field changed: the one way a feature set is derived from
    /// another (a preset, or features{}), in any order and chained, with no designated-initializer
    /// order to keep (C++20 wants designators in declaration order):
    ///   constexpr features F = presets::raytracer_phong.with_unit_inputs(true).with_specular_gate(false);
    ///   constexpr features G = features{}.with_lights(light_kind::directional).with_view(view_model::fixed_direction);
    /// Each returns a copy; the value it is called on is unchanged.
    PHONG_INLINE constexpr features with_scene_ambient(bool value) const { features f = *this; f.scene_ambient = value; return f; } ///< a copy with scene_ambient = value
    PHONG_INLINE constexpr features with_light_ambient(bool value) const { features f = *this; f.light_ambient = value; return f; } ///< a copy with light_ambient = value
    PHONG_INLINE constexpr features with_diffuse(bool value) const { features f = *this; f.diffuse = value; return f; } ///< a copy with diffuse = value
    PHONG_INLINE constexpr features with_specular(specular_model value) const { features f = *this; f.specular = value; return f; } ///< a copy with specular = value
    PHONG_INLINE constexpr features with_specular_gate(bool value) const { features f = *this; f.specular_gate = value; return f; } ///< a copy with specular_gate = value
    PHONG_INLINE constexpr features with_lights(light_kind value) const { features f = *this; f.lights = value; return f; } ///< a copy with lights = value
    PHONG_INLINE constexpr features with_attenuation(attenuation_model value) const { features f = *this; f.attenuation = value; return f; } ///< a copy with attenuation = value
    PHONG_INLINE constexpr features with_spot(spot_model value) const { features f = *this; f.spot = value; return f; } ///< a copy with spot = value
    PHONG_INLINE constexpr features with_attenuate_ambient(bool value) const { features f = *this; f.attenuate_ambient = value; return f; } ///< a copy with attenuate_ambient = value
    PHONG_INLINE constexpr features with_two_sided(facing value) const { features f = *this; f.two_sided = value; return f; } ///< a copy with two_sided = value
    PHONG_INLINE constexpr features with_view(view_model value) const { features f = *this; f.view = value; return f; } ///< a copy with view = value
    PHONG_INLINE constexpr features with_emission(bool value) const { features f = *this; f.emission = value; return f; } ///< a copy with emission = value
    PHONG_INLINE constexpr features with_alpha(bool value) const { features f = *this; f.alpha = value; return f; } ///< a copy with alpha = value
    PHONG_INLINE constexpr features with_mode(evaluation value) const { features f = *this; f.mode = value; return f; } ///< a copy with mode = value
    PHONG_INLINE constexpr features with_precision(stable_precision value) const { features f = *this; f.precision = value; return f; } ///< a copy with precision = value
    PHONG_INLINE constexpr features with_stable_twofold_above(unsigned value) const { features f = *this; f.stable_twofold_above = value; return f; } ///< a copy with stable_twofold_above = value
    PHONG_INLINE constexpr features with_unit_inputs(bool value) const { features f = *this; f.unit_inputs = value; return f; } ///< a copy with unit_inputs = value
};

/// A feature set as a type, for templating a CUDA kernel on it: nvcc 13 rejects a class-type
/// non-type parameter on a __global__ template (`template <phong::features F> __global__`: its
/// host stub names the argument as an undeclared identifier), and takes
/// `template <class Set> __global__ void k(...)` calling shade<Set::value>, launched as
/// k<phong::feature_set<F>><<<...>>>(...). Any other code may use it too (docs/cuda.md).
template <features F> struct feature_set {
    static constexpr features value = F; ///< the feature set, for shade<Set::value>
};

/// Ready-made feature sets, named for the model they compute. docs/models.md maps each source
/// document and each of its terms to them.
namespace presets {

/// Classic eye-space Phong (the OpenGL fixed-function model; source document 000):
///   I = ka La + sum_i f_i(Q) L_i (kd max(n.l_i, 0) + ks max(r_i.v, 0)^m),  r_i = reflect(-l_i, n),
/// polynomial attenuation f_i = 1/(c0 + c1 d + c2 d^2) for positional lights (w = 1; w = 0 is
/// directional), the normal negated where it faces away from the viewer, alpha appended, the
/// viewer at environment::eye (eye_from_projection(projection): perspective or orthographic).
/// n.l and r.v are clamped at 0 (as in every shader of that model), specular not gated.
inline constexpr features classic_phong{
    .scene_ambient = true, .light_ambient = false, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = false, .lights = light_kind::any,
    .attenuation = attenuation_model::polynomial, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::view, .view = view_model::eye_point,
    .emission = false, .alpha = true, .mode = evaluation::exact};

/// Blinn-Phong with an ambient strength per light (source document 001's ray tracer):
///   I = ka La + sum_i (ka La_i + kd Ld_i max(n.l_i, 0) + ks Ls_i max(n.h_i, 0)^m),
///   h_i = normalize(l_i + v),
/// positional lights, no attenuation, no specular gate (as written), the viewer at
/// environment::eye (the camera position, w = 1: right for primary rays; pass v per call with
/// view_model::given for secondary rays, as presets::raytracer_phong does).
inline constexpr features blinn_phong_per_light_ambient{
    .scene_ambient = true, .light_ambient = true, .diffuse = true,
    .specular = specular_model::blinn, .specular_gate = false, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::eye_point,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// A Whitted ray tracer's Phong: I = ka La + sum_i (kd Ld_i max(n.l_i, 0) + [n.l_i > 0] ks Ls_i
/// max(r_i.v, 0)^m), positional lights, and the view vector given per call (v = -ray.dir: right
/// for primary, reflected and refracted rays). Shadows: pass the visible lights (phong::masked,
/// phong::weighted, or any filtered range). Set .unit_inputs = true when n and v are unit already.
inline constexpr features raytracer_phong{
    .scene_ambient = true, .light_ambient = false, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = true, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::given,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// GLSL ambient-diffuse-specular per vertex (source document 003's phong.vert, shade_vertex):
///   La Ka + Ld Kd max(s.n, 0) + [s.n > 0] Ls Ks max(r.v, 0)^f,  r = reflect(-s, n),
/// v = normalize(-eyeCoords) (the eye at the origin of eye coordinates), positional lights.
inline constexpr features glsl_ads{
    .scene_ambient = false, .light_ambient = true, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = true, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::eye_at_origin,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// Diffuse only (Lambert; source document 003's diffuse.vert): Ld Kd max(s.n, 0).
inline constexpr features diffuse_only{
    .scene_ambient = false, .light_ambient = false, .diffuse = true,
    .specular = specular_model::none, .specular_gate = true, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::eye_at_origin,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// Older names, after the source documents (docs/models.md): aliases of classic_phong,
/// blinn_phong_per_light_ambient, glsl_ads and diffuse_only, kept for existing code.

/// The same feature set evaluated in another mode (e.g. with_mode(classic_phong, evaluation::stable)).
PHONG_INLINE constexpr features with_mode(features f, evaluation mode)
{
    return f.with_mode(mode);
}

} // namespace presets
} // namespace phong
