#!/usr/bin/env bash
# The API reference (docs/Doxyfile): Doxygen over include/phong, warnings as errors, so every public
# symbol has a doc comment and every comment parses. Writes build/api/html/index.html (~1 s).
set -euo pipefail
doxygen docs/Doxyfile
echo "API reference: build/api/html/index.html (every public symbol documented)"
