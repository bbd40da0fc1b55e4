// phong: the GLSL twin's source for a C++ program: phong.glsl's directory and text, the #define lines
// of a features value, and a shader assembled from them (docs/glsl.md). C++17, but defines(F), which
// takes a phong::features, needs C++20.
// SPDX-License-Identifier: MIT
#pragma once

#if __cplusplus >= 202002L
#include "inputs/features.hpp"
#endif

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>

namespace phong::glsl {

namespace detail {
/// Throws E(message); built without exceptions (-fno-exceptions), prints the message to stderr and
/// aborts instead.
template <class E> [[noreturn]] inline void fail(const std::string& message)
{
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
    throw E(message);
#else
    std::fprintf(stderr, "%s\n", message.c_str());
    std::abort();
#endif
}
} // namespace detail

/// The directory that holds phong.glsl: PHONG_GLSL_DIR (defined by the CMake target phong::phong),
/// else the folder glsl beside this header as __FILE__ names it; "" when __FILE__ names no folder.
inline std::string directory()
{
#if defined(PHONG_GLSL_DIR)
    return PHONG_GLSL_DIR;
#else
    const std::string here = __FILE__;
    const std::size_t slash = here.find_last_of("/\\");
    return slash == std::string::npos ? std::string() : here.substr(0, slash + 1) + "glsl";
#endif
}

/// The text of phong.glsl in `dir` (default: directory()). Throws std::runtime_error naming the
/// path when the file cannot be read (or when no directory is known); without exceptions, prints
/// that message and aborts.
inline std::string source(const std::string& dir = directory())
{
    if (dir.empty())
        detail::fail<std::runtime_error>("phong::glsl::source: no directory known (link phong::phong, use pkg-config's glsldir, or pass the directory)");
    const std::string path = dir + "/phong.glsl";
    std::ifstream in(path, std::ios::binary);
    if (!in) detail::fail<std::runtime_error>("phong::glsl::source: cannot read " + path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

#if __cplusplus >= 202002L
/// The #define lines that select F in phong.glsl (every field written out, no preset needed), then
/// PHONG_MAX_LIGHTS max_lights. Throws std::invalid_argument for evaluation::stable (C++ only: GLSL
/// ES has no double) and for max_lights < 1 (without exceptions: prints the message and aborts).
inline std::string defines(const features& F, int max_lights = 8)
{
    if (F.mode == evaluation::stable)
        detail::fail<std::invalid_argument>("phong::glsl::defines: features::mode = evaluation::stable has no GLSL twin (exact or fast)");
    if (max_lights < 1) detail::fail<std::invalid_argument>("phong::glsl::defines: max_lights must be at least 1");
    const auto flag = [](bool b) { return b ? "1" : "0"; };
    const char* specular[] = {"PHONG_SPECULAR_NONE", "PHONG_SPECULAR_PHONG", "PHONG_SPECULAR_BLINN"};
    const char* lights[] = {"PHONG_LIGHTS_ANY", "PHONG_LIGHTS_POSITIONAL", "PHONG_LIGHTS_DIRECTIONAL"};
    const char* attenuation[] = {"PHONG_ATTENUATION_NONE", "PHONG_ATTENUATION_POLYNOMIAL", "PHONG_ATTENUATION_WINDOWED"};
    const char* spot[] = {"PHONG_SPOT_NONE", "PHONG_SPOT_OPENGL", "PHONG_SPOT_SMOOTH", "PHONG_SPOT_LINEAR"};
    const char* facing_names[] = {"PHONG_FACING_NONE", "PHONG_FACING_VIEW", "PHONG_FACING_FLAG"};
    const char* view[] = {"PHONG_VIEW_EYE_AT_ORIGIN", "PHONG_VIEW_FIXED_DIRECTION", "PHONG_VIEW_EYE_POINT", "PHONG_VIEW_GIVEN"};
    std::string s;
    const auto line = [&](std::string_view name, std::string_view value) {
        s += "#define ";
        s += name;
        s += ' ';
        s += value;
        s += '\n';
    };
    line("PHONG_SCENE_AMBIENT", flag(F.scene_ambient));
    line("PHONG_LIGHT_AMBIENT", flag(F.light_ambient));
    line("PHONG_DIFFUSE", flag(F.diffuse));
    line("PHONG_SPECULAR", specular[static_cast<int>(F.specular)]);
    line("PHONG_SPECULAR_GATE", flag(F.specular_gate));
    line("PHONG_LIGHTS", lights[static_cast<int>(F.lights)]);
    line("PHONG_ATTENUATION", attenuation[static_cast<int>(F.attenuation)]);
    line("PHONG_SPOT", spot[static_cast<int>(F.spot)]);
    line("PHONG_ATTENUATE_AMBIENT", flag(F.attenuate_ambient));
    line("PHONG_TWO_SIDED", facing_names[static_cast<int>(F.two_sided)]);
    line("PHONG_VIEW", view[static_cast<int>(F.view)]);
    line("PHONG_EMISSION", flag(F.emission));
    line("PHONG_ALPHA", flag(F.alpha));
    line("PHONG_UNIT_INPUTS", flag(F.unit_inputs));
    line("PHONG_MODE", F.mode == evaluation::fast ? "PHONG_MODE_FAST" : "PHONG_MODE_EXACT");
    line("PHONG_MAX_LIGHTS", std::to_string(max_lights));
    return s;
}
#endif // C++20: defines(F)

/// One shader's text: version_line ("#version 330 core"), a newline, defines_text (defines(F), or
/// "#define PHONG_PRESET_GLSL_ADS\n"), phong.glsl's text (twin), then body after "#line 1 1", so that
/// a driver's compile errors point at body's own lines.
inline std::string shader(std::string_view version_line, std::string_view defines_text, std::string_view twin,
                          std::string_view body)
{
    std::string s;
    s.reserve(version_line.size() + defines_text.size() + twin.size() + body.size() + 32);
    s += version_line;
    s += '\n';
    s += defines_text;
    s += twin;
    s += "\n#line 1 1\n";
    s += body;
    return s;
}

} // namespace phong::glsl
