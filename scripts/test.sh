#!/usr/bin/env bash
# Installs the dependencies, builds the release preset and runs every test, then builds the asan
# preset (the dev preset's checks: warnings as errors, engine validation after each cycle and the
# libraries' assertions, at -O2 under AddressSanitizer and UndefinedBehaviorSanitizer) and runs
# the unit and verification programs again, so that a sanitizer finding fails.
# The window's and the examples' tests run the desktop program and run in release only: Mesa and
# libdbus under the sanitizers are not ours, and building the window with VTK and running every
# example under the sanitizers took a third of CI's time; the engine they drive is checked by
# the unit and verification programs.
# Tests labelled `slow` (minutes of cycling in release, on code the other tests cover too) run in
# release only.
# Pass ctest options through, e.g. scripts/test.sh -L unit: they apply to both passes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release "$@"
cmake --preset asan >/dev/null
cmake --build --preset asan --target tessera_checks
ctest --preset asan -L "unit|verification" -LE slow "$@"
