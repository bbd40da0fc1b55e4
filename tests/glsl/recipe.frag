// Per-pixel lighting through the twin, classic Phong (presets::classic_phong): polynomial
// attenuation, two-sided normals, alpha. The program passes glShaderSource four strings:
// "#version 330 core\n" (or "#version 300 es\n"), "#define PHONG_PRESET_CLASSIC_PHONG\n",
// phong.glsl's text, and this file.
in vec3 ec_position; // the point in eye coordinates, from the vertex shader
in vec3 ec_normal;   // its normal in eye coordinates, any length

uniform phong_material material;
uniform phong_light lights[PHONG_MAX_LIGHTS];
uniform int light_count; // lights[0 .. light_count - 1] are used
uniform phong_environment environment;

out vec4 frag_color;

void main()
{
    frag_color = phong_shade(ec_position, ec_normal, vec3(0.0), material, lights, light_count, environment, gl_FrontFacing);
}
