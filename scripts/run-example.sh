#!/usr/bin/env bash
# Installs the dependencies, builds the release preset and runs an example model headless.
# Usage: scripts/run-example.sh [examples/NAME.tess]   (default: the brick wall)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target tessera
model="${1:-examples/brick_wall.tess}"
./build/release/app/tessera --batch "$model"
