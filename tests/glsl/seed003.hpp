// Seed 003's phong.vert (tests/glsl/seed003_phong.vert, verbatim) and the same model through the
// GLSL twin (phong_shade_vertex with PHONG_PRESET_GLSL_ADS), as two transform feedback programs over
// the same vertex buffers and uniforms: the agreement test (glsl.test.cpp) and the throughput
// benchmark (benchmarks/glsl/glsl_bench.cpp) both use them.
#pragma once

#include "gl.hpp"

#include <phong/glsl.hpp>
#include <phong/phong.hpp>

#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace glt {

/// The seed's shader text, as the seed has it (#version 410).
inline std::string seed003_source(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The twin's shader for the same model: the seed's inputs, outputs and matrices, the light and the
/// material as the twin's structs, GLSL 410 as the seed.
inline const char* const twin_ads_body = R"(
layout (location = 0) in vec3 VertexPosition;
layout (location = 1) in vec3 VertexNormal;
out vec3 LightIntensity;
uniform phong_light light;
uniform phong_material material;
uniform mat4 ModelViewMatrix;
uniform mat3 NormalMatrix;
uniform mat4 MVP;
void main()
{
    phong_light lights[1];
    lights[0] = light;
    phong_environment env;
    env.ambient = vec3(0.0);
    env.eye = vec4(0.0, 0.0, 0.0, 1.0);
    LightIntensity = phong_shade_vertex(VertexPosition, VertexNormal, ModelViewMatrix, NormalMatrix, material, lights, 1, env);
    gl_Position = MVP * vec4(VertexPosition, 1.0);
}
)";

inline std::string twin_ads_source()
{
    return phong::glsl::shader("#version 410", "#define PHONG_PRESET_GLSL_ADS\n#define PHONG_MAX_LIGHTS 1\n", phong::glsl::source(),
                               twin_ads_body);
}

/// One uniform set of the seed's model: its light (eye coordinates), material and matrices.
struct ads_uniforms {
    phong::light<float> light;
    phong::material<float> material;
    glm::mat4 model_view{1}, projection{1};
    glm::mat3 normal_matrix{1};
};

/// Sets the uniforms in the seed's names (seed == true) or the twin's, in program p (in use).
inline void set_ads_uniforms(const context& c, const feedback_program& p, const ads_uniforms& u, bool seed)
{
    const functions& gl = c.gl();
    const auto v3 = [&](const char* name, const glm::vec3& v) { gl.glUniform3fv(p.uniform(name), 1, &v.x); };
    const glm::mat4 mvp = u.projection * u.model_view;
    gl.glUniformMatrix4fv(p.uniform("ModelViewMatrix"), 1, GL_FALSE, &u.model_view[0][0]);
    gl.glUniformMatrix3fv(p.uniform("NormalMatrix"), 1, GL_FALSE, &u.normal_matrix[0][0]);
    gl.glUniformMatrix4fv(p.uniform("MVP"), 1, GL_FALSE, &mvp[0][0]);
    if (seed) {
        gl.glUniformMatrix4fv(p.uniform("ProjectionMatrix"), 1, GL_FALSE, &u.projection[0][0]);
        gl.glUniform4fv(p.uniform("Light.Position"), 1, &u.light.position.x);
        v3("Light.La", u.light.ambient);
        v3("Light.Ld", u.light.diffuse);
        v3("Light.Ls", u.light.specular);
        v3("Material.Ka", u.material.ka);
        v3("Material.Kd", u.material.kd);
        v3("Material.Ks", u.material.ks);
        gl.glUniform1f(p.uniform("Material.Shininess"), u.material.shininess);
    } else {
        gl.glUniform4fv(p.uniform("light.position"), 1, &u.light.position.x);
        v3("light.ambient", u.light.ambient);
        v3("light.diffuse", u.light.diffuse);
        v3("light.specular", u.light.specular);
        v3("material.ka", u.material.ka);
        v3("material.kd", u.material.kd);
        v3("material.ks", u.material.ks);
        gl.glUniform1f(p.uniform("material.shininess"), u.material.shininess);
    }
}

/// Vertex buffers at attribute locations 0 (position) and 1 (normal), bound while it lives.
class vertex_buffers {
public:
    vertex_buffers(const context& c, const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals) : c_(c)
    {
        const functions& gl = c.gl();
        gl.glGenBuffers(2, buffers_);
        const std::vector<glm::vec3>* data[2] = {&positions, &normals};
        for (GLuint i = 0; i < 2; ++i) {
            gl.glBindBuffer(GL_ARRAY_BUFFER, buffers_[i]);
            gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data[i]->size() * sizeof(glm::vec3)), data[i]->data(), GL_STATIC_DRAW);
        }
    }
    /// Called with a vertex array object bound (feedback_program::run's bind step).
    void attach() const
    {
        const functions& gl = c_.gl();
        for (GLuint i = 0; i < 2; ++i) {
            gl.glBindBuffer(GL_ARRAY_BUFFER, buffers_[i]);
            gl.glVertexAttribPointer(i, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
            gl.glEnableVertexAttribArray(i);
        }
    }
    ~vertex_buffers() { c_.gl().glDeleteBuffers(2, buffers_); }
    vertex_buffers(const vertex_buffers&) = delete;
    vertex_buffers& operator=(const vertex_buffers&) = delete;

private:
    const context& c_;
    GLuint buffers_[2] = {0, 0};
};

} // namespace glt
