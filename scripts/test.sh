#!/usr/bin/env bash
# Installs the dependencies, builds the dev preset (debug, warnings as errors, engine validation
# on) and runs every test, then the same tests optimised (release), where round-off and lazy
# exact arithmetic behave differently; then the engine's unit and verification programs under
# AddressSanitizer and UndefinedBehaviorSanitizer (asan), so that a sanitizer finding fails.
# Pass ctest options through, e.g. scripts/test.sh -L unit (the sanitizer pass then is skipped).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
for preset in dev release; do
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset" "$@"
done
if [ "$#" -eq 0 ]; then
  # Under the sanitizers a cycle costs 4-5 times more: the two zone-heavy verification programs
  # (Kirsch, Salencon, pressurised openings: 4-6 minutes each there), the examples and the
  # window run in dev and release only.
  sanitized=(test_geometry test_expr test_joint_law test_script_errors test_determinism
    test_concave test_generation test_generation3d test_script_fuzz test_zones
    test_contact_geometry test_core test_incline test_toppling test_dynamics test_arch test_polyhedron
    test_blocks3d)
  cmake --preset asan >/dev/null
  cmake --build --preset asan --target "${sanitized[@]}"
  regex="^($(IFS='|'; echo "${sanitized[*]}"))$"
  ctest --preset asan -R "$regex"
fi
