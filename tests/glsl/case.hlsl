// The HLSL twin's test shader (tests/glsl/glsl.test.cpp): the HLSL counterpart of the GLSL test's
// case shader. The feature #defines come first (the test writes them), then this file. Case
// SV_VertexID is read from the texture `cases` (one row per case, layout: glsl.test.cpp's pack),
// shaded by phong_shade, its colour returned as `result` (alpha 0 without PHONG_ALPHA).
// glslangValidator -D -e main -V -S vert compiles it to SPIR-V; spirv-cross turns that into GLSL,
// which the test runs on llvmpipe with transform feedback (output _entryPointOutput_result).
#include "phong/hlsl/phong.hlsl"

Texture2D<float4> cases;

struct vertex_out {
    float4 result : TEXCOORD0;
    float4 position : SV_Position;
};

float4 at(int i, int id) { return cases.Load(int3(i, id, 0)); }

vertex_out main(uint vertex_id : SV_VertexID)
{
    int id = int(vertex_id);
    phong_material mat;
    mat.ka = at(3, id).xyz; mat.alpha = at(3, id).w; mat.kd = at(4, id).xyz; mat.ks = at(5, id).xyz; mat.emission = at(6, id).xyz;
    mat.shininess = at(2, id).w;
    phong_environment env;
    env.ambient = at(7, id).xyz;
    env.eye = at(8, id);
    int count = int(at(1, id).w);
    phong_light lights[PHONG_MAX_LIGHTS];
    for (int i = 0; i < PHONG_MAX_LIGHTS; ++i) {
        int b = 9 + 6 * i;
        lights[i].position = at(b, id);
        lights[i].ambient = at(b + 1, id).xyz; lights[i].attenuation.range = at(b + 1, id).w;
        lights[i].diffuse = at(b + 2, id).xyz; lights[i].attenuation.constant = at(b + 2, id).w;
        lights[i].specular = at(b + 3, id).xyz; lights[i].attenuation.linear_ = at(b + 3, id).w;
        lights[i].spot.direction = at(b + 4, id).xyz; lights[i].attenuation.quadratic = at(b + 4, id).w;
        lights[i].spot.exponent = at(b + 5, id).x; lights[i].spot.cos_cutoff = at(b + 5, id).y;
        lights[i].spot.cos_inner = at(b + 5, id).z; lights[i].spot.cos_outer = at(b + 5, id).w;
    }
    phong_color c = phong_shade(at(0, id).xyz, at(1, id).xyz, at(2, id).xyz, mat, lights, count, env, at(0, id).w > 0.5);
    vertex_out o;
#if PHONG_ALPHA
    o.result = c;
#else
    o.result = float4(c, 0.0);
#endif
    o.position = float4(0.0, 0.0, 0.0, 1.0);
    return o;
}
