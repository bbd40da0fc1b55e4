#!/usr/bin/env bash
# Compiles include/phong/glsl/phong.glsl with glslangValidator (Debian: glslang-tools) for GLSL
# 330 core, 450 core and 300 es, in a vertex and a fragment shader, for every preset and for
# feature sets that reach every branch (spots, windowed attenuation, every view model, two-sided
# by flag, unit inputs, the fast mode, no-ambient/no-diffuse, the linear cone); then the HLSL twin
# (phong.hlsl) through glslang's HLSL front end and spirv-val. Usage: tests/glsl/validate.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
twin="$root/include/phong/glsl/phong.glsl"
command -v glslangValidator >/dev/null || { echo "validate.sh: glslangValidator not found (apt-get install glslang-tools)"; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
feature_sets=(
  "PHONG_PRESET_CLASSIC_PHONG"
  "PHONG_PRESET_BLINN_PHONG_PER_LIGHT_AMBIENT"
  "PHONG_PRESET_RAYTRACER_PHONG"
  "PHONG_PRESET_GLSL_ADS"
  "PHONG_PRESET_DIFFUSE_ONLY"
  ""
  "PHONG_SPOT=PHONG_SPOT_OPENGL PHONG_ATTENUATION=PHONG_ATTENUATION_WINDOWED PHONG_LIGHT_AMBIENT=1 PHONG_EMISSION=1"
  "PHONG_SPOT=PHONG_SPOT_SMOOTH PHONG_SPECULAR=PHONG_SPECULAR_BLINN PHONG_ATTENUATE_AMBIENT=0 PHONG_LIGHT_AMBIENT=1"
  "PHONG_SPOT=PHONG_SPOT_OPENGL PHONG_SPECULAR=PHONG_SPECULAR_NONE PHONG_LIGHTS=PHONG_LIGHTS_DIRECTIONAL"
  "PHONG_SPOT=PHONG_SPOT_LINEAR PHONG_SPOT_LIGHTS=1 PHONG_MAX_LIGHTS=4 PHONG_LIGHT_AMBIENT=1"
  "PHONG_SPOT=PHONG_SPOT_LINEAR PHONG_SCENE_AMBIENT=0 PHONG_LIGHT_AMBIENT=1 PHONG_SPECULAR_GATE=0 PHONG_ATTENUATION=PHONG_ATTENUATION_POLYNOMIAL PHONG_VIEW=PHONG_VIEW_EYE_POINT"
  "PHONG_VIEW=PHONG_VIEW_FIXED_DIRECTION PHONG_TWO_SIDED=PHONG_FACING_FLAG PHONG_ALPHA=1"
  "PHONG_VIEW=PHONG_VIEW_GIVEN PHONG_UNIT_INPUTS=1 PHONG_MODE=PHONG_MODE_FAST PHONG_SPECULAR=PHONG_SPECULAR_BLINN"
  "PHONG_VIEW=PHONG_VIEW_EYE_POINT PHONG_TWO_SIDED=PHONG_FACING_VIEW PHONG_SPECULAR=PHONG_SPECULAR_NONE PHONG_MAX_LIGHTS=1"
  "PHONG_SCENE_AMBIENT=0 PHONG_DIFFUSE=0 PHONG_SPECULAR_GATE=0 PHONG_MODE=PHONG_MODE_FAST"
)
count=0
for version in "330 core" "450 core" "300 es"; do
  for i in "${!feature_sets[@]}"; do
    defines=""
    for d in ${feature_sets[$i]}; do defines+="#define ${d/=/ }"$'\n'; done
    for stage in vert frag; do
      f="$tmp/set$i.${version// /_}.$stage"
      {
        echo "#version $version"
        printf '%s' "$defines"
        cat "$twin"
        echo "uniform phong_material material;"
        echo "uniform phong_light lights[PHONG_MAX_LIGHTS];"
        echo "uniform int light_count;"
        echo "uniform phong_environment environment;"
        if [[ $stage == vert ]]; then
          echo "in vec3 position; in vec3 normal; uniform mat4 model_view; uniform mat3 normal_matrix; out vec4 colour;"
          echo "void main() {"
          echo "  phong_color c = phong_shade(position, normal, -position, material, lights, light_count, environment, true);"
          echo "  phong_shading_terms t = phong_shade_terms(position, normal, -position, material, lights, light_count, environment, true);"
          echo "#if PHONG_VIEW != PHONG_VIEW_GIVEN"
          echo "  c += phong_shade_vertex(position, normal, model_view, normal_matrix, material, lights, light_count, environment);"
          echo "#endif"
          echo "  float dist; vec3 l = phong_toward(vec4(position, 1.0), normal, dist) + phong_light_direction(vec4(normal, 0.0), position);"
          echo "  float x = phong_specular_reflection(normal, l, -position, 2.0) + phong_specular_halfway(normal, l, -position, 2.0)"
          echo "          + phong_attenuation_polynomial(dist, 1.0, 0.0, 1.0) + phong_attenuation_windowed(dist, 10.0)"
          echo "          + phong_spot_opengl(l, normal, 2.0, 0.5) + phong_spot_smooth(l, normal, 0.9, 0.8) + phong_spot_linear(l, normal, 0.9, 0.8);"
          echo "  vec3 v = phong_view_perspective(position) + phong_view_orthographic(model_view) + phong_view_vector(vec4(0.0, 0.0, 0.0, 1.0), position);"
          echo "  colour = vec4(vec3(c) + t.diffuse + v + phong_face_viewer(normal, v) + phong_transform_normal(normal_matrix, normal), x);"
          echo "  gl_Position = vec4(position, 1.0);"
          echo "}"
        else
          echo "in vec3 ec_position; in vec3 ec_normal; out vec4 frag_colour;"
          echo "void main() {"
          echo "  phong_color c = phong_shade(ec_position, ec_normal, -ec_position, material, lights, light_count, environment, gl_FrontFacing);"
          echo "  frag_colour = vec4(vec3(c), 1.0);"
          echo "}"
        fi
      } >"$f"
      if ! out="$(glslangValidator "$f" 2>&1)"; then
        echo "$out"
        echo "validate.sh: FAILED: GLSL $version, $stage, defines: ${feature_sets[$i]:-(none: features{})}"
        exit 1
      fi
      count=$((count + 1))
    done
  done
done
echo "validate.sh: phong.glsl compiles in $count shaders (GLSL 330 core, 450 core, 300 es; ${#feature_sets[@]} feature sets; vertex and fragment)"

# docs/glsl.md's fragment shaders that carry their defines in their comment ("//   #define ..."):
# compiled with them, in GLSL 330 core, 450 core and 300 es (phong_glsl_tests renders recipe_world.frag).
for recipe in recipe_world blocks; do
  for version in "330 core" "450 core" "300 es"; do
    f="$tmp/$recipe.${version// /_}.frag"
    { echo "#version $version"; sed -n 's|^//   \(#define .*\)$|\1|p' "$root/tests/glsl/$recipe.frag"; cat "$twin" "$root/tests/glsl/$recipe.frag"; } >"$f"
    if ! out="$(glslangValidator "$f" 2>&1)"; then
      echo "$out"
      echo "validate.sh: FAILED: tests/glsl/$recipe.frag in GLSL $version"
      exit 1
    fi
  done
done
echo "validate.sh: tests/glsl/recipe_world.frag and blocks.frag compile with their defines (GLSL 330 core, 450 core, 300 es)"

# The HLSL twin (include/phong/hlsl/phong.hlsl, the same source through a few macros): glslang's HLSL
# front end (-D) compiles tests/glsl/case.hlsl (a vertex shader: the test's) and a pixel shader with
# the lights in a constant buffer, for every feature set, to SPIR-V; spirv-val validates it.
command -v spirv-val >/dev/null || { echo "validate.sh: spirv-val not found (apt-get install spirv-tools)"; exit 1; }
count=0
for i in "${!feature_sets[@]}"; do
  defines=""
  for d in ${feature_sets[$i]}; do defines+="#define ${d/=/ }"$'\n'; done
  for stage in vert frag; do
    f="$tmp/hlsl$i.$stage.hlsl"
    {
      printf '%s' "$defines"
      if [[ $stage == vert ]]; then
        echo '#include "case.hlsl"'
      else
        echo '#include "phong/hlsl/phong.hlsl"'
        echo "cbuffer scene { phong_material material; phong_light lights[PHONG_MAX_LIGHTS]; int light_count; phong_environment environment; };"
        echo "float4 main(float3 position : TEXCOORD0, float3 normal : TEXCOORD1, bool front : SV_IsFrontFace) : SV_Target {"
        echo "  phong_color c = phong_shade(position, normal, -position, material, lights, light_count, environment, front);"
        echo "  float dist; float3 l = phong_toward(float4(position, 1.0), normal, dist);"
        echo "  float x = phong_specular_reflection(normal, l, -position, 2.0) + phong_specular_halfway(normal, l, -position, 2.0)"
        echo "          + phong_spot_opengl(l, normal, 2.0, 0.5) + phong_spot_smooth(l, normal, 0.9, 0.8) + phong_spot_linear(l, normal, 0.9, 0.8);"
        echo "  float4x4 m = float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);"
        echo "  float3 v = phong_view_orthographic(m) + phong_transform_normal((float3x3)m, normal);"
        echo "#if PHONG_VIEW != PHONG_VIEW_GIVEN"
        echo "  c += phong_shade_vertex(position, normal, m, (float3x3)m, material, lights, light_count, environment);"
        echo "#endif"
        echo "  return float4(float3(c.x, c.y, c.z) + v, x);"
        echo "}"
      fi
    } >"$f"
    hlsl_stage=$([[ $stage == vert ]] && echo vert || echo frag)
    if ! out="$(glslangValidator -D -e main -V -S "$hlsl_stage" -I"$root/include" -I"$root/tests/glsl" "$f" -o "$f.spv" 2>&1)" ||
       ! out2="$(spirv-val "$f.spv" 2>&1)"; then
      echo "$out" "${out2:-}"
      echo "validate.sh: FAILED: HLSL, $stage, defines: ${feature_sets[$i]:-(none: features{})}"
      exit 1
    fi
    count=$((count + 1))
  done
done
# docs/glsl.md's HLSL example (its ```hlsl block), as a pixel shader.
awk '/^```hlsl/ { f = 1; next } f && /^```/ { exit } f { print }' "$root/docs/glsl.md" >"$tmp/doc.hlsl"
[[ -s "$tmp/doc.hlsl" ]] || { echo "validate.sh: docs/glsl.md has no hlsl block"; exit 1; }
if ! out="$(glslangValidator -D -e main -V -S frag -I"$root/include" "$tmp/doc.hlsl" -o "$tmp/doc.spv" 2>&1)" ||
   ! out2="$(spirv-val "$tmp/doc.spv" 2>&1)"; then
  echo "$out" "${out2:-}"
  echo "validate.sh: FAILED: docs/glsl.md's HLSL example"
  exit 1
fi
count=$((count + 1))
echo "validate.sh: phong.hlsl compiles to valid SPIR-V in $count shaders (glslangValidator -D, spirv-val; ${#feature_sets[@]} feature sets, vertex and pixel; docs/glsl.md's example)"
