#!/usr/bin/env bash
# The README's test command (g++, Debug, -Werror), then the same suite in Release.
set -euo pipefail
cmake --workflow --preset test
cmake --workflow --preset test-release
