// Compile-only check that phong's headers work in CUDA device code (no GPU needed):
//   nvcc -std=c++20 --expt-relaxed-constexpr -O3 -arch=sm_90 --use_fast_math -I include -c tests/cuda/shade_kernel.cu
// (.ci/steps/50-cuda.sh). Every function reached from the kernels must be __host__ __device__
// (PHONG_HD); a missing one is a compile error here.
#include <phong/accuracy.hpp>
#include <phong/phong.hpp>
#include <phong/primitives.hpp>

#include <array>

namespace {

using namespace phong;

constexpr features classic = presets::classic_phong;
constexpr features blinn_stable{.light_ambient = true, .specular = specular_model::blinn,
                                .attenuation = attenuation_model::windowed, .spot = spot_model::smooth,
                                .two_sided = facing::view, .emission = true, .mode = evaluation::stable};
constexpr features phong_spot{.specular = specular_model::phong, .lights = light_kind::positional,
                              .attenuation = attenuation_model::polynomial, .spot = spot_model::opengl,
                              .mode = evaluation::exact};

} // namespace

/// One thread per point: shade with a fixed light count (std::array, unrolled), three feature sets.
__global__ void shade_points(const glm::vec3* positions, const glm::vec3* normals, glm::vec4* out, int count)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= count) return;
    std::array<light<float>, 2> lights{light<float>::with_strength({2, 2, 0, 1}, {1, 1, 1}, {1, 0.1f, 0.01f}),
                                       light<float>::with_strength({0, 1, 1, 0}, {0.5f, 0.5f, 0.5f})};
    lights[0].spot = spot_cone<float>::opengl({-1, -1, 0}, 4.0f, 45.0f);
    lights[1].spot = spot_cone<float>::smooth({0, -1, -1}, 20.0f, 30.0f);
    const material<float> mat{.ka = glm::vec3(0.2f), .kd = glm::vec3(0.8f), .ks = glm::vec3(0.5f), .shininess = 40};
    environment<float> env{.ambient = glm::vec3(0.1f)};
    env.eye = eye_from_projection(glm::mat4(1.0f));
    const glm::vec4 a = shade<classic>(positions[i], normals[i], mat, lights, env);
    const glm::vec3 b = shade<blinn_stable>(positions[i], normals[i], mat, lights, env);
    const glm::vec3 c = shade<presets::with_mode(phong_spot, evaluation::stable)>(positions[i], normals[i], mat, lights, env);
    const glm::vec3 d = shade<presets::glsl_ads>(positions[i], normals[i], mat, lights, env);
    const glm::vec3 e = shade<presets::with_mode(blinn_stable, evaluation::fast)>(positions[i], normals[i], mat, lights, env);
    out[i] = a + glm::vec4(b + c + d + e, 0.0f);
}

/// The scalar building blocks on their own (double), and validate() on the device.
__global__ void scalar_api(const glm::dvec3* points, double* out, int count)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= count) return;
    const glm::dvec3 q = points[i];
    const glm::dvec3 n = phong::detail::normalize(glm::dvec3(0, 0, 1) + q * 0.01);
    const glm::dvec3 v = phong::detail::view_perspective(q);
    const phong::detail::direction_and_distance<double> to_light = toward(glm::dvec4(1, 2, 3, 1), q);
    const glm::dvec3 l = to_light.direction;
    double r = phong::detail::dot(n, l) + phong::detail::length(q) + phong::detail::dot(phong::detail::cross(n, l), v);
    r += specular_reflection(n, l, v, 32.0) + specular_halfway(n, l, v, 32.0);
    r += phong::detail::specular_reflection_stable(n, l, v, 1e4) + phong::detail::specular_halfway_stable(n, l, v, 1e4);
    r += attenuation_polynomial(to_light.distance, 1.0, 0.1, 0.01) + attenuation_windowed(to_light.distance, 10.0);
    r += spot_opengl(l, glm::dvec3(0, 0, -1), 2.0, 0.5) + spot_smooth(l, glm::dvec3(0, 0, -1), 0.9, 0.8);
    const glm::dmat3 N = normal_matrix(glm::dmat4(2.0));
    r += phong::detail::dot(transform_normal(N, n), face_viewer(n, v)) + phong::detail::dot(phong::detail::face_flag(n, false), phong::reflect(-l, n));
    r += phong::detail::dot(view_vector(eye_from_projection(glm::dmat4(1.0)), q), phong::detail::view_orthographic(glm::dmat4(1.0)));
    r += phong::detail::dot(phong::faceforward(n, -v, n), phong::detail::normalize_unscaled(q)) + phong::detail::dot_compensated(n, l) + phong::detail::pow<5>(0.5);
    r += phong::detail::sqrt(2.0) + phong::detail::exp(0.5) + phong::detail::log(2.0) + phong::detail::log1p(1e-9) + phong::detail::pow(2.0, 0.5);
    r += phong::detail::fma(1.0, 2.0, 3.0) + phong::detail::clamp(r, 0.0, 1e9) + phong::detail::pow_one_minus(0.25, 3.0) + phong::detail::cos_degrees(30.0);
    r += phong::detail::dot(sphere_normal(q), cube_normal(q)) + tapered_cylinder_wall_normal(q, 0.5).z;
    r += ray_sphere(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, -1)).t + ray_tapered_cylinder(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, -1), 0.5).t;
    r += ray_cube(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, -1)).t + accuracy::of<evaluation::stable, double>(accuracy::input_class::well_conditioned).p99_ulp;
    r += validate(material<double>{}) ? 1.0 : 0.0;
    r += validate(light<double>{}) ? 1.0 : 0.0;
    out[i] = r;
}
