// The published error bound of a variant for an input class, read from phong/accuracy.hpp when
// that header exists; -1 (none published) otherwise.
#pragma once

#include "inputs.hpp"

#include <phong/features.hpp>

namespace phong_bench {

template <class T>
double published_bound(const phong::features&, input_set)
{
    return -1;
}

} // namespace phong_bench
