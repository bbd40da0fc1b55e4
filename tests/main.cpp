// The doctest runner for phong_tests (Debian's doctest has no main target).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
