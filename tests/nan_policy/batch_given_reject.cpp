// shade_batch with view_model::given needs the per-point view vectors: the soa3 overloads (no
// views) are a compile error naming soa_points/aos_points. Case 0 is the valid control (views
// through aos_points); case 1 must fail. Built by tests/nan_policy/checks.cmake.
#include <phong/batch.hpp>

#include <vector>

int main()
{
    using namespace phong;
    std::vector<glm::vec3> p(3, glm::vec3(0, 0, -2)), n(3, glm::vec3(0, 0, 1)), v(3, glm::vec3(0, 0, 1)), out(3);
    std::vector<light<float>> lights(1);
    const material<float> mat{};
#if PHONG_REJECT_CASE == 0
    shade_batch<presets::raytracer_phong>(aos_points<float>{.positions = p, .normals = n, .views = v}, mat, lights, out);
#else
    std::vector<float> x(3);
    shade_batch<presets::raytracer_phong>(soa3<float>{x, x, x}, soa3<float>{x, x, x}, mat, std::span<const light<float>>(lights),
                                          std::span<glm::vec3>(out));
#endif
    return out[0].r >= 0 ? 0 : 1;
}
