#!/usr/bin/env bash
# Every test of the workspace, as the README and CI run it:
#   1. the shader freshness check (`airlight check`: shaders-out/ is what the source emits),
#   2. the fuzz targets (kernel, f32_vs_f64, shader) for a bounded time each (FUZZ_SECONDS,
#      default 60; needs the nightly toolchain and cargo-fuzz — .ci/run installs cargo-fuzz;
#      SKIP_FUZZ=1 leaves them out on a developer machine, never under CI=true),
#   3. the complex E1 tuning and the sine/cosine minimax tables re-derived against mpmath, and
#      surface.jsonl's Lambertian records checked by a second formula (needs python3 with
#      mpmath; .ci/run installs it), and the kernel as a crates.io package: clippy's `incompatible_msrv` lint against its
#      `rust-version` (functions and methods newer than it; language features and traits are
#      not covered), and `cargo publish --dry-run` (packages and builds what crates.io would get),
#   4. `cargo test --workspace --release`: unit, reference, property, C ABI (no_std included),
#      shader-validation and GPU-agreement tests.
# The last line totals every test harness's results ("N passed, N failed").
# Tools the tests need (spirv-val, glslangValidator, the lavapipe Vulkan driver) are installed
# by .ci/run; with CI=true a missing tool or adapter fails the run, never skips.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== airlight check"
cargo run --release -q -p airlight-codegen -- check

if [ "${SKIP_FUZZ:-0}" = "1" ] && [ "${CI:-}" != "true" ]; then
  echo "== fuzz SKIPPED (SKIP_FUZZ=1)"
else
  echo "== fuzz (${FUZZ_SECONDS:-60}s per target)"
  bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
fi

echo "== E1 tuning (tests/reference/gen_e1_tuning.py: the tables in kernel/src/real.rs, re-derived)"
python3 tests/reference/gen_e1_tuning.py

echo "== minimax polynomials (scripts/gen_minimax.py: the tables of sin_cos_quarter, exp_nonpositive and atan_nonnegative in kernel/src/real.rs, re-derived)"
python3 scripts/gen_minimax.py --check

echo "== surface references (tests/reference/check_surface_spheroidal.py: the first Lambertian record of each class under a light without an axis, re-derived as a volume integral in prolate spheroidal coordinates)"
python3 tests/reference/check_surface_spheroidal.py

echo "== kernel package"
cargo clippy -q -p airlight -p airlight-capi --all-features --lib -- -A clippy::all -D clippy::incompatible_msrv
if [ "${CI:-}" = "true" ]; then
  cargo publish --dry-run -p airlight
else
  cargo publish --dry-run -p airlight --allow-dirty
fi

echo "== cargo test"
log=$(mktemp)
set +e
cargo test --workspace --release 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
set -e
passed=$(grep -o '[0-9]* passed' "$log" | awk '{s += $1} END {print s + 0}')
failed=$(grep -o '[0-9]* failed' "$log" | awk '{s += $1} END {print s + 0}')
rm -f "$log"
echo "${passed} passed, ${failed} failed"
exit "$status"
