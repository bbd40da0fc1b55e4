#include <phong/phong.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using namespace phong;
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 1, 4), glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 model_view = view * glm::rotate(glm::mat4(1), 0.5f, glm::vec3(0, 1, 0));
    const glm::mat3 normal_mat = normal_matrix(model_view); // GLSL's NormalMatrix
    const std::array lights{light<float>{.position = view * glm::vec4(2, 0.7f, -2.5f, 1), // eye coordinates
                                         .ambient = glm::vec3(0.1f), .diffuse = glm::vec3(0.9f), .specular = glm::vec3(0.6f)}};
    const material<float> mat{.ka = {0.8f, 0.3f, 0.3f}, .kd = {0.8f, 0.3f, 0.3f}, .ks = glm::vec3(0.5f), .shininess = 30};
    const glm::vec3 p(0.5f, 0.5f, 0.5f), n(0.577f, 0.577f, 0.577f); // an object-space vertex and its normal

    // Per vertex: the vertex shader's colour, interpolated by the rasterizer.
    const glm::vec3 gouraud = shade_vertex<presets::glsl_ads>(p, n, model_view, normal_mat, mat, lights);

    // Per pixel: the rasterizer interpolates these two; here, the values at the vertex itself.
    const glm::vec3 eye_position = glm::vec3(model_view * glm::vec4(p, 1));
    const glm::vec3 eye_normal = normal_mat * n; // any length: shade normalizes it
    const glm::vec3 per_pixel = shade<presets::glsl_ads>(eye_position, eye_normal, mat, lights);

    // The terms apart (tone mapping, separate buffers): their sum is shade's colour bit for bit.
    const shading_terms<float> terms = shade_terms<presets::glsl_ads>(eye_position, eye_normal, mat, lights);
    std::printf("gouraud %.4f, per pixel %.4f = %.4f ambient + %.4f diffuse + %.4f specular (red)\n", gouraud.r,
                per_pixel.r, terms.ambient.r, terms.diffuse.r, terms.specular.r);
    const bool same_vertex = std::fabs(gouraud.r - per_pixel.r) <= 1e-5f;
    return same_vertex && terms.sum() == per_pixel ? 0 : 1;
}
