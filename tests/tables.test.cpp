// The literal tables of the headers equal the constant evaluation they were printed from
// (tests/tools/print_tables.cpp), bit for bit: the power kernel's tables and coefficients
// (phong/core/power.hpp against tests/support/power_tables.hpp) and the derived accuracy bounds
// (phong/accuracy.hpp against tests/support/accuracy_analysis.hpp). A mismatch names the entry.
// SPDX-License-Identifier: MIT
#include "support/accuracy_analysis.hpp"
#include "support/power_tables.hpp"

#include <phong/accuracy.hpp>
#include <phong/core/power.hpp>

#include <doctest/doctest.h>

#include <bit>
#include <cstdint>

namespace {
std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }
} // namespace

TEST_CASE("tables: the power kernel's literal tables are the constant evaluation's, bit for bit")
{
    namespace pw = phong::detail::power;
    namespace pt = phong_test::power_tables;
    static constexpr auto log2_table = pt::make_log2_table();
    static constexpr auto exp2_table = pt::make_exp2_table();
    REQUIRE(pw::log2_table.size() == log2_table.size());
    for (std::size_t i = 0; i < log2_table.size(); ++i) {
        CAPTURE(i);
        CHECK(bits(pw::log2_table[i].inv_c) == bits(log2_table[i].inv_c));
        CHECK(bits(pw::log2_table[i].log2_c) == bits(log2_table[i].log2_c));
    }
    REQUIRE(pw::exp2_table.size() == exp2_table.size());
    for (std::size_t j = 0; j < exp2_table.size(); ++j) {
        CAPTURE(j);
        CHECK(pw::exp2_table[j] == exp2_table[j]);
    }
    static constexpr auto a = pt::log2_coefficients();
    const double literal_a[] = {pw::a1, pw::a2, pw::a3, pw::a4, pw::a5, pw::a6, pw::a7};
    for (std::size_t k = 0; k < a.size(); ++k) {
        CAPTURE(k + 1);
        CHECK(bits(literal_a[k]) == bits(a[k]));
    }
    static constexpr auto b = pt::exp2_coefficients();
    const double literal_b[] = {pw::b1, pw::b2, pw::b3, pw::b4, pw::b5};
    for (std::size_t k = 0; k < b.size(); ++k) {
        CAPTURE(k + 1);
        CHECK(bits(literal_b[k]) == bits(b[k]));
    }
    // The test would pass on two empty or all-zero tables: the entries are the kernel's.
    CHECK(pw::log2_table[80].inv_c == 1.0); // the interval holding 1
    CHECK(pw::exp2_table[0] == bits(1.0));
    CHECK(pw::b1 == doctest::Approx(0.6931471805599453).epsilon(1e-15));
}

namespace {
template <phong::evaluation M, class T> void check_derived(const char* table)
{
    namespace acc = phong::accuracy;
    static constexpr auto derived = acc::derived_bounds<M, T>;
    for (std::size_t i = 0; i < acc::input_class_count; ++i) {
        const auto c = static_cast<acc::input_class>(i);
        INFO(table << ", " << acc::name(c));
        const acc::bound published = acc::of<M, T>(c);
        CHECK(bits(published.p99_ulp) == bits(derived[i].p99_ulp));
        CHECK(bits(published.max_ulp) == bits(derived[i].max_ulp));
        CHECK(bits(published.max_rel) == bits(derived[i].max_rel));
        // Every P reads the same derived table.
        CHECK(bits((acc::of<M, T, phong::stable_precision::twofold>(c).max_rel)) == bits(derived[i].max_rel));
        // max_rel is the class bound of the analysis (its own function, not the table builder).
        if (c == acc::input_class::non_finite) continue; // no bound: +inf in every field
        const double class_bound = M == phong::evaluation::exact ? acc::exact_class_bound<T>(c) : acc::fast_class_bound<T>(c);
        CHECK(bits(published.max_rel) == bits(class_bound));
    }
}
} // namespace

TEST_CASE("tables: the exact and fast modes' published bounds are the error analysis's, bit for bit")
{
    check_derived<phong::evaluation::exact, float>("exact, float");
    check_derived<phong::evaluation::exact, double>("exact, double");
    check_derived<phong::evaluation::fast, float>("fast, float");
    check_derived<phong::evaluation::fast, double>("fast, double");
}
