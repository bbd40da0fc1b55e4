// Test support: the seeds' formulas, written out literally with plain GLM and std:: functions
// (glm::normalize, glm::reflect, glm::dot, std::pow, std::max), in the seeds' own variable names.
// They share no code with phong: they are the independent oracle for the presets. Instantiate
// them in double or long double (GLM 0.9.9.8 accepts long double: it is IEC 559 on x86-64).
//
// Where the seed leaves something to the implementer, the choice is stated at the function and is
// the one phong's presets document (features.hpp): seed 000 clamps its dot products at 0 and has
// no gate; f_i(Q) is OpenGL's 1 / (c0 + c1 d + c2 d^2) for positional lights and 1 for directional.
#pragma once

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace phong_test::seeds {

// ---------------------------------------------------------------------------------------------
// Seed 000: I_Q = k_a * L_a + sum_i f_i(Q) L_i { k_d * (n.l_i) + k_s * (r_i.v)^m }, eye coordinates.

/// One light of seed 000: p_ecLightPos (w = 1 positional, w = 0 directional), lightStrength, and
/// the coefficients of atten(i, Q) (OpenGL's constant, linear, quadratic attenuation).
template <class R>
struct seed000_light {
    glm::vec<4, R> p_ecLightPos;
    glm::vec<3, R> lightStrength;
    R c0 = 1, c1 = 0, c2 = 0;
};

/// Seed 000's uniforms.
template <class R>
struct seed000_uniforms {
    glm::vec<3, R> ka, kd, ks, La;
    R m;
    glm::mat<4, 4, R> ec_lds; ///< the projection matrix, read for the orthographic v
    bool perspective = true;
    R alpha = 1;
};

/// atten(i, Q): the "shader function that computes the attenuation" the seed asks for, OpenGL's
/// polynomial in the distance to a positional light; 1 for a directional one.
template <class R>
R atten(const seed000_light<R>& L, const glm::vec<3, R>& Q)
{
    if (L.p_ecLightPos.w == R(0)) return R(1);
    const R d = glm::length(glm::vec<3, R>(L.p_ecLightPos) - Q);
    return R(1) / (L.c0 + L.c1 * d + L.c2 * d * d);
}

/// Seed 000 at Q (pvaIn.ecPosition) with normal pvaIn.ecUnitNormal; returns (I_Q, alpha).
/// As in features.hpp's classic_phong: ec_nHat is negated when it faces away from vHat, and the
/// dot products are clamped at 0 (max(n.l, 0), max(r.v, 0)); no gate.
template <class R>
glm::vec<4, R> seed000(const glm::vec<3, R>& ecPosition, const glm::vec<3, R>& ecUnitNormal,
                       const seed000_uniforms<R>& u, const std::vector<seed000_light<R>>& lights)
{
    using vec3 = glm::vec<3, R>;
    const vec3 Q = ecPosition;
    const vec3 O(0, 0, 0);
    const glm::mat<4, 4, R>& M = u.ec_lds; // M_02 is row 0, column 2: M[2][0] in GLM
    const vec3 vHat = u.perspective ? glm::normalize(O - Q)
                                    : glm::normalize(vec3(-M[2][0] / M[0][0], -M[2][1] / M[1][1], R(1)));
    vec3 ec_nHat = glm::normalize(ecUnitNormal);
    if (glm::dot(ec_nHat, vHat) < R(0)) ec_nHat = -ec_nHat; // "conditionally negated"
    vec3 I = u.ka * u.La;
    for (const seed000_light<R>& L : lights) {
        const vec3 Lxyz(L.p_ecLightPos);
        const vec3 liHat = L.p_ecLightPos.w == R(1) ? glm::normalize(Lxyz - Q) : glm::normalize(Lxyz);
        const vec3 riHat = glm::reflect(-liHat, ec_nHat);
        const R f = atten(L, Q);
        I += f * L.lightStrength *
             (u.kd * std::max(glm::dot(ec_nHat, liHat), R(0)) + u.ks * std::pow(std::max(glm::dot(riHat, vHat), R(0)), u.m));
    }
    return glm::vec<4, R>(I, u.alpha);
}

// ---------------------------------------------------------------------------------------------
// Seed 001: the ray tracer's Phong shader, steps 1-18.

template <class R>
struct seed001_light {
    glm::vec<3, R> position;
    glm::vec<3, R> lightamb, lightdiff, lightspec;
};

template <class R>
struct seed001_material {
    glm::vec<3, R> materialamb, materialdiff, materialspec;
    R f; ///< specular exponent, 0 <= f <= 200
};

/// Step 4: m = M * m', the generic normal carried by the object's inverse transformed matrix M.
template <class R>
glm::vec<3, R> seed001_normal(const glm::mat<3, 3, R>& M, const glm::vec<3, R>& m_generic)
{
    return M * m_generic;
}

/// Steps 1-18 at the hit point P = ray(hit_time) with the actual normal m (step 4's result);
/// ray_start is the eye (step 8: e = ray.start - P).
template <class R>
glm::vec<3, R> seed001(const glm::vec<3, R>& P, const glm::vec<3, R>& m_actual, const glm::vec<3, R>& ray_start,
                       const std::vector<seed001_light<R>>& lights, const seed001_material<R>& mat,
                       const glm::vec<3, R>& GlobalAmbient)
{
    using vec3 = glm::vec<3, R>;
    vec3 I(0);
    for (const seed001_light<R>& light : lights) {
        vec3 l = light.position - P;                              // 2
        vec3 m = m_actual;                                        // 3, 4
        l = glm::normalize(l);                                    // 5
        m = glm::normalize(m);
        const R lambert = std::max(glm::dot(l, m), R(0));        // 6
        const vec3 Idiff = light.lightdiff * mat.materialdiff * lambert; // 7
        vec3 e = ray_start - P;                                   // 8
        e = glm::normalize(e);                                    // 9
        vec3 h = l + e;                                           // 10
        h = glm::normalize(h);                                    // 11
        const R phong = std::max(R(0), glm::dot(h, m));          // 12
        const vec3 Ispec = light.lightspec * mat.materialspec * std::pow(phong, mat.f); // 13
        const vec3 Iamb = light.lightamb * mat.materialamb;      // 14
        const vec3 IL = Idiff + Ispec + Iamb;                     // 15
        I += IL;                                                  // 17 (sum over lights)
    }
    const vec3 IG = GlobalAmbient * mat.materialamb;             // 16
    return I + IG;                                                // 17, 18
}

// ---------------------------------------------------------------------------------------------
// Seed 003: GLSL 4.1 vertex shaders phong.vert and diffuse.vert.

template <class R>
struct LightInfo {
    glm::vec<4, R> Position; // Light position in eye coords.
    glm::vec<3, R> La;       // Ambient light intensity
    glm::vec<3, R> Ld;       // Diffuse light intensity
    glm::vec<3, R> Ls;       // Specular light intensity
};

template <class R>
struct MaterialInfo {
    glm::vec<3, R> Ka; // Ambient reflectivity
    glm::vec<3, R> Kd; // Diffuse reflectivity
    glm::vec<3, R> Ks; // Specular reflectivity
    R Shininess;       // Specular shininess factor
};

/// phong.vert's main(), returning LightIntensity.
template <class R>
glm::vec<3, R> phong_vert(const glm::vec<3, R>& VertexPosition, const glm::vec<3, R>& VertexNormal,
                          const LightInfo<R>& Light, const MaterialInfo<R>& Material,
                          const glm::mat<4, 4, R>& ModelViewMatrix, const glm::mat<3, 3, R>& NormalMatrix)
{
    using vec3 = glm::vec<3, R>;
    using vec4 = glm::vec<4, R>;
    const vec3 tnorm = glm::normalize(NormalMatrix * VertexNormal);
    const vec4 eyeCoords = ModelViewMatrix * vec4(VertexPosition, R(1.0));
    const vec3 s = glm::normalize(vec3(Light.Position - eyeCoords));
    const vec3 v = glm::normalize(-vec3(eyeCoords));
    const vec3 r = glm::reflect(-s, tnorm);
    const R sDotN = std::max(glm::dot(s, tnorm), R(0.0));
    const vec3 ambient = Light.La * Material.Ka;
    const vec3 diffuse = Light.Ld * Material.Kd * sDotN;
    vec3 spec = vec3(0.0);
    if (sDotN > R(0.0))
        spec = Light.Ls * Material.Ks * std::pow(std::max(glm::dot(r, v), R(0.0)), Material.Shininess);
    return ambient + diffuse + spec;
}

/// diffuse.vert's main(), returning LightIntensity.
template <class R>
glm::vec<3, R> diffuse_vert(const glm::vec<3, R>& VertexPosition, const glm::vec<3, R>& VertexNormal,
                            const glm::vec<4, R>& LightPosition, const glm::vec<3, R>& Kd, const glm::vec<3, R>& Ld,
                            const glm::mat<4, 4, R>& ModelViewMatrix, const glm::mat<3, 3, R>& NormalMatrix)
{
    using vec3 = glm::vec<3, R>;
    using vec4 = glm::vec<4, R>;
    const vec3 tnorm = glm::normalize(NormalMatrix * VertexNormal);
    const vec4 eyeCoords = ModelViewMatrix * vec4(VertexPosition, R(1.0));
    const vec3 s = glm::normalize(vec3(LightPosition - eyeCoords));
    return Ld * Kd * std::max(glm::dot(s, tnorm), R(0.0));
}

} // namespace phong_test::seeds
