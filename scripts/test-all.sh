#!/usr/bin/env bash
# Every test of the workspace, as the README and CI run it:
#   1. the shader freshness check (`airlight check`: shaders-out/ is what the source emits),
#   2. the fuzz targets for a bounded time each (FUZZ_SECONDS, default 60),
#   3. `cargo test --workspace --release`: unit, reference, property, no_std, allocation,
#      shader-validation and GPU-agreement tests.
# Tools it needs (spirv-val, glslangValidator, the lavapipe Vulkan driver, nightly cargo-fuzz)
# are installed by .ci/run; with CI=true a missing tool or adapter fails the run, never skips.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== airlight check"
cargo run --release -q -p airlight-codegen -- check

if [ -d fuzz ] && [ "${SKIP_FUZZ:-0}" != "1" ]; then
  echo "== fuzz (${FUZZ_SECONDS:-60}s per target)"
  bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
fi

echo "== cargo test"
cargo test --workspace --release
