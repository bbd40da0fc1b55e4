// A multi-light fragment shader shaped like the most-read OpenGL tutorial's lighting chapters,
// written by hand, against the same lighting through the GLSL twin's phong_shade, on Mesa llvmpipe
// offscreen (EGL surfaceless), 800x600 (docs/glsl.md, "Speed: a tutorial's multi-light shader").
//  * six lights: one directional light, four point lights with constant, linear and quadratic
//    attenuation, one flashlight spot at the camera with a linear edge between an inner and an outer
//    cone; per-light ambient; Phong specular with reflect() and no n.l gate; diffuse and specular
//    texture maps; lighting in world space. Ported to phong_shade as a user replacing the lighting
//    would: the shader keeps the tutorial's uniforms and builds phong_shade's arguments (the
//    phong_lights, the material, the environment) from them; PHONG_SPOT_LINEAR, lights of any
//    kind. And the lights as the twin's uniform array (the world-space recipe's layout, every
//    light in phong_light uniforms): the flashlight first with PHONG_SPOT_LIGHTS 1, and with
//    every light allowed a cone (the default), the point lights' spot uniforms left at 0; both
//    against the tutorial's shader and against the same loop written by hand over those uniforms.
//  * one light: the tutorial's basic specular shader (one point light, ambient 0.1, specular 0.5,
//    shininess 32, an object colour), and the same through phong_shade: with the tutorial's
//    uniforms (a light colour, an object colour), and with phong_material / phong_light uniforms,
//    against the tutorial's Materials-chapter shader (the same lighting from the same uniforms: a
//    colour per term in the material and the light) and against the basic one.
// Each frame is a clear, one draw of a tessellated height field that covers the viewport, and
// glFinish. The frames alternate between the programs in blocks (the order rotates each round),
// timed in this thread's CPU time with llvmpipe shading on the calling thread (LP_NUM_THREADS=0,
// set here unless the environment sets it): on a shared machine wall time mostly measures the
// other processes. Reported: the median frame time of each, the ratio of the medians and the
// median of the per-round ratios; and the images: pixels that differ and the largest difference in
// 8-bit levels. Usage: phong_glsl_tutorial_bench [frames per block = 10] [rounds = 21], or
// valgrind --tool=callgrind --collect-atstart=no phong_glsl_tutorial_bench --callgrind (instruction
// counts of one frame of each program, one dump each; build without AVX-512 for valgrind).
#include "../../tests/glsl/gl.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <phong/glsl.hpp>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h> // --callgrind: instruction counts (Debian: valgrind)
#else
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

namespace {

constexpr int width = 800, height = 600;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double now()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

const char* const vertex_shader = R"(#version 330 core
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
layout (location = 2) in vec2 aTexCoords;
out vec3 FragPos;
out vec3 Normal;
out vec2 TexCoords;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;
void main()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = normalMatrix * aNormal;
    TexCoords = aTexCoords;
    gl_Position = projection * view * vec4(FragPos, 1.0);
}
)";

// The tutorial's six-light interface: its structs, inputs and uniforms, which the hand-written
// shader and its port both read.
const std::string tutorial_six_interface = R"(
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight {
    vec3 position; vec3 direction; float cutOff; float outerCutOff;
    float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular;
};
#define NR_POINT_LIGHTS 4
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform DirLight dirLight;
uniform PointLight pointLights[NR_POINT_LIGHTS];
uniform SpotLight spotLight;
uniform Material material;
)";

// The tutorial's shape, written by hand: a function per light kind, each sampling the maps.
const std::string hand_six = "#version 330 core\n" + tutorial_six_interface + R"(
vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir)
{
    vec3 lightDir = normalize(-light.direction);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
    vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));
    vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));
    vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));
    return ambient + diffuse + specular;
}

vec3 CalcPointLight(PointLight light, vec3 normal, vec3 fragPos, vec3 viewDir)
{
    vec3 lightDir = normalize(light.position - fragPos);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
    float distance = length(light.position - fragPos);
    float attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance));
    vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));
    vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));
    vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));
    return (ambient + diffuse + specular) * attenuation;
}

vec3 CalcSpotLight(SpotLight light, vec3 normal, vec3 fragPos, vec3 viewDir)
{
    vec3 lightDir = normalize(light.position - fragPos);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
    float distance = length(light.position - fragPos);
    float attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance));
    float theta = dot(lightDir, normalize(-light.direction));
    float epsilon = light.cutOff - light.outerCutOff;
    float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);
    vec3 ambient = light.ambient * vec3(texture(material.diffuse, TexCoords));
    vec3 diffuse = light.diffuse * diff * vec3(texture(material.diffuse, TexCoords));
    vec3 specular = light.specular * spec * vec3(texture(material.specular, TexCoords));
    return (ambient + diffuse + specular) * (attenuation * intensity);
}

void main()
{
    vec3 norm = normalize(Normal);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 result = CalcDirLight(dirLight, norm, viewDir);
    for (int i = 0; i < NR_POINT_LIGHTS; i++)
        result += CalcPointLight(pointLights[i], norm, FragPos, viewDir);
    result += CalcSpotLight(spotLight, norm, FragPos, viewDir);
    FragColor = vec4(result, 1.0);
}
)";

// The tutorial's shader ported to phong_shade: its uniforms kept, phong_shade's arguments built from
// them (the flashlight first, then the point lights, then the directional light).
// The world-space recipe's defines for six lights, every light allowed a cone (PHONG_SPOT_LIGHTS at
// its default, 6).
const std::string six_defines = R"(#define PHONG_SCENE_AMBIENT 0
#define PHONG_LIGHT_AMBIENT 1
#define PHONG_SPECULAR_GATE 0
#define PHONG_ATTENUATION PHONG_ATTENUATION_POLYNOMIAL
#define PHONG_SPOT PHONG_SPOT_LINEAR
#define PHONG_VIEW PHONG_VIEW_EYE_POINT
#define PHONG_MAX_LIGHTS 6
)";
const std::string port_six_body = tutorial_six_interface + R"(
void main()
{
    phong_light lights[6];
    // The flashlight; its spot direction points away from the light, as the tutorial's.
    lights[0].position = vec4(spotLight.position, 1.0);
    lights[0].ambient = spotLight.ambient;
    lights[0].diffuse = spotLight.diffuse;
    lights[0].specular = spotLight.specular;
    lights[0].attenuation = phong_falloff(spotLight.constant, spotLight.linear, spotLight.quadratic, 1e30);
    lights[0].spot = phong_spot_cone(spotLight.direction, 0.0, -1.0, spotLight.cutOff, spotLight.outerCutOff);
    for (int i = 0; i < NR_POINT_LIGHTS; ++i) { // no cone: a zero axis
        lights[i + 1].position = vec4(pointLights[i].position, 1.0);
        lights[i + 1].ambient = pointLights[i].ambient;
        lights[i + 1].diffuse = pointLights[i].diffuse;
        lights[i + 1].specular = pointLights[i].specular;
        lights[i + 1].attenuation = phong_falloff(pointLights[i].constant, pointLights[i].linear, pointLights[i].quadratic, 1e30);
        lights[i + 1].spot = phong_spot_cone(vec3(0.0), 0.0, -1.0, -1.0, -1.0);
    }
    // The directional light: xyz points toward the light (the tutorial's direction points away).
    lights[5].position = vec4(-dirLight.direction, 0.0);
    lights[5].ambient = dirLight.ambient;
    lights[5].diffuse = dirLight.diffuse;
    lights[5].specular = dirLight.specular;
    lights[5].attenuation = phong_falloff(1.0, 0.0, 0.0, 1e30);
    lights[5].spot = phong_spot_cone(vec3(0.0), 0.0, -1.0, -1.0, -1.0);
    vec3 albedo = texture(material.diffuse, TexCoords).rgb;
    phong_material mat;
    mat.ka = albedo;
    mat.kd = albedo;
    mat.ks = texture(material.specular, TexCoords).rgb;
    mat.emission = vec3(0.0);
    mat.shininess = material.shininess;
    mat.alpha = 1.0;
    phong_environment env;
    env.ambient = vec3(0.0);
    env.eye = vec4(viewPos, 1.0);
    FragColor = vec4(phong_shade(FragPos, Normal, vec3(0.0), mat, lights, 6, env, true), 1.0);
}
)";

// The same lighting with the lights as the twin's uniform array (the world-space recipe's layout):
// the maps give the material, the lights are phong_light uniforms.
// The cone on the first light only; six_defines alone: every light allowed a cone, the five
// without one having their spot uniforms at 0.
const std::string twin_six_defines = six_defines + "#define PHONG_SPOT_LIGHTS 1\n";
const char* const twin_body = R"(
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform sampler2D diffuse_map;
uniform sampler2D specular_map;
uniform float shininess;
uniform phong_light lights[PHONG_MAX_LIGHTS];
uniform int light_count;
uniform phong_environment environment; // eye: the camera, (viewPos, 1)
void main()
{
    vec3 albedo = texture(diffuse_map, TexCoords).rgb;
    phong_material material;
    material.ka = albedo;
    material.kd = albedo;
    material.ks = texture(specular_map, TexCoords).rgb;
    material.emission = vec3(0.0);
    material.shininess = shininess;
    material.alpha = 1.0;
    FragColor = vec4(phong_shade(FragPos, Normal, vec3(0.0), material, lights, light_count, environment, true), 1.0);
}
)";

// The six-light lighting by hand over the twin's uniform layout (twin_body's names and the
// phong_light fields, declared here by hand): one loop over light_count lights, the tutorial's
// formulas per light, w = 0 for the directional light, the linear-edge cone on the first light
// only, or (every_light_cone) on every light with a nonzero axis. What a renderer author writes
// over these uniforms without phong: the fair baseline of the twin's uniform rows.
std::string hand_six_twin_uniforms(bool every_light_cone)
{
    return std::string("#version 330 core\n") + (every_light_cone ? "#define CONE_ON(i) (lights[i].spot.direction != vec3(0.0))\n"
                                                                  : "#define CONE_ON(i) (i == 0)\n") + R"(
struct Falloff { float constant; float linear; float quadratic; float range; };
struct SpotCone { vec3 direction; float exponent; float cos_cutoff; float cos_inner; float cos_outer; };
struct Light { vec4 position; vec3 ambient; vec3 diffuse; vec3 specular; Falloff attenuation; SpotCone spot; };
struct Environment { vec3 ambient; vec4 eye; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform sampler2D diffuse_map;
uniform sampler2D specular_map;
uniform float shininess;
uniform Light lights[6];
uniform int light_count;
uniform Environment environment;
void main()
{
    vec3 albedo = texture(diffuse_map, TexCoords).rgb;
    vec3 ks = texture(specular_map, TexCoords).rgb;
    vec3 norm = normalize(Normal);
    vec3 viewDir = normalize(environment.eye.xyz - FragPos);
    vec3 result = vec3(0.0);
    for (int i = 0; i < light_count; i++) {
        vec3 toLight = lights[i].position.xyz - lights[i].position.w * FragPos;
        float distance = length(toLight);
        vec3 lightDir = toLight / distance;
        float diff = max(dot(norm, lightDir), 0.0);
        vec3 reflectDir = reflect(-lightDir, norm);
        float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
        float attenuation = 1.0;
        if (lights[i].position.w != 0.0)
            attenuation = 1.0 / (lights[i].attenuation.constant + lights[i].attenuation.linear * distance +
                                 lights[i].attenuation.quadratic * (distance * distance));
        if (CONE_ON(i)) {
            float theta = dot(lightDir, -lights[i].spot.direction);
            float epsilon = lights[i].spot.cos_inner - lights[i].spot.cos_outer;
            attenuation *= clamp((theta - lights[i].spot.cos_outer) / epsilon, 0.0, 1.0);
        }
        result += (lights[i].ambient * albedo + lights[i].diffuse * diff * albedo + lights[i].specular * spec * ks) * attenuation;
    }
    FragColor = vec4(result, 1.0);
}
)";
}

// The tutorial's basic specular shader (one light, an object colour), by hand.
const char* const hand_one = R"(#version 330 core
out vec4 FragColor;
in vec3 Normal;
in vec3 FragPos;
in vec2 TexCoords;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
void main()
{
    float ambientStrength = 0.1;
    vec3 ambient = ambientStrength * lightColor;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;
    float specularStrength = 0.5;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 specular = specularStrength * spec * lightColor;
    vec3 result = (ambient + diffuse + specular) * objectColor;
    FragColor = vec4(result, 1.0);
}
)";

// The basic shader ported to phong_shade: its uniforms kept, (0.1 L + diff L + 0.5 spec L) object
// as ka = kd = object with La = 0.1 L and Ld = L, ks = 0.5 object with Ls = L.
const char* const port_one_body = R"(
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
void main()
{
    phong_material material;
    material.ka = objectColor;
    material.kd = objectColor;
    material.ks = 0.5 * objectColor;
    material.emission = vec3(0.0);
    material.shininess = 32.0;
    material.alpha = 1.0;
    phong_light lights[1];
    lights[0].position = vec4(lightPos, 1.0);
    lights[0].ambient = 0.1 * lightColor;
    lights[0].diffuse = lightColor;
    lights[0].specular = lightColor;
    lights[0].attenuation = phong_falloff(1.0, 0.0, 0.0, 1e30);
    lights[0].spot = phong_spot_cone(vec3(0.0), 0.0, -1.0, -1.0, -1.0);
    phong_environment environment;
    environment.ambient = vec3(0.0);
    environment.eye = vec4(viewPos, 1.0);
    FragColor = vec4(phong_shade(FragPos, Normal, vec3(0.0), material, lights, 1, environment, true), 1.0);
}
)";

// The same with the material and the light as phong_material / phong_light uniforms.
const char* const twin_one_defines = R"(#define PHONG_SCENE_AMBIENT 0
#define PHONG_LIGHT_AMBIENT 1
#define PHONG_SPECULAR_GATE 0
#define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
#define PHONG_VIEW PHONG_VIEW_EYE_POINT
#define PHONG_MAX_LIGHTS 1
)";
const char* const twin_one_body = R"(
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform phong_material material;
uniform phong_light lights[PHONG_MAX_LIGHTS];
uniform phong_environment environment;
void main()
{
    FragColor = vec4(phong_shade(FragPos, Normal, vec3(0.0), material, lights, 1, environment, true), 1.0);
}
)";

// The tutorial's Materials chapter by hand: the basic shader's lighting with a colour per term in
// the material and in the light (ambient, diffuse, specular) and the shininess as uniforms, the
// uniforms the twin's phong_material / phong_light rows read; named as the twin's (ka, kd, ks;
// a vec4 position and eye) so that one setter serves both.
const char* const hand_one_materials = R"(#version 330 core
struct Material { vec3 ka; vec3 kd; vec3 ks; float shininess; };
struct Light { vec4 position; vec3 ambient; vec3 diffuse; vec3 specular; };
struct Environment { vec4 eye; };
out vec4 FragColor;
in vec3 Normal;
in vec3 FragPos;
in vec2 TexCoords;
uniform Material material;
uniform Light lights[1];
uniform Environment environment;
void main()
{
    vec3 ambient = lights[0].ambient * material.ka;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lights[0].position.xyz - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = lights[0].diffuse * (diff * material.kd);
    vec3 viewDir = normalize(environment.eye.xyz - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
    vec3 specular = lights[0].specular * (spec * material.ks);
    FragColor = vec4(ambient + diffuse + specular, 1.0);
}
)";

/// A height field z = 0.15 sin(3x) cos(2y) over [-2, 2] x [-1.5, 1.5], n x n quads, as triangles:
/// position, normal, texture coordinate (two repeats of the maps).
std::vector<float> height_field(int n)
{
    std::vector<float> v;
    const auto vertex = [&](float x, float y) {
        const float z = 0.15f * std::sin(3 * x) * std::cos(2 * y);
        const glm::vec3 nrm = glm::normalize(glm::vec3(-0.45f * std::cos(3 * x) * std::cos(2 * y), 0.3f * std::sin(3 * x) * std::sin(2 * y), 1));
        v.insert(v.end(), {x, y, z, nrm.x, nrm.y, nrm.z, (x + 2) / 2, (y + 1.5f) / 1.5f});
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x0 = -2 + 4.0f * float(i) / float(n), x1 = -2 + 4.0f * float(i + 1) / float(n);
            const float y0 = -1.5f + 3.0f * float(j) / float(n), y1 = -1.5f + 3.0f * float(j + 1) / float(n);
            vertex(x0, y0), vertex(x1, y0), vertex(x1, y1);
            vertex(x0, y0), vertex(x1, y1), vertex(x0, y1);
        }
    return v;
}

/// An RGBA8 texture of 256 x 256 from f(x, y) -> rgb in [0, 1], linear filtering, repeat.
template <class F> GLuint make_texture(const glt::functions& gl, F f)
{
    constexpr int n = 256;
    std::vector<unsigned char> texels(std::size_t(n) * n * 4);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const glm::vec3 c = glm::clamp(f(float(x) / n, float(y) / n), 0.0f, 1.0f);
            unsigned char* t = &texels[(std::size_t(y) * n + std::size_t(x)) * 4];
            t[0] = (unsigned char)std::lround(c.r * 255), t[1] = (unsigned char)std::lround(c.g * 255), t[2] = (unsigned char)std::lround(c.b * 255), t[3] = 255;
        }
    GLuint id = 0;
    gl.glGenTextures(1, &id);
    gl.glBindTexture(GL_TEXTURE_2D, id);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    return id;
}

struct scene_lights {
    glm::vec3 view_pos{0, 0, 3};
    glm::vec3 dir_direction{-0.2f, -1.0f, -0.3f};
    glm::vec3 points[4] = {{0.7f, 0.2f, 0.6f}, {-1.2f, -0.8f, 0.5f}, {1.3f, -0.9f, 0.8f}, {-0.9f, 0.9f, 0.4f}};
    glm::vec3 spot_direction = glm::normalize(glm::vec3(0.1f, 0.05f, -1.0f));
    float cut_off = std::cos(glm::radians(12.5f)), outer_cut_off = std::cos(glm::radians(15.0f));
};

/// One program with its uniforms set: draws a frame with draw().
struct frame_program {
    glt::feedback_program program;
    frame_program(const glt::context& c, const std::string& fragment) : program(c, vertex_shader, nullptr, fragment) {}
};

void set_common(const glt::context& c, const glt::feedback_program& p, const scene_lights& s)
{
    const glt::functions& gl = c.gl();
    gl.glUseProgram(p.id());
    const glm::mat4 model(1), view = glm::lookAt(s.view_pos, glm::vec3(0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(45.0f), float(width) / float(height), 0.1f, 100.0f);
    const glm::mat3 normal_matrix(1);
    gl.glUniformMatrix4fv(p.uniform("model"), 1, GL_FALSE, &model[0][0]);
    gl.glUniformMatrix4fv(p.uniform("view"), 1, GL_FALSE, &view[0][0]);
    gl.glUniformMatrix4fv(p.uniform("projection"), 1, GL_FALSE, &projection[0][0]);
    gl.glUniformMatrix3fv(p.uniform("normalMatrix"), 1, GL_FALSE, &normal_matrix[0][0]);
}

void set_hand_six(const glt::context& c, const glt::feedback_program& p, const scene_lights& s)
{
    const glt::functions& gl = c.gl();
    set_common(c, p, s);
    const auto v3 = [&](const std::string& n, glm::vec3 v) { gl.glUniform3fv(p.uniform(n.c_str()), 1, &v.x); };
    const auto f1 = [&](const std::string& n, float v) { gl.glUniform1f(p.uniform(n.c_str()), v); };
    v3("viewPos", s.view_pos);
    gl.glUniform1i(p.uniform("material.diffuse"), 0);
    gl.glUniform1i(p.uniform("material.specular"), 1);
    f1("material.shininess", 32);
    v3("dirLight.direction", s.dir_direction);
    v3("dirLight.ambient", glm::vec3(0.05f)), v3("dirLight.diffuse", glm::vec3(0.4f)), v3("dirLight.specular", glm::vec3(0.5f));
    for (int i = 0; i < 4; ++i) {
        const std::string L = "pointLights[" + std::to_string(i) + "].";
        v3(L + "position", s.points[i]);
        v3(L + "ambient", glm::vec3(0.05f)), v3(L + "diffuse", glm::vec3(0.8f)), v3(L + "specular", glm::vec3(1.0f));
        f1(L + "constant", 1), f1(L + "linear", 0.09f), f1(L + "quadratic", 0.032f);
    }
    v3("spotLight.position", s.view_pos);
    v3("spotLight.direction", s.spot_direction);
    v3("spotLight.ambient", glm::vec3(0)), v3("spotLight.diffuse", glm::vec3(1)), v3("spotLight.specular", glm::vec3(1));
    f1("spotLight.constant", 1), f1("spotLight.linear", 0.09f), f1("spotLight.quadratic", 0.032f);
    f1("spotLight.cutOff", s.cut_off), f1("spotLight.outerCutOff", s.outer_cut_off);
}

void set_twin_six(const glt::context& c, const glt::feedback_program& p, const scene_lights& s)
{
    const glt::functions& gl = c.gl();
    set_common(c, p, s);
    const auto v3 = [&](const std::string& n, glm::vec3 v) { gl.glUniform3fv(p.uniform(n.c_str()), 1, &v.x); };
    const auto v4 = [&](const std::string& n, glm::vec4 v) { gl.glUniform4fv(p.uniform(n.c_str()), 1, &v.x); };
    const auto f1 = [&](const std::string& n, float v) { gl.glUniform1f(p.uniform(n.c_str()), v); };
    gl.glUniform1i(p.uniform("diffuse_map"), 0);
    gl.glUniform1i(p.uniform("specular_map"), 1);
    f1("shininess", 32);
    v4("environment.eye", glm::vec4(s.view_pos, 1));
    gl.glUniform1i(p.uniform("light_count"), 6);
    // Light 5: directional; its position's xyz points toward the light (the tutorial's direction
    // points from the light: negated). No attenuation is read for w = 0; no cone (spot left at 0).
    v4("lights[5].position", glm::vec4(-s.dir_direction, 0));
    v3("lights[5].ambient", glm::vec3(0.05f)), v3("lights[5].diffuse", glm::vec3(0.4f)), v3("lights[5].specular", glm::vec3(0.5f));
    for (int i = 0; i < 4; ++i) { // lights 1-4: points, spot uniforms left at 0 (no cone)
        const std::string L = "lights[" + std::to_string(i + 1) + "].";
        v4(L + "position", glm::vec4(s.points[i], 1));
        v3(L + "ambient", glm::vec3(0.05f)), v3(L + "diffuse", glm::vec3(0.8f)), v3(L + "specular", glm::vec3(1.0f));
        f1(L + "attenuation.constant", 1), f1(L + "attenuation.linear", 0.09f), f1(L + "attenuation.quadratic", 0.032f);
    }
    // Light 0: the flashlight (first: PHONG_SPOT_LIGHTS 1); its spot direction points away from
    // the light, as the tutorial's.
    v4("lights[0].position", glm::vec4(s.view_pos, 1));
    v3("lights[0].ambient", glm::vec3(0)), v3("lights[0].diffuse", glm::vec3(1)), v3("lights[0].specular", glm::vec3(1));
    f1("lights[0].attenuation.constant", 1), f1("lights[0].attenuation.linear", 0.09f), f1("lights[0].attenuation.quadratic", 0.032f);
    v3("lights[0].spot.direction", s.spot_direction);
    f1("lights[0].spot.cos_inner", s.cut_off), f1("lights[0].spot.cos_outer", s.outer_cut_off);
}

void set_hand_one(const glt::context& c, const glt::feedback_program& p, const scene_lights& s)
{
    const glt::functions& gl = c.gl();
    set_common(c, p, s);
    const auto v3 = [&](const char* n, glm::vec3 v) { gl.glUniform3fv(p.uniform(n), 1, &v.x); };
    v3("lightPos", glm::vec3(1.2f, 1.0f, 2.0f));
    v3("viewPos", s.view_pos);
    v3("lightColor", glm::vec3(1));
    v3("objectColor", glm::vec3(1.0f, 0.5f, 0.31f));
}

void set_twin_one(const glt::context& c, const glt::feedback_program& p, const scene_lights& s)
{
    const glt::functions& gl = c.gl();
    set_common(c, p, s);
    const auto v3 = [&](const char* n, glm::vec3 v) { gl.glUniform3fv(p.uniform(n), 1, &v.x); };
    const glm::vec3 object(1.0f, 0.5f, 0.31f);
    // (0.1 L + diff L + 0.5 spec L) object: ka = object with La = 0.1 L; kd = object, Ld = L; ks = 0.5 object, Ls = L.
    v3("material.ka", object), v3("material.kd", object), v3("material.ks", 0.5f * object);
    gl.glUniform1f(p.uniform("material.shininess"), 32);
    const glm::vec4 position(1.2f, 1.0f, 2.0f, 1);
    gl.glUniform4fv(p.uniform("lights[0].position"), 1, &position.x);
    v3("lights[0].ambient", glm::vec3(0.1f)), v3("lights[0].diffuse", glm::vec3(1)), v3("lights[0].specular", glm::vec3(1));
    const glm::vec4 eye(s.view_pos, 1);
    gl.glUniform4fv(p.uniform("environment.eye"), 1, &eye.x);
}

struct comparison {
    int differing = 0, worst = 0;
};

comparison compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
    comparison r;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        int d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a[i + std::size_t(k)]) - int(b[i + std::size_t(k)])));
        if (d > 0) ++r.differing;
        r.worst = std::max(r.worst, d);
    }
    return r;
}

} // namespace

int main(int argc, char** argv)
{
    // --callgrind: one frame of each program, each in its own callgrind dump (run under
    // valgrind --tool=callgrind --collect-atstart=no): instruction counts, repeatable where CPU
    // time on a shared machine is not.
    const bool count = argc > 1 && std::string(argv[1]) == "--callgrind";
    const int frames = count ? 1 : argc > 1 ? std::atoi(argv[1]) : 10;
    const int rounds = count ? 1 : argc > 2 ? std::atoi(argv[2]) : 21;
    if (frames < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: phong_glsl_tutorial_bench [frames per block >= 1] [rounds >= 1]\n");
        return 2;
    }
    setenv("LP_NUM_THREADS", "0", 0); // llvmpipe shades on this thread: its CPU time is the frame's
    try {
        glt::context c(glt::api::gl33_core);
        const glt::functions& gl = c.gl();
        std::printf("%s: %s (EGL %s), LP_NUM_THREADS=%s, %dx%d\n", c.renderer().c_str(), c.version().c_str(), c.platform().c_str(),
                    std::getenv("LP_NUM_THREADS"), width, height);
        const std::string twin = phong::glsl::source();
        frame_program hand6(c, hand_six), port6(c, phong::glsl::shader("#version 330 core", six_defines, twin, port_six_body));
        frame_program twin6(c, phong::glsl::shader("#version 330 core", twin_six_defines, twin, twin_body));
        frame_program twin6all(c, phong::glsl::shader("#version 330 core", six_defines, twin, twin_body));
        frame_program hand6u(c, hand_six_twin_uniforms(false)), hand6uall(c, hand_six_twin_uniforms(true));
        frame_program hand1(c, hand_one), port1(c, phong::glsl::shader("#version 330 core", twin_one_defines, twin, port_one_body));
        frame_program hand1m(c, hand_one_materials), twin1(c, phong::glsl::shader("#version 330 core", twin_one_defines, twin, twin_one_body));
        // The target: 800x600 RGBA8, no depth (the height field does not overlap itself from this camera).
        GLuint fbo = 0, rb = 0;
        gl.glGenFramebuffers(1, &fbo);
        gl.glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        gl.glGenRenderbuffers(1, &rb);
        gl.glBindRenderbuffer(GL_RENDERBUFFER, rb);
        gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
        gl.glViewport(0, 0, width, height);
        // The maps: a warm wood-like diffuse map and a specular map bright on a grid of borders.
        gl.glActiveTexture(GL_TEXTURE0);
        const GLuint diffuse_map = make_texture(gl, [](float x, float y) {
            const float ring = 0.5f + 0.5f * std::sin(40 * std::sqrt((x - 0.3f) * (x - 0.3f) + (y - 0.6f) * (y - 0.6f)) + 6 * y);
            return glm::vec3(0.45f + 0.3f * ring, 0.28f + 0.18f * ring, 0.12f + 0.08f * ring);
        });
        gl.glActiveTexture(GL_TEXTURE1);
        const GLuint specular_map = make_texture(gl, [](float x, float y) {
            const float fx = std::fabs(x * 8 - std::round(x * 8)), fy = std::fabs(y * 8 - std::round(y * 8));
            return glm::vec3(std::min(fx, fy) < 0.08f ? 0.9f : 0.15f);
        });
        gl.glActiveTexture(GL_TEXTURE0);
        const std::vector<float> mesh = height_field(48);
        const int vertices = int(mesh.size() / 8);
        GLuint vao = 0, vbo = 0;
        gl.glGenVertexArrays(1, &vao);
        gl.glBindVertexArray(vao);
        gl.glGenBuffers(1, &vbo);
        gl.glBindBuffer(GL_ARRAY_BUFFER, vbo);
        gl.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.size() * sizeof(float)), mesh.data(), GL_STATIC_DRAW);
        for (GLuint i = 0; i < 3; ++i) {
            const GLint size = i == 2 ? 2 : 3;
            gl.glVertexAttribPointer(i, size, GL_FLOAT, GL_FALSE, 8 * sizeof(float), reinterpret_cast<const void*>(std::size_t(i) * 3 * sizeof(float)));
            gl.glEnableVertexAttribArray(i);
        }
        gl.glActiveTexture(GL_TEXTURE1);
        gl.glBindTexture(GL_TEXTURE_2D, specular_map);
        gl.glActiveTexture(GL_TEXTURE0);
        gl.glBindTexture(GL_TEXTURE_2D, diffuse_map);
        const scene_lights s;
        set_hand_six(c, hand6.program, s);
        set_hand_six(c, port6.program, s); // the ports keep the tutorial's uniforms
        set_twin_six(c, twin6.program, s);
        set_twin_six(c, twin6all.program, s);
        set_twin_six(c, hand6u.program, s); // the twin's uniform names
        set_twin_six(c, hand6uall.program, s);
        set_hand_one(c, hand1.program, s);
        set_hand_one(c, port1.program, s);
        set_twin_one(c, hand1m.program, s); // the twin's uniform names
        set_twin_one(c, twin1.program, s);
        const auto frame = [&](const glt::feedback_program& p) {
            gl.glUseProgram(p.id());
            gl.glClearColor(0, 0, 0, 1);
            gl.glClear(GL_COLOR_BUFFER_BIT);
            gl.glDrawArrays(GL_TRIANGLES, 0, vertices);
            gl.glFinish();
        };
        const auto image = [&](const glt::feedback_program& p) {
            frame(p);
            std::vector<unsigned char> pixels(std::size_t(width) * height * 4);
            gl.glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
            return pixels;
        };
        const auto report = [&](const char* name, const glt::feedback_program& hand, const glt::feedback_program& port) {
            const std::vector<unsigned char> a = image(hand), b = image(port); // also the warm-up (compilation on first draw)
            int lit = 0;
            for (std::size_t i = 0; i < a.size(); i += 4) lit += (a[i] | a[i + 1] | a[i + 2]) != 0;
            const comparison cmp = compare(a, b);
            if (count) {
                for (const bool is_hand : {true, false}) {
                    CALLGRIND_ZERO_STATS;
                    CALLGRIND_TOGGLE_COLLECT;
                    frame(is_hand ? hand : port);
                    CALLGRIND_TOGGLE_COLLECT;
                    const std::string label = std::string(name) + (is_hand ? ": by hand" : ": phong_shade");
                    CALLGRIND_DUMP_STATS_AT(label.c_str());
                }
                std::printf("%s: images: %d pixels differ, by at most %d / 255; instruction counts in the callgrind dumps\n", name,
                            cmp.differing, cmp.worst);
                return cmp;
            }
            std::vector<double> t_hand, t_twin, ratio;
            for (int r = 0; r < rounds; ++r) {
                double th = 0, tt = 0;
                for (int k = 0; k < 2; ++k) {
                    const bool hand_first = (r + k) % 2 == 0;
                    const double start = now();
                    for (int f = 0; f < frames; ++f) frame(hand_first ? hand : port);
                    (hand_first ? th : tt) = (now() - start) / frames;
                }
                t_hand.push_back(th), t_twin.push_back(tt), ratio.push_back(tt / th);
            }
            const double mh = median(t_hand), mt = median(t_twin);
            std::printf("%s: %d of %d pixels lit; images: %d pixels differ, by at most %d / 255\n", name, lit, width * height, cmp.differing,
                        cmp.worst);
            std::printf("  min ms: by hand %.2f, phong_shade %.2f, ratio of minima %.3f\n", *std::min_element(t_hand.begin(), t_hand.end()) * 1e3,
                        *std::min_element(t_twin.begin(), t_twin.end()) * 1e3,
                        *std::min_element(t_twin.begin(), t_twin.end()) / *std::min_element(t_hand.begin(), t_hand.end()));
            std::printf("  median thread CPU ms per frame (%d frames x %d rounds, interleaved): by hand %.2f, phong_shade %.2f; "
                        "phong_shade / by hand: ratio of medians %.3f, median of per-round ratios %.3f (min %.3f, max %.3f)\n",
                        frames, rounds, mh * 1e3, mt * 1e3, mt / mh, median(ratio), *std::min_element(ratio.begin(), ratio.end()),
                        *std::max_element(ratio.begin(), ratio.end()));
            return cmp;
        };
        const char* only = std::getenv("PHONG_BENCH_ONLY"); // "six" or "one": that case alone
        if (!only || std::string(only) == "six") {
            report("six lights (directional, 4 point, linear-edge spot; texture maps), the tutorial's uniforms", hand6.program, port6.program);
            report("six lights, phong_light uniforms, PHONG_SPOT_LIGHTS 1", hand6.program, twin6.program);
            report("six lights, phong_light uniforms, every light allowed a cone (PHONG_SPOT_LIGHTS = PHONG_MAX_LIGHTS)", hand6.program,
                   twin6all.program);
            report("six lights, phong_light uniforms, PHONG_SPOT_LIGHTS 1, against the same loop by hand over the same uniforms",
                   hand6u.program, twin6.program);
            report("six lights, phong_light uniforms, every light allowed a cone, against the same loop by hand over the same uniforms",
                   hand6uall.program, twin6all.program);
        }
        if (!only || std::string(only) == "one") {
            report("one light (basic specular), the tutorial's uniforms", hand1.program, port1.program);
            report("one light, phong_material / phong_light uniforms, against the Materials chapter's shader (the same uniforms)",
                   hand1m.program, twin1.program);
            report("one light, phong_material / phong_light uniforms, against the basic shader (two colour uniforms)", hand1.program,
                   twin1.program);
        }
        gl.glBindVertexArray(0);
        gl.glDeleteVertexArrays(1, &vao);
        gl.glDeleteBuffers(1, &vbo);
        gl.glDeleteTextures(1, &diffuse_map);
        gl.glDeleteTextures(1, &specular_map);
        gl.glDeleteRenderbuffers(1, &rb);
        gl.glDeleteFramebuffers(1, &fbo);
        if (gl.glGetError() != GL_NO_ERROR) throw std::runtime_error("GL error");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "phong_glsl_tutorial_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
