// phong.hlsl: the HLSL twin of phong's C++ model, from the same source as the GLSL twin.
// SPDX-License-Identifier: MIT
//
// #include "phong/hlsl/phong.hlsl" (after the feature #defines, e.g. PHONG_PRESET_GLSL_ADS, or
// glslangValidator/dxc -D options). This file spells GLSL's names in HLSL and includes
// ../glsl/phong.glsl, which is written in the subset the two languages share: every function,
// struct, define and edge policy is the GLSL twin's (docs/glsl.md, "The HLSL twin"), under the same
// names (phong_shade, phong_light, ...), with float3/float4 for vec3/vec4.
// Matrices: phong_transform_normal and phong_shade_vertex take float3x3 / float4x4 in HLSL's own
// convention, mul(M, v) with M[row][column]; phong_view_orthographic reads the projection's
// element (row 0, column 2) as M[0][2].
// Reserved words: HLSL's `linear` (an interpolation modifier) is phong_falloff's field name in
// GLSL; here the field is named linear_ (PHONG_FALLOFF_LINEAR), and so is the C++ name in a
// constant buffer that mirrors phong_falloff.
#ifndef PHONG_HLSL_INCLUDED
#define PHONG_HLSL_INCLUDED

#define PHONG_HLSL 1
#define vec2 float2
#define vec3 float3
#define vec4 float4
#define ivec2 int2
#define ivec3 int3
#define ivec4 int4
#define mat3 float3x3
#define mat4 float4x4
#define inversesqrt rsqrt
#define floatBitsToUint asuint
#define uintBitsToFloat asfloat
#define mix lerp
#define fract frac
#define phong_const static const
#define phong_mul(M, v) mul(M, v)
#define phong_element(M, row, column) M[row][column]
#define PHONG_FALLOFF_LINEAR linear_

#include "../glsl/phong.glsl"

#endif // PHONG_HLSL_INCLUDED
