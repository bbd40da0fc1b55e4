// phong: closes the region opened by diagnostics_push.hpp (no include guard, on purpose).
// SPDX-License-Identifier: MIT
#include "../../core/diagnostics_pop.hpp"
