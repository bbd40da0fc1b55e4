// phong: everything. Include this, or only the headers you use (each compiles on its own).
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
#include "accuracy.hpp"
#include "shade.hpp"
#include "incident.hpp"
#include "adapt.hpp"
#include "batch.hpp"
#include "primitives.hpp"
