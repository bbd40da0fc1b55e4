// Building blocks: a shader that keeps its own light type (a tutorial's PointLight array) and runs
// its own loop over it, through the twin's steps: phong_prepare (the frame at the point: the unit
// normal, the view vector, n.v), phong_add_light per light, then phong_terms_of (the material's
// products: emission, ambient, diffuse and specular terms) and phong_total_of (their sum).
// The defines before phong.glsl, as in recipe_world.frag:
//   #define PHONG_SCENE_AMBIENT 0
//   #define PHONG_LIGHT_AMBIENT 1
//   #define PHONG_SPECULAR_GATE 0
//   #define PHONG_LIGHTS PHONG_LIGHTS_POSITIONAL
//   #define PHONG_ATTENUATION PHONG_ATTENUATION_POLYNOMIAL
//   #define PHONG_VIEW PHONG_VIEW_EYE_POINT
struct PointLight {
    vec3 position;
    float constant;
    float linear;
    float quadratic;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
#define NR_POINT_LIGHTS 4

in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;

uniform PointLight pointLights[NR_POINT_LIGHTS];
uniform vec3 viewPos;
uniform highp sampler2D diffuse_map;
uniform highp sampler2D specular_map;
uniform float shininess;

out vec4 FragColor;

void main()
{
    phong_environment env;
    env.ambient = vec3(0.0); // no scene ambient (PHONG_SCENE_AMBIENT 0)
    env.eye = vec4(viewPos, 1.0);
    phong_frame frame = phong_prepare(FragPos, Normal, vec3(0.0), env, true);
    phong_sums sums;
    sums.ambient = vec3(0.0);
    sums.diffuse = vec3(0.0);
    sums.specular = vec3(0.0);
    for (int i = 0; i < NR_POINT_LIGHTS; ++i) {
        phong_light L;
        L.position = vec4(pointLights[i].position, 1.0);
        L.ambient = pointLights[i].ambient;
        L.diffuse = pointLights[i].diffuse;
        L.specular = pointLights[i].specular;
        L.attenuation.constant = pointLights[i].constant;
        L.attenuation.linear = pointLights[i].linear;
        L.attenuation.quadratic = pointLights[i].quadratic;
        L.attenuation.range = 1e30;      // read with PHONG_ATTENUATION_WINDOWED only
        L.spot.direction = vec3(0.0);    // no cone (read with PHONG_SPOT only)
        L.spot.exponent = 0.0;
        L.spot.cos_cutoff = -1.0;
        L.spot.cos_inner = -1.0;
        L.spot.cos_outer = -1.0;
        phong_add_light(sums, frame, L, shininess);
    }
    vec3 albedo = texture(diffuse_map, TexCoords).rgb;
    phong_material material;
    material.ka = albedo;
    material.kd = albedo;
    material.ks = texture(specular_map, TexCoords).rgb;
    material.emission = vec3(0.0);
    material.shininess = shininess;
    material.alpha = 1.0;
    FragColor = vec4(phong_total_of(phong_terms_of(sums, material, env)), 1.0);
}
