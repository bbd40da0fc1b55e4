// detail/config.hpp, issue 15 item 3: a failed precondition reaches the user with validate()'s
// message (which field, why) through a replaceable handler. The default handler (print, abort) is
// checked by tests/nan_policy/checks.cmake (a program that must die with the field in stderr);
// here: installing, restoring, and a custom handler receiving the message, file and line.
#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <array>
#include <limits>
#include <span>
#include <string>
#include <vector>

using namespace phong;

namespace {

struct call {
    std::string message, file;
    int line;
};
std::vector<call> calls;
void record(const char* message, const char* file, int line) { calls.push_back({message, file, line}); }
void other(const char*, const char*, int) {}

const std::array<light<float>, 1> one_light{light<float>::with_strength({0, 0, 1, 0}, {1, 1, 1})};

/// A renderer's own light type (one colour, a point light), read through light_traits.
struct point_light {
    glm::vec3 position, colour;
};

} // namespace

template <> struct phong::light_traits<point_light> {
    static glm::vec4 position(const point_light& L) { return glm::vec4(L.position, 1.0f); }
    static const glm::vec3& diffuse(const point_light& L) { return L.colour; }
    static const glm::vec3& specular(const point_light& L) { return L.colour; }
};

TEST_CASE("set_precondition_handler: returns the previous handler; nullptr restores the default")
{
    // (Compared into bools: doctest cannot print function pointers.)
    const precondition_handler original = get_precondition_handler();
    REQUIRE(static_cast<bool>(original));
    bool same = set_precondition_handler(&record) == original;
    CHECK(same);
    same = get_precondition_handler() == &record;
    CHECK(same);
    same = set_precondition_handler(&other) == &record;
    CHECK(same);
    same = set_precondition_handler(nullptr) == &other;
    CHECK(same);
    same = get_precondition_handler() == original; // the default again
    CHECK(same);
}

TEST_CASE("a failed precondition calls the installed handler with validate()'s message, file and line")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    material<float> mat{};
    mat.kd.y = -0.5f;
    const glm::vec3 c = shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), mat, one_light);
    light<float> w2 = one_light[0];
    w2.position = {0.0f, 0.0f, 2.0f, 2.0f};
    const std::array<light<float>, 1> bad_light{w2};
    (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, bad_light);
    set_precondition_handler(previous);
    (void)c;
#if defined(NDEBUG)
    CHECK(calls.empty()); // no check at all in release builds
#else
    REQUIRE(calls.size() == 2);
    // The field and the reason, as material.hpp and light.hpp document them.
    CHECK(calls[0].message.find("material.kd") == 0);
    CHECK(calls[0].message.find("negative") != std::string::npos);
    CHECK(calls[1].message.find("light.position.w") == 0);
    for (const call& k : calls) {
        CHECK(k.file.find("phong") != std::string::npos);
        CHECK(k.line > 0);
    }
#endif
}

TEST_CASE("a renderer's own light type: a failed precondition names the light<T> field it stands for")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const std::array<point_light, 3> bad{point_light{{0, 0, 2}, {1, -0.5f, 1}}, point_light{{nan, 0, 2}, {1, 1, 1}},
                                         point_light{{0, inf, 2}, {1, 1, 1}}};
    for (const point_light& L : bad) (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, std::array{L});
    set_precondition_handler(previous);
#if defined(NDEBUG)
    CHECK(calls.empty());
#else
    REQUIRE(calls.size() == 3);
    CHECK(calls[0].message.find("light.diffuse") == 0);
    CHECK(calls[1].message.find("light.position") == 0);
    CHECK(calls[2].message.find("light.position") == 0);
#endif
}

// weighted(lights, weights): a negative, NaN or inf weight is a bad parameter (visibility.hpp: each
// weight finite and >= 0), reported with the field's name, not shaded into a negative or NaN colour.
TEST_CASE("a bad visibility weight reaches the handler with the field it names")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const float w : {-0.5f, nan, inf}) {
        const std::array<float, 1> weights{w};
        (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{},
                                weighted(one_light, std::span<const float>(weights)));
    }
    const std::array<float, 1> fine{0.5f}; // in [0, 1]: no call
    (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, weighted(one_light, std::span<const float>(fine)));
    set_precondition_handler(previous);
#if defined(NDEBUG)
    CHECK(calls.empty());
#else
    REQUIRE(calls.size() == 3);
    for (const call& k : calls) CHECK(k.message.find("weighted: weights") != std::string::npos);
#endif
}

// A light list longer than the second range read with it (weighted()'s weights, shade_incident's
// incidents) would be a read past that range. In every build no light is shaded then (the scene's
// ambient term stays): nothing is read past the range. Debug builds report it (once per call for
// a list with a size); release builds do not call the handler.
TEST_CASE("fewer weights or incidents than lights: reported in debug builds, never read past in any")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    const std::array<light<float>, 2> two{one_light[0], light<float>::with_strength({1, 0, 1, 0}, {0.5f, 0.25f, 1})};
    const std::array<float, 2> weights{0.5f, 0.75f};
    const glm::vec3 p(0, 0, -2), n(0, 0, 1);
    const std::array<light<float>, 0> none{};
    const glm::vec3 short_weights = shade<features{}>(p, n, material<float>{}, weighted(two, std::span<const float>(weights.data(), 1)));
    const glm::vec3 unlit = shade<features{}>(p, n, material<float>{}, none);

    constexpr features given = [] {
        features f = presets::raytracer_phong;
        f.unit_inputs = true;
        return f;
    }();
    const std::array<incident<float>, 2> in{incident<float>{n, 0.0f}, incident<float>{glm::vec3(0.6f, 0.0f, 0.8f), 0.0f}};
    const glm::vec3 short_incidents = shade_incident<given>(n, n, material<float>{}, two, std::span<const incident<float>>(in.data(), 1));
    const glm::vec3 unlit_incident = shade_incident<given>(n, n, material<float>{}, none, std::span<const incident<float>>());
    // masked: an incident per light of the list, masked or not
    const glm::vec3 masked_short = shade_incident<given>(n, n, material<float>{}, masked(two, 1u), std::span<const incident<float>>(in.data(), 1));
    set_precondition_handler(previous);

#if defined(NDEBUG)
    CHECK(calls.empty());
#else
    REQUIRE(calls.size() == 3);
    CHECK(calls[0].message == "phong::weighted: fewer weights than lights");
    CHECK(calls[1].message == "phong::shade_incident: fewer incidents than lights");
    CHECK(calls[2].message == "phong::shade_incident: fewer incidents than lights");
#endif
    CHECK(short_weights == unlit);
    CHECK(short_incidents == unlit_incident);
    CHECK(masked_short == unlit_incident);
}

// The environment is a parameter as the material is: a negative or NaN scene ambient La is
// reported (environment.hpp's validate), not shaded.
TEST_CASE("a bad environment reaches the handler with the field it names")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    environment<float> env{};
    env.ambient.g = -0.25f;
    (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, one_light, env);
    env = {};
    env.eye = {0.0f, 0.0f, 1.0f, -1.0f};
    (void)shade<presets::classic_phong>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, one_light, env);
    set_precondition_handler(previous);
#if defined(NDEBUG)
    CHECK(calls.empty());
#else
    REQUIRE(calls.size() == 2);
    CHECK(calls[0].message.find("environment.ambient") == 0);
    CHECK(calls[1].message.find("environment.eye.w") == 0);
#endif
}

TEST_CASE("valid parameters never call the handler")
{
    calls.clear();
    const precondition_handler previous = set_precondition_handler(&record);
    (void)shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, one_light);
    set_precondition_handler(previous);
    CHECK(calls.empty());
}
