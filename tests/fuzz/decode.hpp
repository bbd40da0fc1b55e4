// Shared decoding of the fuzzers' inputs (fuzz_shade.cpp, fuzz_batch.cpp): one scalar from a tag
// byte, and vectors of them. Reader: any type with std::uint8_t byte().
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>
#include <limits>

namespace phong_fuzz {

/// One scalar. Tag byte: < 0x20 raw bit pattern (sizeof(T) bytes follow); < 0x40 one of 32 special
/// values; otherwise a grid value: coefficients (tag - 0x40) / 16 in [0, 12), coordinates and
/// cosines (`signed_grid`) (tag - 0xA0) / 8 in [-12, 12).
template <class T, class Reader> T scalar(Reader& in, bool signed_grid = false)
{
    using lim = std::numeric_limits<T>;
    const std::uint8_t tag = in.byte();
    if (tag < 0x20) {
        unsigned char bytes[sizeof(T)];
        for (auto& b : bytes) b = in.byte();
        T x;
        std::memcpy(&x, bytes, sizeof(T));
        return x;
    }
    if (tag < 0x40) {
        const T special[32] = {T(0), -T(0), T(1), T(-1), T(0.5), T(2), lim::infinity(), -lim::infinity(),
                               lim::quiet_NaN(), -lim::quiet_NaN(), lim::max(), lim::lowest(), lim::min(), -lim::min(),
                               lim::denorm_min(), -lim::denorm_min(), lim::epsilon(), T(1) + lim::epsilon(),
                               T(1) - lim::epsilon() / 2, T(1e-20), T(1e20), T(1e-30), T(1e30), T(65536),
                               T(3), T(200), T(1e5), T(0.998), T(1.002), T(0.999), T(1.0005), T(-1) - lim::epsilon()};
        return special[tag - 0x20];
    }
    return signed_grid ? T(int(tag) - 0xA0) / T(8) : T(int(tag) - 0x40) / T(16);
}

/// L scalars.
template <int L, class T, class Reader> glm::vec<L, T> vec(Reader& in, bool signed_grid = false)
{
    glm::vec<L, T> v;
    for (int k = 0; k < L; ++k) v[k] = scalar<T>(in, signed_grid);
    return v;
}

} // namespace phong_fuzz
