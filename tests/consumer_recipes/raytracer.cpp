#include <phong/phong.hpp>
#include <array>
#include <cstdint>
#include <cstdio>
#include <ranges>

// The renderer's own types.
struct point_light { glm::vec3 position, color; };
struct ray { glm::vec3 start, dir; };    // dir of unit length
struct hit { glm::vec3 point, normal; }; // normal of unit length

const std::array<point_light, 2> scene_lights{{{{2, 4, 3}, {1, 1, 1}}, {{-4, 1, -2}, {0.5f, 0.5f, 0.6f}}}};

// The renderer's shadow test (here: light 1 is always occluded).
bool reaches(const hit&, std::size_t light_index) { return light_index == 0; }

constexpr phong::features F = [] {
    phong::features f = phong::presets::raytracer_phong; // view_model::given
    f.unit_inputs = true;                                 // normal and ray direction are unit
    return f;
}();
const phong::material<float> mat{.ka = glm::vec3(0.1f), .kd = {0.7f, 0.2f, 0.2f}, .ks = glm::vec3(0.5f), .shininess = 50};
const phong::environment<float> env{.ambient = glm::vec3(0.2f)};

// How phong reads a point_light: a positional light whose colour is its diffuse and specular strength.
template <> struct phong::light_traits<point_light> {
    static glm::vec4 position(const point_light& p) { return glm::vec4(p.position, 1.0f); }
    static const glm::vec3& diffuse(const point_light& p) { return p.color; }
    static const glm::vec3& specular(const point_light& p) { return p.color; }
};

// The local colour at a hit, seen along ray r (primary or secondary).
glm::vec3 local_color(const hit& h, const ray& r) {
    std::uint64_t visible_bits = 0; // bit i: light i is seen
    for (std::size_t i = 0; i < scene_lights.size(); ++i)
        if (reaches(h, i)) visible_bits |= std::uint64_t{1} << i;
    return phong::shade<F>(h.point, h.normal, -r.dir, mat, phong::masked(scene_lights, visible_bits), env);
}

int main() {
    // A primary ray hits a sphere; its mirror ray hits the floor y = -1.
    const ray primary{{0, -0.6f, 5}, {0, 0, -1}};
    const hit on_sphere{{0, -0.6f, 0.8f}, {0, -0.6f, 0.8f}};
    const ray mirror{on_sphere.point, phong::reflect(primary.dir, on_sphere.normal)}; // (0, -0.96, 0.28)
    const float t = (-1 - mirror.start.y) / mirror.dir.y;
    const hit on_floor{mirror.start + t * mirror.dir, {0, 1, 0}};
    const glm::vec3 color = local_color(on_sphere, primary) + 0.3f * local_color(on_floor, mirror);
    std::printf("%.4f %.4f %.4f\n", color.r, color.g, color.b);

    // The same shadows with std::views::filter on the renderer's lights.
    const auto lit = [&](const point_light& p) { return &p == &scene_lights[0]; };
    const glm::vec3 filtered = phong::shade<F>(on_sphere.point, on_sphere.normal, -primary.dir, mat,
                                               scene_lights | std::views::filter(lit), env);
    return filtered == local_color(on_sphere, primary) ? 0 : 1; // the same lights in the same order: the same bits
}
