// phong: opens the region of a phong header in which -Wfloat-equal is off: the model compares
// floats exactly on purpose (x == 0, m == 0, a value against its own rounding), and a user's
// -Wfloat-equal -Werror must still build. Closed by diagnostics_pop.hpp at the end of the same
// header (the user's own lines keep the warning); no include guard, on purpose.
// SPDX-License-Identifier: MIT
#if defined(__GNUC__) || defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wfloat-equal"
#endif
