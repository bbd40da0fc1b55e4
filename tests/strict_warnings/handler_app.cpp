// The executable of handler_library.cpp: installs its own precondition handler, calls the library,
// and exits 0 only if the library's failed check came to that handler (the default one aborts).
// SPDX-License-Identifier: MIT
#include <phong/phong.hpp>

#include <cstdio>

float library_shade();

namespace {
int calls = 0;
void count(const char* message, const char*, int) noexcept
{
    ++calls;
    std::printf("handler_app: the application's handler: %s\n", message);
}
} // namespace

int main()
{
    phong::set_precondition_handler(&count);
    (void)library_shade();
    return calls > 0 ? 0 : 1;
}
