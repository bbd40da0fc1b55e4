// Test support: RapidCheck inside doctest. Debian's RapidCheck snapshot has no doctest adapter:
// rc::check returns whether the property held; CHECK that. The seed is pinned by RC_PARAMS in
// ctest's environment (tests/CMakeLists.txt); on failure RapidCheck prints the reproduce line.
#pragma once

#include <doctest/doctest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <string>

namespace phong_test {

/// CHECKs that the property holds for RapidCheck's generated inputs.
template <class Property> void check_property(const char* description, Property&& property)
{
    const bool ok = rc::check(description, std::forward<Property>(property));
    CHECK_MESSAGE(ok, std::string(description)); // doctest prints a const char* as a pointer
}

/// A float on a grid: integer i in [lo, hi] times step. RapidCheck's float generators never give
/// NaN/Inf and gen::inRange is integer-based, so float inputs are built from integer grids.
template <class T> rc::Gen<T> grid(int lo, int hi, T step)
{
    return rc::gen::map(rc::gen::inRange(lo, hi + 1), [step](int i) { return T(i) * step; });
}

} // namespace phong_test
