// phong: what a scalar renderer uses. Include this, or only the headers you use (each compiles on
// its own). The extensions are included by name: <phong/batch.hpp> (shade_batch, SIMD lanes),
// <phong/primitives.hpp> (ray-primitive intersections), <phong/accuracy.hpp> (the published error
// bounds), <phong/glsl.hpp> (the GLSL twin's source).
// SPDX-License-Identifier: MIT
#pragma once

#include "math.hpp"
#include "vector.hpp"
#include "direction.hpp"
#include "view.hpp"
#include "attenuation.hpp"
#include "normal.hpp"
#include "specular.hpp"
#include "validate.hpp"
#include "light.hpp"
#include "material.hpp"
#include "features.hpp"
#include "environment.hpp"
#include "shade.hpp"
#include "incident.hpp"
#include "adapt.hpp"
