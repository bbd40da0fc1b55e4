// The power kernel's tables (phong/core/power.hpp) computed by constant evaluation, as the
// kernel computed them before they became literal tables: tests/tables.test.cpp checks every
// entry of the literals against these bit for bit, and tests/tools/print_tables.cpp prints the
// literals from them.
// SPDX-License-Identifier: MIT
#pragma once

#include <phong/core/constexpr_math.hpp>
#include <phong/core/power.hpp>

#include <array>
#include <bit>
#include <cstdint>

namespace phong_test::power_tables {

namespace pw = phong::detail::power;
namespace ce = phong::detail::ce;

inline constexpr long double wide_ln2 = ce::ln2;

/// Entry i: inv_c = 1 / c_i rounded to double, c_i the midpoint of the z whose bits lie in
/// [0.6875's bits + i 2^45, + (i + 1) 2^45) (exactly 1 for the interval that holds 1), and
/// log2_c = log2(1 / inv_c) = -ln(inv_c) / ln 2 in long double, rounded to double.
constexpr std::array<pw::log2_point, (1 << pw::log_table_bits)> make_log2_table()
{
    std::array<pw::log2_point, (1 << pw::log_table_bits)> t{};
    for (int i = 0; i < (1 << pw::log_table_bits); ++i) {
        const double lo = std::bit_cast<double>(pw::log_offset + (pw::u64(i) << (52 - pw::log_table_bits)));
        const double hi = std::bit_cast<double>(pw::log_offset + (pw::u64(i + 1) << (52 - pw::log_table_bits)));
        const double inv_c = (lo <= 1.0 && 1.0 < hi) ? 1.0 : 2.0 / (lo + hi);
        t[i] = {inv_c, static_cast<double>(-ce::log(inv_c) / wide_ln2)};
    }
    return t;
}

/// Entry j: bits(2^(j/64)) - (j << 46), 2^(j/64) = exp(j/64 ln 2) in long double rounded to double.
constexpr std::array<pw::u64, (1 << pw::exp_table_bits)> make_exp2_table()
{
    std::array<pw::u64, (1 << pw::exp_table_bits)> t{};
    for (int j = 0; j < (1 << pw::exp_table_bits); ++j) {
        const double v = static_cast<double>(ce::exp(static_cast<long double>(j) / (1 << pw::exp_table_bits) * wide_ln2));
        t[j] = std::bit_cast<pw::u64>(v) - (pw::u64(j) << (52 - pw::exp_table_bits));
    }
    return t;
}

/// The Taylor coefficients: log2(1 + r) = sum_n (-1)^(n+1) r^n / (n ln 2) (a1..a7) and
/// 2^t = sum_n (t ln 2)^n / n! (b1..b5), each from long double rounded to double.
constexpr std::array<double, 7> log2_coefficients()
{
    constexpr long double inv_ln2 = 1 / wide_ln2;
    return {double(inv_ln2), double(-inv_ln2 / 2), double(inv_ln2 / 3), double(-inv_ln2 / 4),
            double(inv_ln2 / 5), double(-inv_ln2 / 6), double(inv_ln2 / 7)};
}
constexpr std::array<double, 5> exp2_coefficients()
{
    constexpr long double l = wide_ln2;
    return {double(l), double(l * l / 2), double(l * l * l / 6), double(l * l * l * l / 24), double(l * l * l * l * l / 120)};
}

} // namespace phong_test::power_tables
