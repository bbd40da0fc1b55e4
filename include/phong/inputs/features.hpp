// phong: `features`, the compile-time description of what a scene needs: a structural aggregate
// passed to shade<F>; every optional term sits behind `if constexpr` on one of its fields.
// SPDX-License-Identifier: MIT
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

/// How the view vector v (from the point toward the viewer) is found.
///  * `eye_at_origin` (default): v = normalize(-Q), eye coordinates (classic Phong, 003).
///  * `given`: v passed to each shade call (a ray tracer's -ray.dir); use it whenever the renderer has v.
///  * `fixed_direction`: v = environment::eye.xyz for every point (orthographic cameras).
///  * `eye_point`: v = normalize(E.xyz - E.w Q), E = environment::eye (eye_from_projection() makes it).
enum class view_model : unsigned char {
    eye_at_origin,
    fixed_direction,
    eye_point,
    given,
};

/// How the terms are evaluated (bounds in phong/accuracy.hpp; docs/accuracy.md).
/// `exact`: the formulas as written, guarded so they never give NaN/Inf for finite input.
/// `stable`: a few ulp or better on stiff and extreme inputs (route: features::precision); for
/// m beyond ~1/eps^2 a highlight is as uncertain as the inputs' last bits.
/// `fast`: the exact mode's guards with the power and 1/|d| from core/fast_math.hpp (8-bit pixels).
enum class evaluation : unsigned char { exact, stable, fast };

/// Where the stable mode's extra precision comes from (choice for GPUs: docs/cuda.md).
/// `wider` (default): float evaluated in double and rounded once (about 0.5 ulp); double takes `twofold`.
/// `twofold`: T arithmetic, rescaled vectors, twofold unit vectors, n.l and chords (core/twofold.hpp).
/// Float SIMD batches on x86 read neither (double-lane geometry, ext/simd/stable_lanes.hpp).
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
    /// Stable twofold mode only: 0 (default) carries every pair twofold; M > 0 rounds pairs with
    /// shininess m <= M once, cheaper, error growing like sqrt(m) eps (docs/accuracy.md).
    unsigned stable_twofold_above = 0;
    /// n (and a given or fixed v) come at unit length within 1e-3, finite: no normalization or
    /// guards (exact mode; checked in debug builds). A zero or NaN vector voids the NaN policy.
    bool unit_inputs = false;

    /// A copy with one field changed, chainable in any order (designators must keep declaration order):
    ///   presets::raytracer_phong.with_unit_inputs(true).with_specular_gate(false)
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

/// A feature set as a type, e.g. for a CUDA __global__ template (nvcc takes no class-type
/// non-type parameter there): k<phong::feature_set<F>> calling shade<Set::value> (docs/cuda.md).
template <features F> struct feature_set {
    static constexpr features value = F; ///< the feature set, for shade<Set::value>
};

/// Ready-made feature sets, named for the model they compute (docs/models.md).
namespace presets {

/// Classic eye-space Phong (OpenGL fixed function; document 000), polynomial attenuation,
/// two-sided by the view, alpha, viewer at environment::eye, specular not gated:
///   I = ka La + sum_i f_i(Q) L_i (kd max(n.l_i, 0) + ks max(r_i.v, 0)^m),  r_i = reflect(-l_i, n)
inline constexpr features classic_phong{
    .scene_ambient = true, .light_ambient = false, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = false, .lights = light_kind::any,
    .attenuation = attenuation_model::polynomial, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::view, .view = view_model::eye_point,
    .emission = false, .alpha = true, .mode = evaluation::exact};

/// Blinn-Phong with per-light ambient (document 001's ray tracer), positional lights, no gate,
/// viewer at environment::eye (primary rays; secondary rays: view_model::given):
///   I = ka La + sum_i (ka La_i + kd Ld_i max(n.l_i, 0) + ks Ls_i max(n.h_i, 0)^m), h_i = normalize(l_i + v)
inline constexpr features blinn_phong_per_light_ambient{
    .scene_ambient = true, .light_ambient = true, .diffuse = true,
    .specular = specular_model::blinn, .specular_gate = false, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::eye_point,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// A Whitted ray tracer's Phong, positional lights, v = -ray.dir given per call (shadows: pass
/// the visible lights, phong::masked / phong::weighted):
///   I = ka La + sum_i (kd Ld_i max(n.l_i, 0) + [n.l_i > 0] ks Ls_i max(r_i.v, 0)^m)
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


/// The same feature set evaluated in another mode (e.g. with_mode(classic_phong, evaluation::stable)).
PHONG_INLINE constexpr features with_mode(features f, evaluation mode)
{
    return f.with_mode(mode);
}

} // namespace presets
} // namespace phong
