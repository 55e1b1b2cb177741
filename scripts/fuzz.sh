#!/usr/bin/env bash
# Builds and runs every cargo-fuzz target for SECONDS each (default 60), printing libFuzzer's
# execution counts; fails on any finding. Needs the nightly toolchain and cargo-fuzz.
#   kernel, f32_vs_f64: with AddressSanitizer (cargo-fuzz's default);
#   shader: without a sanitizer (-s none): it drives the Vulkan driver, which is not
#           instrumented, through wgpu; it needs an adapter (lavapipe here).
# New inputs go to a scratch corpus; the committed seeds in fuzz/corpus/ are read only.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
secs="${1:-60}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for target in kernel f32_vs_f64 shader; do
  sanitizer=()
  [ "$target" = shader ] && sanitizer=(-s none)
  echo "== fuzz $target (${secs}s)"
  mkdir -p "$scratch/$target"
  log="$scratch/$target.log"
  set +e
  cargo +nightly fuzz run --release "${sanitizer[@]}" "$target" "$scratch/$target" "corpus/$target" -- \
    -max_total_time="$secs" -print_final_stats=1 >"$log" 2>&1
  status=$?
  set -e
  grep -E "stat::number_of_executed_units|ERROR|SUMMARY" "$log" || true
  grep -A1 "panicked" "$log" | cut -c1-3000 || true
  grep "scenes executed" "$log" | tail -1 || true
  if [ "$status" -ne 0 ]; then
    echo "fuzz target $target failed (exit $status); the last lines of its log:"
    tail -40 "$log"
    exit "$status"
  fi
done
