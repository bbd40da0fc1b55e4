// vec3_of (phong/inputs/adapt.hpp, issue 27): a renderer's own vector types as glm::vec<3, T>. Expected
// values: the components as written; the conversion changes no bit of shade_incident's colour.
#include <phong/inputs/adapt.hpp>
#include <phong/sum/incident.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstring>

namespace {
template <class T> struct xyz_vec { T x, y, z; };
template <class T> struct array_vec {
    T e[3];
    constexpr const T& operator[](int i) const { return e[i]; }
};
struct packed_vec { // neither: read through vector_traits
    double data[3];
};
class rgb_class { // made by a constructor with another order of arguments: vector_traits::make
public:
    constexpr rgb_class(float b, float g, float r) : b_(b), g_(g), r_(r) {}
    constexpr float r() const { return r_; }
    constexpr float g() const { return g_; }
    constexpr float b() const { return b_; }
private:
    float b_, g_, r_;
};
} // namespace

template <> struct phong::vector_traits<packed_vec> {
    PHONG_INLINE static constexpr double x(const packed_vec& v) { return v.data[0]; }
    PHONG_INLINE static constexpr double y(const packed_vec& v) { return v.data[1]; }
    PHONG_INLINE static constexpr double z(const packed_vec& v) { return v.data[2]; }
};

template <> struct phong::vector_traits<rgb_class> {
    PHONG_INLINE static constexpr float x(const rgb_class& v) { return v.r(); }
    PHONG_INLINE static constexpr float y(const rgb_class& v) { return v.g(); }
    PHONG_INLINE static constexpr float z(const rgb_class& v) { return v.b(); }
    PHONG_INLINE static constexpr rgb_class make(float r, float g, float b) { return rgb_class(b, g, r); }
};

static_assert(phong::vec3_of(xyz_vec<float>{1, 2, 3}) == glm::vec3(1, 2, 3));
// from_vec3, the way back: an aggregate by V{x, y, z}, a class through vector_traits::make; a
// round trip gives the components as written, and rgba passes its xyz.
static_assert(phong::from_vec3<xyz_vec<float>>(glm::vec3(1, 2, 3)).y == 2.0f);
static_assert(phong::from_vec3<xyz_vec<double>>(glm::dvec4(1, 2, 3, 0.5)).z == 3.0);
static_assert(phong::from_vec3<rgb_class>(glm::vec3(0.25f, 0.5f, 0.75f)).r() == 0.25f);
static_assert(phong::from_vec3<rgb_class>(glm::vec3(0.25f, 0.5f, 0.75f)).b() == 0.75f);
static_assert(phong::vec3_of(phong::from_vec3<rgb_class>(glm::vec3(4, 5, 6))) == glm::vec3(4, 5, 6));
static_assert(phong::vec3_of(phong::from_vec3<xyz_vec<double>>(glm::dvec3(-1, 0, 1e300))) == glm::dvec3(-1, 0, 1e300));
static_assert(phong::vec3_of(array_vec<double>{{4, 5, 6}}) == glm::dvec3(4, 5, 6));
static_assert(phong::vec3_of(packed_vec{{7, 8, 9}}) == glm::dvec3(7, 8, 9));
static_assert(std::is_same_v<decltype(phong::vec3_of(xyz_vec<double>{})), glm::dvec3>);

TEST_CASE_TEMPLATE("vec3_of: the components as written, and shade_incident's colour unchanged", T, float, double)
{
    using vec3 = glm::vec<3, T>;
    const xyz_vec<T> n{T(0.36), T(0.48), T(0.8)}; // unit: 0.1296 + 0.2304 + 0.64 = 1
    const array_vec<T> v{{T(0), T(0), T(1)}};
    CHECK(phong::vec3_of(n) == vec3(T(0.36), T(0.48), T(0.8)));
    CHECK(phong::vec3_of(v) == vec3(T(0), T(0), T(1)));
    constexpr phong::features F = [] {
        phong::features f = phong::presets::raytracer_phong;
        f.unit_inputs = true;
        return f;
    }();
    const std::array lights{phong::light<T>::with_strength(glm::vec<4, T>(T(0), T(3), T(4), T(1)), vec3(T(1)))};
    const std::array<phong::incident<T>, 1> in{phong::incident<T>{vec3(T(0), T(0.6), T(0.8)), T(5)}};
    const phong::material<T> mat{vec3(T(0.1)), vec3(T(0.5)), vec3(T(0.25)), vec3(T(0)), T(8), T(1)};
    const vec3 a = phong::shade_incident<F>(phong::vec3_of(n), phong::vec3_of(v), mat, lights, in);
    const vec3 b = phong::shade_incident<F>(vec3(T(0.36), T(0.48), T(0.8)), vec3(T(0), T(0), T(1)), mat, lights, in);
    CHECK(std::memcmp(&a, &b, sizeof a) == 0);
}
