// World-space lighting with mixed lights and texture maps through the twin (the shape of a
// tutorial's multiple-lights chapter: a directional light, point lights with constant, linear and
// quadratic attenuation, a flashlight with a linear edge between two cones, per-light ambient,
// Phong specular with no n.l gate, diffuse and specular maps). glShaderSource gets four strings:
// "#version 330 core\n", these defines (one per line, without the comment marks), phong.glsl's
// text, and this file.
//   #define PHONG_SCENE_AMBIENT 0
//   #define PHONG_LIGHT_AMBIENT 1
//   #define PHONG_SPECULAR_GATE 0
//   #define PHONG_ATTENUATION PHONG_ATTENUATION_POLYNOMIAL
//   #define PHONG_SPOT PHONG_SPOT_LINEAR
//   #define PHONG_VIEW PHONG_VIEW_EYE_POINT
//   #define PHONG_MAX_LIGHTS 8
in vec3 world_position; // from the vertex shader: model * position
in vec3 world_normal;   // normal matrix * normal (any length)
in vec2 uv;

uniform highp sampler2D diffuse_map;  // ka = kd = its rgb (highp: GLSL ES samplers are lowp by default)
uniform highp sampler2D specular_map; // ks = its rgb
uniform float shininess;
// Directional light: position = vec4(-direction, 0) (xyz points toward the light).
// Point light: position = vec4(p, 1), attenuation.constant, .linear, .quadratic.
// Spot light: a point light plus spot.direction (pointing away from the light), spot.cos_inner,
// spot.cos_outer (cosines of the inner and outer angles). A light whose spot fields are left at 0
// has no cone.
uniform phong_light lights[PHONG_MAX_LIGHTS];
uniform int light_count; // lights[0 .. light_count - 1] are used
uniform phong_environment environment; // eye = vec4(camera position, 1)

out vec4 frag_color;

void main()
{
    vec3 albedo = texture(diffuse_map, uv).rgb;
    phong_material material;
    material.ka = albedo;
    material.kd = albedo;
    material.ks = texture(specular_map, uv).rgb;
    material.emission = vec3(0.0);
    material.shininess = shininess;
    material.alpha = 1.0;
    // phong_shade returns a vec3 here (a vec4 only with PHONG_ALPHA); the last argument is read
    // only with PHONG_TWO_SIDED PHONG_FACING_FLAG.
    vec3 color = phong_shade(world_position, world_normal, vec3(0.0), material, lights, light_count, environment, true);
    frag_color = vec4(color, 1.0);
}
