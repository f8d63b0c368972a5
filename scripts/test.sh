#!/usr/bin/env bash
# Installs the dependencies, builds the dev preset (debug, warnings as errors, engine validation
# on) and runs every test, then the same tests optimised (release), where round-off and lazy
# exact arithmetic behave differently. Pass ctest options through, e.g. scripts/test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
for preset in dev release; do
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset" "$@"
done
