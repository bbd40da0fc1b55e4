// phong/glsl.hpp from C++17 without phong's CMake target (docs/glsl.md): the header compiles as
// C++17, finds phong.glsl beside itself (no PHONG_GLSL_DIR), and assembles a shader. The HLSL twin
// is in the hlsl folder beside glsl. Built and run by .ci/steps/55-glsl.sh with g++ and clang++,
// -std=c++17, against the source tree and the installed copy (pkg-config --cflags phong).
#include <phong/glsl.hpp>

#include <cstdio>
#include <fstream>

int main()
{
    const std::string dir = phong::glsl::directory();
    const std::string text = phong::glsl::source();
    const std::string shader = phong::glsl::shader("#version 330 core", "#define PHONG_PRESET_GLSL_ADS\n", text, "void main() {}\n");
    const bool hlsl = static_cast<bool>(std::ifstream(dir + "/../hlsl/phong.hlsl"));
    std::printf("C++%ld: phong.glsl in %s, %zu characters; shader %zu characters; phong.hlsl beside it: %s\n", __cplusplus / 100 % 100,
                dir.c_str(), text.size(), shader.size(), hlsl ? "yes" : "no");
    const bool ok = text.find("phong_shade(") != std::string::npos && shader.rfind("#version 330 core\n#define PHONG_PRESET_GLSL_ADS\n", 0) == 0 && hlsl;
    return ok ? 0 : 1;
}
