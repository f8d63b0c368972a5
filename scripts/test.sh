#!/usr/bin/env bash
# Installs the dependencies, builds the dev preset (warnings as errors, engine validation on)
# and runs every test. Pass ctest options through, e.g. scripts/test.sh -L verification
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset dev >/dev/null
cmake --build --preset dev
ctest --preset dev "$@"
