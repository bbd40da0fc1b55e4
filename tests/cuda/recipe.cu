// A CUDA translation unit that shades one point per thread with phong: the recipe of docs/cuda.md.
#include <phong/phong.hpp>

#include <cuda_runtime.h>

#include <span>

constexpr int max_lights = 16;
__constant__ phong::light<float> scene_lights[max_lights]; // uploaded with cudaMemcpyToSymbol

// The kernel takes the feature set as a type: nvcc cannot take template <phong::features F> __global__.
template <class Set>
__global__ void shade_points(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* colours,
                             phong::material<float> material, int count, int light_count)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= count) return;
    const std::span<const phong::light<float>> lights(scene_lights, static_cast<std::size_t>(light_count));
    colours[i] = phong::shade<Set::value>(positions[i], normals[i], material, lights);
}

constexpr phong::features ads_fast = phong::presets::with_mode(phong::presets::glsl_ads, phong::evaluation::fast);

// Host side: check the parameters once (the device does not), upload the lights, launch.
cudaError_t shade_all(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* colours, int count,
                      std::span<const phong::light<float>> lights, const phong::material<float>& material)
{
    if (lights.size() > max_lights || !phong::validate(material)) return cudaErrorInvalidValue;
    for (const phong::light<float>& light : lights)
        if (!phong::validate(light)) return cudaErrorInvalidValue;
    const cudaError_t copied = cudaMemcpyToSymbol(scene_lights, lights.data(), lights.size_bytes());
    if (copied != cudaSuccess) return copied;
    shade_points<phong::feature_set<ads_fast>><<<(count + 255) / 256, 256>>>(positions, normals, colours, material, count,
                                                                              static_cast<int>(lights.size()));
    return cudaGetLastError();
}
