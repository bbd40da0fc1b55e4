// phong: what a scalar renderer uses. Include this, or only the headers you use (each compiles on
// its own). The extensions are included by name: <phong/batch.hpp> (shade_batch, SIMD lanes),
// <phong/bsdf.hpp> (path-tracer BSDFs), <phong/primitives.hpp> (ray-primitive intersections),
// <phong/accuracy.hpp> (the published error bounds), <phong/glsl.hpp> (the GLSL twin's source).
// SPDX-License-Identifier: MIT
#pragma once

#include "core/math.hpp"
#include "core/vector.hpp"
#include "terms/direction.hpp"
#include "terms/view.hpp"
#include "terms/attenuation.hpp"
#include "terms/normal.hpp"
#include "terms/specular.hpp"
#include "inputs/validate.hpp"
#include "inputs/light.hpp"
#include "inputs/material.hpp"
#include "inputs/features.hpp"
#include "inputs/environment.hpp"
#include "sum/shade.hpp"
#include "sum/incident.hpp"
#include "inputs/adapt.hpp"
