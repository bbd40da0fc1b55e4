// phong: the colour of one point from its per-light sums: the public color<F> and shading_terms
// types, and the last step of every route (terms_of, finish), scalar and batch alike.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/config.hpp"
#include "../routes/light_terms.hpp"
#include "../inputs/environment.hpp"
#include "../inputs/features.hpp"
#include "../inputs/material.hpp"

#include <type_traits>

namespace phong {

/// The colour shade<F> returns: rgb, or rgba when F.alpha.
template <features F, class T, glm::qualifier Q = glm::defaultp>
using color = std::conditional_t<F.alpha, glm::vec<4, T, Q>, glm::vec<3, T, Q>>;

/// The model's terms at one point, each an rgb (shade_terms<F>): emission, ambient
/// ka (La + sum_i f_i La_i), diffuse kd sum_i f_i Ld_i max(n.l_i, 0), specular ks sum_i f_i Ls_i s_i
/// (0 where F leaves a term out), alpha the material's. emission + ambient + diffuse + specular, in
/// that order, is shade<F>'s colour bit for bit (with FMA contraction on, within the exact bound:
/// docs/compilers.md). For a point with NaN or inf input every term is NaN.
template <class T, glm::qualifier Q = glm::defaultp>
struct shading_terms {
    glm::vec<3, T, Q> emission; ///< the material's emission
    glm::vec<3, T, Q> ambient;  ///< ka (La + sum_i f_i La_i)
    glm::vec<3, T, Q> diffuse;  ///< kd sum_i f_i Ld_i max(n.l_i, 0)
    glm::vec<3, T, Q> specular; ///< ks sum_i f_i Ls_i s_i
    T alpha;                    ///< the material's alpha
    /// emission + ambient + diffuse + specular, in that order.
    PHONG_INLINE constexpr glm::vec<3, T, Q> sum() const { return emission + ambient + diffuse + specular; }
};

namespace detail {

/// The model's terms at the point, from the per-light sums (poison: the NaN policy's 0 or NaN).
template <features F, class T, glm::qualifier Q, class Frame>
PHONG_INLINE constexpr shading_terms<T, Q> terms_of(const light_sums<T, Q>& sums, const Frame& s, const material<T, Q>& mat,
                                                const environment<T, Q>& env)
{
    using vec3 = glm::vec<3, T, Q>;
    shading_terms<T, Q> t{vec3(s.poison), vec3(T(0)), vec3(T(0)), vec3(T(0)), mat.alpha + s.poison};
    if constexpr (F.emission) t.emission += mat.emission;
    if constexpr (F.scene_ambient && F.light_ambient) t.ambient = mat.ka * (env.ambient + sums.ambient);
    else if constexpr (F.scene_ambient) t.ambient = mat.ka * env.ambient;
    else if constexpr (F.light_ambient) t.ambient = mat.ka * sums.ambient;
    if constexpr (F.diffuse) t.diffuse = mat.kd * sums.diffuse;
    if constexpr (F.specular != specular_model::none) t.specular = mat.ks * sums.specular;
    return t;
}

/// The colour: emission + ambient + diffuse + specular, summed in that order (the terms F leaves
/// out are not added), alpha appended.
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr color<F, T, Q> total_of(const shading_terms<T, Q>& t)
{
    glm::vec<3, T, Q> c = t.emission;
    if constexpr (F.scene_ambient || F.light_ambient) c += t.ambient;
    if constexpr (F.diffuse) c += t.diffuse;
    if constexpr (F.specular != specular_model::none) c += t.specular;
    if constexpr (F.alpha) return glm::vec<4, T, Q>(c, t.alpha);
    else return c;
}

/// The colour from the per-light sums (the batch path's last step).
template <features F, class T, glm::qualifier Q, class Frame>
PHONG_INLINE constexpr color<F, T, Q> finish(const light_sums<T, Q>& sums, const Frame& s, const material<T, Q>& mat,
                                         const environment<T, Q>& env)
{
    return total_of<F>(terms_of<F>(sums, s, mat, env));
}

/// The colour from folded sums (one material: the lights carry ka, kd, ks; the total started at
/// emission + ka La + poison), alpha appended (mat.alpha + poison). The poison added first: the same
/// colours (the total is never -0 then), and it is not held across the light loop.
template <features F, class T, glm::qualifier Q, class Frame>
PHONG_INLINE constexpr color<F, T, Q> finish(const folded_sums<T, Q>& sums, [[maybe_unused]] const Frame& s,
                                         [[maybe_unused]] const material<T, Q>& mat, const environment<T, Q>&)
{
    const glm::vec<3, T, Q> c = sums.total;
    if constexpr (F.alpha) return glm::vec<4, T, Q>(c, mat.alpha + s.poison);
    else return c;
}

} // namespace detail
} // namespace phong
