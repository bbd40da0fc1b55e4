#!/usr/bin/env bash
# The include rule of include/phong/ (docs/design.md, 'Layout: the layers'): no header includes a
# header of a higher layer. Reads the #include lines only (about a second).
set -euo pipefail
python3 tests/layers/check_layers.py
