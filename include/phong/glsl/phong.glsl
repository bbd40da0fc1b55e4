// phong.glsl: the GLSL twin of phong's C++ model (include/phong/*.hpp), for GLSL 3.30 core and
// later and GLSL ES 3.00 and later. SPDX-License-Identifier: MIT
//
// No #version line: the including program's comes first. GLSL has no #include, so a program
// passes the strings in order to glShaderSource: its #version line, its feature #defines (or one
// preset define), this file's text, then its own shader (docs/glsl.md; phong/glsl.hpp hands the
// text to a C++ program, PHONG_GLSL_DIR from find_package(phong) names the installed directory).
//
// Names: the C++ function phong::x is phong_x here, its struct phong::y is phong_y, with the
// same fields; the features fields are the PHONG_* defines below. The formulas are those of the
// C++ exact mode (detail/exact.hpp), step by step, so that a shader's colour agrees with
// phong::shade<F> on float within the exact mode's bound plus the driver's own error of sqrt,
// division, inversesqrt and pow (tests/glsl/ measures them on Mesa llvmpipe; docs/glsl.md).
//
// Edge policy, as in C++: no NaN or inf from finite input in range (a light at the point, a zero
// normal, Blinn's l = -v, the point at the eye, m = 0, c0 = 0 with d = 0): each function says
// what it returns there. Non-finite input: GLSL 3.30 and ES 3.00 do not require NaN or inf to
// exist (ES may flush or clamp them), so the C++ NaN policy (NaN in, NaN out) is not promised here.
//
// ---- Feature selection: #define before this file (1 = on, 0 = off; enums by name) -------------
//   PHONG_PRESET_CLASSIC_PHONG, PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT,
//   PHONG_PRESET_RAYTRACER_PHONG, PHONG_PRESET_GLSL_ADS, PHONG_PRESET_DIFFUSE_ONLY: the C++ presets
//   (phong::presets::*); a field #defined as well overrides the preset's value.
//   PHONG_SCENE_AMBIENT, PHONG_LIGHT_AMBIENT, PHONG_DIFFUSE     features::scene_ambient, light_ambient, diffuse
//   PHONG_SPECULAR = PHONG_SPECULAR_NONE | _PHONG | _BLINN        features::specular
//   PHONG_SPECULAR_GATE                                          features::specular_gate
//   PHONG_LIGHTS = PHONG_LIGHTS_ANY | _POSITIONAL | _DIRECTIONAL  features::lights
//   PHONG_ATTENUATION = PHONG_ATTENUATION_NONE | _POLYNOMIAL | _WINDOWED   features::attenuation
//   PHONG_SPOT = PHONG_SPOT_NONE | _OPENGL | _SMOOTH | _LINEAR   features::spot (a light whose
//                                                                spot.direction is 0 has no cone)
//   PHONG_ATTENUATE_AMBIENT                                      features::attenuate_ambient
//   PHONG_TWO_SIDED = PHONG_FACING_NONE | _VIEW | _FLAG          features::two_sided
//   PHONG_VIEW = PHONG_VIEW_EYE_AT_ORIGIN | _FIXED_DIRECTION | _EYE_POINT | _GIVEN   features::view
//   PHONG_EMISSION, PHONG_ALPHA, PHONG_UNIT_INPUTS               features::emission, alpha, unit_inputs
//   PHONG_MODE = PHONG_MODE_EXACT | PHONG_MODE_FAST              features::mode (no stable mode in GLSL)
//   PHONG_MAX_LIGHTS (default 8): the size of the light arrays phong_shade takes.
//   PHONG_SPOT_LIGHTS (default PHONG_MAX_LIGHTS): with PHONG_SPOT, only lights[0 ..
//   PHONG_SPOT_LIGHTS - 1] may have a cone; the others have none and their spot fields are not
//   read (put the spot lights first). Within them a zero spot.direction is no cone too.
// Defaults (no preset): the C++ `features{}`: scene ambient, diffuse, gated Phong specular,
// lights of any kind, eye at the origin, exact mode.

// The language: this file is GLSL, and the HLSL twin (include/phong/hlsl/phong.hlsl) is this file
// read through a few macros (vec3 -> float3, inversesqrt -> rsqrt, ...) that it defines, with
// PHONG_HLSL, before including it. The few constructs the two languages spell differently go
// through these names.
#ifndef PHONG_HLSL
#  define phong_const const                         // a global constant (HLSL: static const)
#  define phong_mul(M, v) ((M) * (v))               // matrix times column vector (HLSL: mul(M, v))
#  define phong_element(M, row, column) M[column][row] // GLSL indexes columns first (HLSL: M[row][column])
#  define PHONG_FALLOFF_LINEAR linear               // phong_falloff's field (HLSL reserves `linear`: linear_)
#endif

#define PHONG_SPECULAR_NONE 0
#define PHONG_SPECULAR_PHONG 1
#define PHONG_SPECULAR_BLINN 2
#define PHONG_LIGHTS_ANY 0
#define PHONG_LIGHTS_POSITIONAL 1
#define PHONG_LIGHTS_DIRECTIONAL 2
#define PHONG_ATTENUATION_NONE 0
#define PHONG_ATTENUATION_POLYNOMIAL 1
#define PHONG_ATTENUATION_WINDOWED 2
#define PHONG_SPOT_NONE 0
#define PHONG_SPOT_OPENGL 1
#define PHONG_SPOT_SMOOTH 2
#define PHONG_SPOT_LINEAR 3
#define PHONG_FACING_NONE 0
#define PHONG_FACING_VIEW 1
#define PHONG_FACING_FLAG 2
#define PHONG_VIEW_EYE_AT_ORIGIN 0
#define PHONG_VIEW_FIXED_DIRECTION 1
#define PHONG_VIEW_EYE_POINT 2
#define PHONG_VIEW_GIVEN 3
#define PHONG_MODE_EXACT 0
#define PHONG_MODE_FAST 2

// The presets (include/phong/inputs/features.hpp): only the fields not #defined already.
#if defined(PHONG_PRESET_CLASSIC_PHONG)
#  ifndef PHONG_SCENE_AMBIENT
#    define PHONG_SCENE_AMBIENT 1
#  endif
#  ifndef PHONG_LIGHT_AMBIENT
#    define PHONG_LIGHT_AMBIENT 0
#  endif
#  ifndef PHONG_SPECULAR_GATE
#    define PHONG_SPECULAR_GATE 0
#  endif
#  ifndef PHONG_LIGHTS
#    define PHONG_LIGHTS PHONG_LIGHTS_ANY
#  endif
#  ifndef PHONG_ATTENUATION
#    define PHONG_ATTENUATION PHONG_ATTENUATION_POLYNOMIAL
#  endif
#  ifndef PHONG_TWO_SIDED
#    define PHONG_TWO_SIDED PHONG_FACING_VIEW
#  endif
#  ifndef PHONG_VIEW
#    define PHONG_VIEW PHONG_VIEW_EYE_POINT
#  endif
#  ifndef PHONG_ALPHA
#    define PHONG_ALPHA 1
#  endif
#elif defined(PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT)
#  ifndef PHONG_LIGHT_AMBIENT
#    define PHONG_LIGHT_AMBIENT 1
#  endif
#  ifndef PHONG_SPECULAR
#    define PHONG_SPECULAR PHONG_SPECULAR_BLINN
#  endif
#  ifndef PHONG_SPECULAR_GATE
#    define PHONG_SPECULAR_GATE 0
#  endif
#  ifndef PHONG_LIGHTS
#    define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
#  endif
#  ifndef PHONG_VIEW
#    define PHONG_VIEW PHONG_VIEW_EYE_POINT
#  endif
#elif defined(PHONG_PRESET_RAYTRACER_PHONG)
#  ifndef PHONG_LIGHTS
#    define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
#  endif
#  ifndef PHONG_VIEW
#    define PHONG_VIEW PHONG_VIEW_GIVEN
#  endif
#elif defined(PHONG_PRESET_GLSL_ADS)
#  ifndef PHONG_SCENE_AMBIENT
#    define PHONG_SCENE_AMBIENT 0
#  endif
#  ifndef PHONG_LIGHT_AMBIENT
#    define PHONG_LIGHT_AMBIENT 1
#  endif
#  ifndef PHONG_LIGHTS
#    define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
#  endif
#elif defined(PHONG_PRESET_DIFFUSE_ONLY)
#  ifndef PHONG_SCENE_AMBIENT
#    define PHONG_SCENE_AMBIENT 0
#  endif
#  ifndef PHONG_SPECULAR
#    define PHONG_SPECULAR PHONG_SPECULAR_NONE
#  endif
#  ifndef PHONG_LIGHTS
#    define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
#  endif
#endif

// The defaults of phong::features{}.
#ifndef PHONG_SCENE_AMBIENT
#  define PHONG_SCENE_AMBIENT 1
#endif
#ifndef PHONG_LIGHT_AMBIENT
#  define PHONG_LIGHT_AMBIENT 0
#endif
#ifndef PHONG_DIFFUSE
#  define PHONG_DIFFUSE 1
#endif
#ifndef PHONG_SPECULAR
#  define PHONG_SPECULAR PHONG_SPECULAR_PHONG
#endif
#ifndef PHONG_SPECULAR_GATE
#  define PHONG_SPECULAR_GATE 1
#endif
#ifndef PHONG_LIGHTS
#  define PHONG_LIGHTS PHONG_LIGHTS_ANY
#endif
#ifndef PHONG_ATTENUATION
#  define PHONG_ATTENUATION PHONG_ATTENUATION_NONE
#endif
#ifndef PHONG_SPOT
#  define PHONG_SPOT PHONG_SPOT_NONE
#endif
#ifndef PHONG_ATTENUATE_AMBIENT
#  define PHONG_ATTENUATE_AMBIENT 1
#endif
#ifndef PHONG_TWO_SIDED
#  define PHONG_TWO_SIDED PHONG_FACING_NONE
#endif
#ifndef PHONG_VIEW
#  define PHONG_VIEW PHONG_VIEW_EYE_AT_ORIGIN
#endif
#ifndef PHONG_EMISSION
#  define PHONG_EMISSION 0
#endif
#ifndef PHONG_ALPHA
#  define PHONG_ALPHA 0
#endif
#ifndef PHONG_UNIT_INPUTS
#  define PHONG_UNIT_INPUTS 0
#endif
#ifndef PHONG_MODE
#  define PHONG_MODE PHONG_MODE_EXACT
#endif
#ifndef PHONG_MAX_LIGHTS
#  define PHONG_MAX_LIGHTS 8
#endif
#ifndef PHONG_SPOT_LIGHTS
#  define PHONG_SPOT_LIGHTS PHONG_MAX_LIGHTS
#endif
#if PHONG_MODE != PHONG_MODE_EXACT && PHONG_MODE != PHONG_MODE_FAST
#  error "phong.glsl: PHONG_MODE must be PHONG_MODE_EXACT or PHONG_MODE_FAST (the stable mode needs double or twofold arithmetic: C++ only)"
#endif
#if PHONG_MAX_LIGHTS < 1
#  error "phong.glsl: PHONG_MAX_LIGHTS must be at least 1"
#endif
#if PHONG_SPOT_LIGHTS < 0 || PHONG_SPOT_LIGHTS > PHONG_MAX_LIGHTS
#  error "phong.glsl: PHONG_SPOT_LIGHTS must be in [0, PHONG_MAX_LIGHTS]"
#endif

// The specular gate matters only with a specular term (features.hpp's detail::gated).
#if PHONG_SPECULAR_GATE || PHONG_SPECULAR == PHONG_SPECULAR_NONE
#  define PHONG_GATED 1
#else
#  define PHONG_GATED 0
#endif

#ifdef GL_ES
// The model needs float's range and precision: ES fragment shaders have no default precision.
precision highp float;
precision highp int;
#endif

// ---- Types: phong::falloff, spot_cone, light, material, environment, shading_terms ------------

/// phong::falloff: OpenGL's constant, linear and quadratic attenuation (c0, c1, c2 >= 0,
/// c0 + c1 + c2 > 0) and the windowed model's range (> 0; a huge value for no window: GLSL ES need
/// not have inf).
struct phong_falloff {
    float constant;
    float PHONG_FALLOFF_LINEAR; // `linear`: the macro spells it for HLSL, where linear is reserved
    float quadratic;
    float range;
};

/// phong::spot_cone: the unit axis s from the light outward (zero: no cone, whatever the other
/// fields hold: the default of a uniform), OpenGL's exponent e >= 0 and cos cutoff (in [0, 1], or
/// -1: no spot), the smooth and linear models' cos_inner >= cos_outer (-1 and -1: no spot).
struct phong_spot_cone {
    vec3 direction;
    float exponent;
    float cos_cutoff;
    float cos_inner;
    float cos_outer;
};

/// phong::light: homogeneous position (w = 1 positional, w = 0 directional), per-light ambient,
/// diffuse and specular strengths, falloff (read with PHONG_ATTENUATION), spot (with PHONG_SPOT).
struct phong_light {
    vec4 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    phong_falloff attenuation;
    phong_spot_cone spot;
};

/// phong::material: ka, kd, ks, emission >= 0; shininess m >= 0; alpha in [0, 1].
struct phong_material {
    vec3 ka;
    vec3 kd;
    vec3 ks;
    vec3 emission;
    float shininess;
    float alpha;
};

/// phong::environment: the scene's ambient La >= 0 and the eye as a homogeneous point (read by
/// PHONG_VIEW_EYE_POINT: w = 1 a point, w = 0 a direction; PHONG_VIEW_FIXED_DIRECTION: xyz).
struct phong_environment {
    vec3 ambient;
    vec4 eye;
};

/// phong::shading_terms: emission, ambient, diffuse, specular (rgb each) and alpha; their sum in
/// that order is phong_shade's colour.
struct phong_shading_terms {
    vec3 emission;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float alpha;
};

// ---- Constants --------------------------------------------------------------------------------

/// The smallest normal float, 2^-126 (exact_min_square<float>): a squared length below it is
/// not used (its vector is taken as 0), as in the C++ exact mode.
phong_const float phong_min_square = 1.17549435e-38;
/// The largest float (largest<float>): a squared length above it overflowed.
phong_const float phong_largest = 3.40282347e38;
/// attenuation_denominator_min<float> = 2^-63: the floor under an attenuation's denominator.
phong_const float phong_attenuation_denominator_min = 1.08420217e-19;
/// Blinn: |l + v|^2 below 2^-48 = u^2 is taken as l = -v (no halfway vector). A GLSL compiler
/// may fuse l = d / |d| with the sum (no `precise` in GLSL 3.30 / ES 3.00), after which l = -v
/// leaves |l + v| of a few rounding errors, not 0; the C++ SIMD lanes use the same threshold.
phong_const float phong_halfway_min_square = 3.55271368e-15;

/// 1/sqrt(x) as the mode takes it: the exact mode divides by sqrt (the C++ rsqrt, two
/// roundings); the fast mode takes GLSL's inversesqrt (the hardware's estimate; C++: fast::rsqrt).
#if PHONG_MODE == PHONG_MODE_FAST
#  define phong_rsqrt(x) inversesqrt(x)
#else
#  define phong_rsqrt(x) (1.0 / sqrt(x))
#endif

// ---- Building blocks (C++: vector.hpp, direction.hpp, attenuation.hpp, specular.hpp, ...) ------

/// detail::exact_inverse_length: 1/|v| from dd = |v|^2 (phong_rsqrt); 0 when dd is not a normal
/// float (a zero or underflowed vector; an overflowed one).
float phong_exact_inverse_length(float dd)
{
    return (dd >= phong_min_square && dd <= phong_largest) ? phong_rsqrt(dd) : 0.0;
}

/// phong::normalize: v / |v|, scaled first by a power of two (exact) that brings its largest
/// component into [1, 2) ([2, 4) beyond 2^127), so that huge and tiny vectors survive. Edge: normalize(0) = 0 (GLSL's
/// normalize(0) is undefined). Branch-free: SIMD shader compilers (llvmpipe's) run both sides of
/// a branch whose lanes disagree.
vec3 phong_normalize(vec3 v)
{
    float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    // 2^(127 - e) for m's biased exponent e, at least 2^-126 (for m beyond 2^127)
    int e = int(floatBitsToUint(m) >> 23);
    float scale = uintBitsToFloat(uint(max(254 - e, 1)) << 23);
    vec3 s = v * scale;
    return (m > 0.0 && m <= phong_largest) ? s * phong_rsqrt(dot(s, s)) : vec3(0.0, 0.0, 0.0);
}

/// phong::pow_unit: x^m for a base x in [0, 1] and m >= 0, with pow(0, 0) = 1 and 0^m = 0 for
/// m > 0 (GLSL's pow is undefined at x = 0, m <= 0). A base below 0 is taken as 0, above 1 as 1.
/// Accuracy: the driver's pow.
float phong_pow_unit(float x, float m)
{
    // pow(max(x, 0), m): defined for m > 0 (0 at a base <= 0); pow's undefined value at m = 0 is
    // never selected. min(..., 1) gives 1 for a base above 1, as its clamp to 1 would (1^m = 1),
    // and stays finite where pow overflows. The form a hand-written shader uses (pow(max(r.v, 0),
    // m)); docs/glsl.md compares it with the other forms.
    float p = min(pow(max(x, 0.0), m), 1.0);
    return m == 0.0 ? 1.0 : p;
}

/// phong::toward: the unit vector from the point q toward the homogeneous point P,
///   direction = normalize(P.xyz - P.w q),  distance = |P.xyz - P.w q| / P.w (P.w > 0).
/// Returns the direction; distance gets the distance, or phong_largest for P.w = 0 (C++: +inf).
/// Pre: P.w >= 0. Edge: P at q (w > 0): direction 0, distance 0; P.xyz = 0 with w = 0: direction 0.
vec3 phong_toward(vec4 P, vec3 q, out float distance)
{
    vec3 d = P.xyz - P.w * q;
    float w = P.w > 0.0 ? P.w : 1.0;
    distance = P.w > 0.0 ? length(d) / w : phong_largest;
    return phong_normalize(d);
}

/// phong::light_direction: classic Phong's l-hat = normalize(L.xyz - L.w q) (w = 1 or 0).
/// Edge: a light at q gives 0.
vec3 phong_light_direction(vec4 L, vec3 q)
{
    return phong_normalize(L.xyz - L.w * q);
}

/// phong::attenuation_polynomial (classic Phong's f_i(Q), OpenGL):
///   f = 1 / max(c0 + d (c1 + c2 d), 2^-63).
/// Pre: c0, c1, c2 >= 0, d >= 0. Edge: d = 0 with c0 = 0 gives the cap 2^63 (finite).
float phong_attenuation_polynomial(float d, float c0, float c1, float c2)
{
    d = min(d, phong_largest);
    return 1.0 / max(c0 + d * (c1 + c2 * d), phong_attenuation_denominator_min);
}

/// phong::attenuation_windowed (Filament, three.js):
///   f = clamp(1 - (d / range)^4, 0, 1)^2 / max(d^2, 2^-63).
/// Pre: range > 0, d >= 0. Edge: 0 for d >= range; finite at d = 0 (cap 2^63).
float phong_attenuation_windowed(float d, float range)
{
    d = min(d, phong_largest);
    float ratio = min(d / range, 65536.0);
    float r2 = ratio * ratio;
    float window = clamp(1.0 - r2 * r2, 0.0, 1.0);
    return window * window / max(d * d, phong_attenuation_denominator_min);
}

/// phong::spot_opengl: c = dot(-l, s); c >= cos_cutoff ? clamp(c, 0, 1)^e : 0; cos_cutoff <= -1
/// (180 degrees) gives 1. Pre: l, s unit (or l = 0), e >= 0. Edge: l = 0 gives c = 0; e = 0 a hard
/// cone of strength 1.
float phong_spot_opengl(vec3 l, vec3 s, float exponent, float cos_cutoff)
{
    if (cos_cutoff <= -1.0) return 1.0;
    float c = -dot(l, s);
    return c >= cos_cutoff ? phong_pow_unit(clamp(c, 0.0, 1.0), exponent) : 0.0;
}

/// phong::spot_smooth: t = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1), t^2 (3 - 2 t),
/// c = dot(-l, s). Pre: cos_outer <= cos_inner. Edge: cos_inner = cos_outer gives a hard edge
/// (1 where c >= cos_outer), no division by 0.
float phong_spot_smooth(vec3 l, vec3 s, float cos_inner, float cos_outer)
{
    float c = -dot(l, s);
    float width = cos_inner - cos_outer;
    if (!(width > 0.0)) return c >= cos_outer ? 1.0 : 0.0;
    float t = clamp((c - cos_outer) / width, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// phong::spot_linear: clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1), c = dot(-l, s): the
/// straight edge between the cones (LearnOpenGL's flashlight). Pre: cos_outer <= cos_inner.
/// Edge: cos_inner = cos_outer gives a hard edge (1 where c >= cos_outer), no division by 0.
float phong_spot_linear(vec3 l, vec3 s, float cos_inner, float cos_outer)
{
    float c = -dot(l, s);
    float width = cos_inner - cos_outer;
    if (!(width > 0.0)) return c >= cos_outer ? 1.0 : 0.0;
    return clamp((c - cos_outer) / width, 0.0, 1.0);
}

/// detail::cosine_power: the specular power of c = x * scale, min(max(c, 0), 1)^m with
/// pow(0, 0) = 1 (x: the cosine times a length scale >= 0, so c is of x's sign or 0; pow_unit
/// takes c <= 0 as 0 and c > 1 as 1).
float phong_cosine_power(float x, float scale, float m)
{
    return phong_pow_unit(x * scale, m);
}

/// phong::specular_reflection (Phong, classic Phong and 003):
///   r = reflect(-l, n) = 2 (n.l) n - l,  s = [n.l > 0] max(r.v, 0)^m,  r.v = 2 (n.l)(n.v) - l.v.
/// Pre: n, l, v unit (or 0), m >= 0. Edge: 0 where n.l <= 0; m = 0 gives 1 where lit; l = 0 or
/// v = 0 give 0 (m > 0).
float phong_specular_reflection(vec3 n, vec3 l, vec3 v, float m)
{
    float nl = dot(n, l);
    float s = phong_cosine_power(2.0 * nl * dot(n, v) - dot(l, v), 1.0, m);
    return nl > 0.0 ? s : 0.0;
}

/// detail::inverse_halfway_length: 1/|l + v|, or 0 where |l + v|^2 < phong_halfway_min_square
/// (l = -v: no halfway vector).
float phong_inverse_halfway_length(vec3 l, vec3 v)
{
    vec3 h = l + v;
    float hh = dot(h, h);
    return hh >= phong_halfway_min_square ? phong_exact_inverse_length(hh) : 0.0;
}

/// phong::specular_halfway (Blinn-Phong, the ray tracer model):
///   h = normalize(l + v),  s = [n.l > 0] max(n.h, 0)^m,  n.h = (n.l + n.v) / |l + v|.
/// Pre: n, l, v unit (or 0), m >= 0. Edge: l = -v takes n.h = 0 (0 for m > 0, 1 for m = 0);
/// 0 where n.l <= 0.
float phong_specular_halfway(vec3 n, vec3 l, vec3 v, float m)
{
    float nl = dot(n, l);
    float s = phong_cosine_power(nl + dot(n, v), phong_inverse_halfway_length(l, v), m);
    return nl > 0.0 ? s : 0.0;
}

/// phong::face_viewer (classic Phong's conditional negation): dot(n, v) < 0 ? -n : n.
/// Edge: dot(n, v) = 0 or n = 0 keeps n.
vec3 phong_face_viewer(vec3 n, vec3 v)
{
    return dot(n, v) < 0.0 ? -n : n;
}

/// phong::face_flag: front_facing ? n : -n (pass gl_FrontFacing in a fragment shader).
vec3 phong_face_flag(vec3 n, bool front_facing)
{
    return front_facing ? n : -n;
}

/// phong::view_perspective (classic Phong): v = normalize(-q), the eye at the origin.
/// Edge: q = 0 gives 0.
vec3 phong_view_perspective(vec3 q)
{
    return phong_normalize(-q);
}

/// phong::view_orthographic (classic Phong): v = normalize(-M02/M00, -M12/M11, 1), M = ec_lds the
/// projection matrix (M02: row 0, column 2, GLSL's M[2][0]). Pre: M00 != 0, M11 != 0.
vec3 phong_view_orthographic(mat4 ec_lds)
{
    return phong_normalize(vec3(-phong_element(ec_lds, 0, 2) / phong_element(ec_lds, 0, 0), -phong_element(ec_lds, 1, 2) / phong_element(ec_lds, 1, 1), 1.0));
}

/// phong::view_vector: v = normalize(E.xyz - E.w q) for the homogeneous eye E (w = 1 a point, w =
/// 0 a direction). Edge: q at the eye gives 0.
vec3 phong_view_vector(vec4 eye, vec3 q)
{
    return phong_normalize(eye.xyz - eye.w * q);
}

/// phong::transform_normal: normalize(N n) for a normal matrix N (GLSL's NormalMatrix, the
/// inverse transpose of the model-view's upper 3x3: the GLSL ADS shader's tnorm). Edge: a zero result stays 0.
vec3 phong_transform_normal(mat3 N, vec3 n)
{
    return phong_normalize(phong_mul(N, n));
}

// ---- The model at a point (C++: detail/exact.hpp's prepare, add_light; shade.hpp's terms_of) ---

/// The per-point frame: detail::exact::surface_frame.
struct phong_frame {
    vec3 position;    ///< Q
    vec3 normal;      ///< unit normal after two-sided negation (0 if none)
    vec3 view;        ///< unit view vector (0 if none)
    bool defined;     ///< the normal is nonzero: diffuse and specular can be on
    bool sees_viewer; ///< the view vector exists: specular can be on
    float nv;         ///< n.v
};

/// The per-light sums: detail::light_sums (ambient La_i f_i, diffuse Ld_i f_i max(n.l, 0),
/// specular Ls_i f_i s_i).
struct phong_sums {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

/// phong_prepare with the unit normal n given (n_ok: it exists; n = 0 otherwise): the view
/// vector, two-sided negation and n.v (for a shader whose normal is unit already, e.g. from
/// phong_transform_normal: no second normalization).
phong_frame phong_prepare_unit(vec3 q, vec3 n, bool n_ok, vec3 given_view, phong_environment env, bool front_facing)
{
    phong_frame s;
    s.position = q;
    vec3 v = vec3(0.0, 0.0, 0.0);
    bool v_ok = true;
#if PHONG_VIEW == PHONG_VIEW_FIXED_DIRECTION
    v = phong_normalize(env.eye.xyz);
    v_ok = dot(v, v) > 0.0;
#elif PHONG_SPECULAR != PHONG_SPECULAR_NONE || PHONG_TWO_SIDED == PHONG_FACING_VIEW
#  if PHONG_VIEW == PHONG_VIEW_GIVEN
#    if PHONG_UNIT_INPUTS
    v = given_view;
#    else
    float v_inv = phong_exact_inverse_length(dot(given_view, given_view));
    v = given_view * v_inv;
    v_ok = v_inv > 0.0;
#    endif
#  elif PHONG_VIEW == PHONG_VIEW_EYE_AT_ORIGIN
    float v_inv = phong_exact_inverse_length(dot(q, q));
    v = q * -v_inv;
    v_ok = v_inv > 0.0;
#  else
    vec3 e = env.eye.xyz - env.eye.w * q;
    float v_inv = phong_exact_inverse_length(dot(e, e));
    v = e * v_inv;
    v_ok = v_inv > 0.0;
#  endif
#endif
#if PHONG_TWO_SIDED == PHONG_FACING_VIEW
    n = phong_face_viewer(n, v);
#elif PHONG_TWO_SIDED == PHONG_FACING_FLAG
    n = phong_face_flag(n, front_facing);
#endif
    s.normal = n;
    s.view = v;
    s.defined = n_ok;
    s.sees_viewer = v_ok;
    s.nv = dot(n, v);
    return s;
}

/// detail::exact::prepare: the unit normal (two-sided: faced toward the viewer, or by
/// front_facing), the view vector per PHONG_VIEW (given_view: read for PHONG_VIEW_GIVEN only),
/// whether both exist, n.v. Edge: a zero normal gives defined = false (no diffuse, no specular);
/// no view vector (q at the eye, a zero given v) gives sees_viewer = false (no specular).
phong_frame phong_prepare(vec3 q, vec3 normal, vec3 given_view, phong_environment env, bool front_facing)
{
#if PHONG_UNIT_INPUTS
    return phong_prepare_unit(q, normal, true, given_view, env, front_facing);
#else
    float n_inv = phong_exact_inverse_length(dot(normal, normal));
    return phong_prepare_unit(q, normal * n_inv, n_inv > 0.0, given_view, env, front_facing);
#endif
}

/// detail::light_factor: f_i = attenuation(distance) * spot(l) for one light; distance = |L.xyz
/// - Q| (positional lights only: a directional light is not attenuated), l the unit light vector
/// (0 if none); cone: whether the light may have a cone (false: its spot fields are not read, as
/// for a zero axis). Pre: the light's parameters in phong::validate(light)'s domain.
float phong_light_factor(phong_light L, float distance, float w, vec3 l, bool cone)
{
    float f = 1.0;
#if PHONG_ATTENUATION != PHONG_ATTENUATION_NONE && PHONG_LIGHTS != PHONG_LIGHTS_DIRECTIONAL
#  if PHONG_ATTENUATION == PHONG_ATTENUATION_POLYNOMIAL
    float fa = phong_attenuation_polynomial(distance, L.attenuation.constant, L.attenuation.PHONG_FALLOFF_LINEAR, L.attenuation.quadratic);
#  else
    float fa = phong_attenuation_windowed(distance, L.attenuation.range);
#  endif
#  if PHONG_LIGHTS == PHONG_LIGHTS_ANY
    f = w > 0.0 ? fa : 1.0;
#  else
    f = fa;
#  endif
#endif
#if PHONG_SPOT != PHONG_SPOT_NONE
    // A zero axis is no cone (a light whose spot uniforms are left at 0 is lit). For lights in
    // uniforms the condition is the same on every pixel (a uniform branch).
    float axis2 = cone ? dot(L.spot.direction, L.spot.direction) : 0.0;
    if (axis2 > 0.0) {
        // The model reads the axis's direction (validate accepts it within 1e-3 of unit length).
        vec3 s = L.spot.direction * phong_rsqrt(axis2);
#  if PHONG_SPOT == PHONG_SPOT_OPENGL
        f *= phong_spot_opengl(l, s, L.spot.exponent, L.spot.cos_cutoff);
#  elif PHONG_SPOT == PHONG_SPOT_SMOOTH
        f *= phong_spot_smooth(l, s, L.spot.cos_inner, L.spot.cos_outer);
#  else
        f *= phong_spot_linear(l, s, L.spot.cos_inner, L.spot.cos_outer);
#  endif
    }
#endif
    return f;
}

/// detail::exact::add_light's scalars for one light: the factors its ambient, diffuse and
/// specular colours are scaled by (m: the shininess),
///   d = L.xyz - w Q,  l = d / |d|,  f = phong_light_factor,
///   x = f (or 1 without PHONG_ATTENUATE_AMBIENT),  y = f max(n.l, 0),  z = f s,
/// y and z for a lit pair only (the normal exists, |d|^2 a normal float, and, gated, n.l > 0),
/// 0 otherwise; s: Phong max(r.v, 0)^m with r.v = (2 (n.d)(n.v) - d.v) / |d|, Blinn max(n.h, 0)^m
/// with n.h = (n.l + n.v) / |l + v|. Edge: a light at Q (or a directional light with xyz = 0)
/// gives (x, 0, 0). cone: as for phong_light_factor (false: the light has no cone).
vec3 phong_light_weights(phong_frame s, phong_light L, float m, bool cone)
{
#if PHONG_LIGHTS == PHONG_LIGHTS_POSITIONAL
    float w = 1.0;
    vec3 d = L.position.xyz - s.position;
#elif PHONG_LIGHTS == PHONG_LIGHTS_DIRECTIONAL
    float w = 0.0;
    vec3 d = L.position.xyz;
#else
    float w = L.position.w;
    vec3 d = L.position.xyz - s.position * w;
#endif
    float dd = dot(d, d);
    float nd = dot(s.normal, d);
    vec3 l = vec3(0.0, 0.0, 0.0);
    float inv = 0.0;
#if PHONG_SPOT != PHONG_SPOT_NONE
    inv = phong_exact_inverse_length(dd);
    l = d * inv;
#endif
    float distance = 0.0;
#if PHONG_ATTENUATION != PHONG_ATTENUATION_NONE && PHONG_LIGHTS != PHONG_LIGHTS_DIRECTIONAL
    distance = sqrt(dd);
#endif
    float f = phong_light_factor(L, distance, w, l, cone);
    vec3 weights = vec3(0.0, 0.0, 0.0);
#if PHONG_LIGHT_AMBIENT
#  if PHONG_ATTENUATE_AMBIENT
    weights.x = f;
#  else
    weights.x = 1.0;
#  endif
#endif
    bool on = s.defined && dd >= phong_min_square && dd <= phong_largest;
#if PHONG_GATED
    on = on && nd > 0.0;
#endif
    // The pair's terms are selected by `on`, not branched over: shader compilers for SIMD lanes
    // (llvmpipe's) run both sides of a branch whose lanes disagree, and pay for the masks. An unlit
    // lane's values (|d| = 0: inf or NaN) are never selected.
#if PHONG_SPECULAR == PHONG_SPECULAR_NONE && PHONG_SPOT == PHONG_SPOT_NONE
    float nl = nd / sqrt(dd);
#else
#  if PHONG_SPOT == PHONG_SPOT_NONE
    inv = phong_rsqrt(dd);
#  endif
    float nl = nd * inv;
#endif
#if PHONG_DIFFUSE
#  if PHONG_GATED
    weights.y = on ? f * nl : 0.0;
#  else
    weights.y = on ? f * max(nl, 0.0) : 0.0;
#  endif
#endif
#if PHONG_SPECULAR == PHONG_SPECULAR_PHONG
    float power = phong_cosine_power(2.0 * nd * s.nv - dot(d, s.view), inv, m);
#elif PHONG_SPECULAR == PHONG_SPECULAR_BLINN
#  if PHONG_SPOT == PHONG_SPOT_NONE
    l = d * inv;
#  endif
    float power = phong_cosine_power(nl + s.nv, phong_inverse_halfway_length(l, s.view), m);
#endif
#if PHONG_SPECULAR != PHONG_SPECULAR_NONE
    weights.z = on && s.sees_viewer ? f * power : 0.0;
#endif
    return weights;
}

/// The light's colours scaled by its weights (phong_light_weights) added to the sums.
void phong_add_light_weighted(inout phong_sums sums, phong_light L, vec3 weights)
{
#if PHONG_LIGHT_AMBIENT
    sums.ambient += L.ambient * weights.x;
#endif
#if PHONG_DIFFUSE
    sums.diffuse += L.diffuse * weights.y;
#endif
#if PHONG_SPECULAR != PHONG_SPECULAR_NONE
    sums.specular += L.specular * weights.z;
#endif
}

/// detail::exact::add_light: one light's terms added to the sums (m: the shininess):
///   ambient += La x,  diffuse += Ld y,  specular += Ls z  with (x, y, z) = phong_light_weights
/// (the light's cone read with PHONG_SPOT; a zero spot axis is no cone).
void phong_add_light(inout phong_sums sums, phong_frame s, phong_light L, float m)
{
    phong_add_light_weighted(sums, L, phong_light_weights(s, L, m, true));
}

/// shade.hpp's terms_of: the model's terms from the per-light sums:
///   emission, ka (La + sum La_i f_i), kd sum Ld_i f_i max(n.l_i, 0), ks sum Ls_i f_i s_i, alpha.
phong_shading_terms phong_terms_of(phong_sums sums, phong_material mat, phong_environment env)
{
    phong_shading_terms t;
    t.emission = vec3(0.0, 0.0, 0.0);
    t.ambient = vec3(0.0, 0.0, 0.0);
    t.diffuse = vec3(0.0, 0.0, 0.0);
    t.specular = vec3(0.0, 0.0, 0.0);
    t.alpha = mat.alpha;
#if PHONG_EMISSION
    t.emission = mat.emission;
#endif
#if PHONG_SCENE_AMBIENT && PHONG_LIGHT_AMBIENT
    t.ambient = mat.ka * (env.ambient + sums.ambient);
#elif PHONG_SCENE_AMBIENT
    t.ambient = mat.ka * env.ambient;
#elif PHONG_LIGHT_AMBIENT
    t.ambient = mat.ka * sums.ambient;
#endif
#if PHONG_DIFFUSE
    t.diffuse = mat.kd * sums.diffuse;
#endif
#if PHONG_SPECULAR != PHONG_SPECULAR_NONE
    t.specular = mat.ks * sums.specular;
#endif
    return t;
}

/// The colour type: vec4 (rgb, alpha) with PHONG_ALPHA, else vec3 (C++: phong::color<F, T>).
#if PHONG_ALPHA
#  define phong_color vec4
#else
#  define phong_color vec3
#endif

/// shade.hpp's total_of: emission + ambient + diffuse + specular, in that order; alpha appended
/// with PHONG_ALPHA.
phong_color phong_total_of(phong_shading_terms t)
{
    vec3 c = t.emission;
#if PHONG_SCENE_AMBIENT || PHONG_LIGHT_AMBIENT
    c += t.ambient;
#endif
#if PHONG_DIFFUSE
    c += t.diffuse;
#endif
#if PHONG_SPECULAR != PHONG_SPECULAR_NONE
    c += t.specular;
#endif
#if PHONG_ALPHA
    return vec4(c, t.alpha);
#else
    return c;
#endif
}

/// The terms at a prepared point: every light's terms added (the first `count`), then terms_of.
phong_shading_terms phong_terms_at(phong_frame s, phong_material mat, phong_light lights[PHONG_MAX_LIGHTS], int count,
                                   phong_environment env)
{
    phong_sums sums;
    sums.ambient = vec3(0.0, 0.0, 0.0);
    sums.diffuse = vec3(0.0, 0.0, 0.0);
    sums.specular = vec3(0.0, 0.0, 0.0);
    // Two loops: the first PHONG_SPOT_LIGHTS lights, whose cones are read, then the others, which
    // have none (their spot fields are not read).
#if PHONG_MAX_LIGHTS == 1
    // One light: no loop, its fields read at a constant index.
    if (count > 0)
        phong_add_light_weighted(sums, lights[0], phong_light_weights(s, lights[0], mat.shininess, PHONG_SPOT_LIGHTS > 0));
#else
    int n = min(count, PHONG_MAX_LIGHTS);
    int i = 0;
#if PHONG_SPOT != PHONG_SPOT_NONE
    int k = min(n, PHONG_SPOT_LIGHTS);
    if (k > 0) {
        do {
            phong_add_light_weighted(sums, lights[i], phong_light_weights(s, lights[i], mat.shininess, true));
            ++i;
        } while (i < k);
    }
#endif
#if PHONG_SPOT == PHONG_SPOT_NONE || PHONG_SPOT_LIGHTS < PHONG_MAX_LIGHTS
    if (n > i) {
        do {
            phong_add_light_weighted(sums, lights[i], phong_light_weights(s, lights[i], mat.shininess, false));
            ++i;
        } while (i < n);
    }
#endif
#endif // PHONG_MAX_LIGHTS == 1
    return phong_terms_of(sums, mat, env);
}

/// phong::shade_terms<F>: the model's terms at the point q with normal n (any length; unit with
/// PHONG_UNIT_INPUTS), view vector v (read only with PHONG_VIEW_GIVEN: from q toward the viewer,
/// any length), the first `count` lights of `lights` (count <= PHONG_MAX_LIGHTS), the material,
/// the environment, and front_facing (read only with PHONG_FACING_FLAG).
/// Edges: those of phong::shade (a light at q adds its ambient only; n = 0: no diffuse or
/// specular; no view vector: no specular; Blinn's l = -v: n.h = 0; m = 0: base^0 = 1; c0 = 0 and
/// d = 0: f capped at 2^63); a squared length outside float's normal range drops its vector.
phong_shading_terms phong_shade_terms(vec3 q, vec3 n, vec3 v, phong_material mat, phong_light lights[PHONG_MAX_LIGHTS],
                                      int count, phong_environment env, bool front_facing)
{
    return phong_terms_at(phong_prepare(q, n, v, env, front_facing), mat, lights, count, env);
}


/// phong::shade<F>: the full local model at q,
///   I = emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i max(n.l_i, 0) + ks sum_i f_i Ls_i s_i,
/// rgba with PHONG_ALPHA. Arguments and edges: phong_shade_terms.
phong_color phong_shade(vec3 q, vec3 n, vec3 v, phong_material mat, phong_light lights[PHONG_MAX_LIGHTS], int count,
                        phong_environment env, bool front_facing)
{
    return phong_total_of(phong_shade_terms(q, n, v, mat, lights, count, env, front_facing));
}

/// phong::shade_vertex<F> (the GLSL ADS shader's phong.vert): eyeCoords = model_view * (p, 1),
/// tnorm = normalize(normal_matrix * n), then phong_shade at (eyeCoords.xyz, tnorm) with lights in
/// eye coordinates. Pre: model_view affine; PHONG_VIEW not PHONG_VIEW_GIVEN.
/// Edge: normal_matrix * n is normalized once, by phong_shade: where its squared length is not a
/// normal float (|N n| below about 1.1e-19 or above 1.8e19) the normal is dropped (no diffuse or
/// specular), as phong_shade drops such a normal; C++ shade_vertex rescales it first
/// (transform_normal). A shader compiler that runs both sides of every branch (llvmpipe) would
/// otherwise pay for the rescaling on every vertex.
phong_color phong_shade_vertex(vec3 p, vec3 n, mat4 model_view, mat3 normal_matrix, phong_material mat,
                               phong_light lights[PHONG_MAX_LIGHTS], int count, phong_environment env)
{
    vec4 eye = phong_mul(model_view, vec4(p, 1.0));
    return phong_shade(eye.xyz, phong_mul(normal_matrix, n), vec3(0.0, 0.0, 0.0), mat, lights, count, env, true);
}
