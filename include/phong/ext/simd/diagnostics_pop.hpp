// phong: closes the region opened by diagnostics_push.hpp (no include guard, on purpose).
// SPDX-License-Identifier: MIT
#if defined(__GNUC__) || defined(__clang__)
#  pragma GCC diagnostic pop
#endif
