// Compile-only check that phong/bsdf.hpp works in CUDA device code (no GPU needed), with and
// without --use_fast_math (.ci/steps/50-cuda.sh): both BSDFs, float and double, every function a
// path tracer calls per sample (local_frame, sample, eval, eval_cos, pdf, validate). The directional
// albedo (std::acos, a quadrature) is host code.
#include <phong/bsdf.hpp>

namespace {

template <class T, class Bsdf>
__device__ T one_sample(const Bsdf& b, const glm::vec<3, T>& n, const glm::vec<3, T>& wo_world, T u0, T u1)
{
    const phong::shading_frame<T> frame = phong::local_frame(n);
    const glm::vec<3, T> wo = frame.to_local(wo_world);
    const phong::bsdf_sample<T> s = b.sample(wo, glm::vec<2, T>(u0, u1));
    const glm::vec<3, T> wi_world = frame.to_world(s.wi);
    return s.weight.x + s.pdf + b.pdf(wo, s.wi) + b.eval(wo, s.wi).y + b.eval_cos(wo, s.wi).z + wi_world.x +
           (phong::validate(b) ? T(0) : T(1));
}

} // namespace

__global__ void bsdf_kernel(float* out, const float* u, int n)
{
    const int i = int(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= n) return;
    phong::material<float> mf;
    mf.kd = glm::vec3(0.3f);
    mf.ks = glm::vec3(0.6f);
    mf.shininess = 1e3f;
    phong::material<double> md;
    md.kd = glm::dvec3(0.3);
    md.ks = glm::dvec3(0.6);
    md.shininess = 10.0;
    const glm::vec3 nf(0.0f, 0.6f, 0.8f), wof(0.0f, 0.0f, 1.0f);
    const glm::dvec3 nd(nf), wod(wof);
    out[i] = one_sample<float>(phong::modified_phong_bsdf<float>(mf), nf, wof, u[i], u[i + n]) +
             one_sample<float>(phong::blinn_phong_bsdf<float>(mf), nf, wof, u[i], u[i + n]) +
             float(one_sample<double>(phong::modified_phong_bsdf<double>(md), nd, wod, double(u[i]), double(u[i + n]))) +
             float(one_sample<double>(phong::blinn_phong_bsdf<double>(md, phong::blinn_normalization::approximate), nd, wod,
                                      double(u[i]), double(u[i + n])));
}
