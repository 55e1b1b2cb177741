#!/usr/bin/env bash
# Builds and runs every cargo-fuzz target for SECONDS each (default 60), printing libFuzzer's
# execution counts; fails on any crash. Needs the nightly toolchain and cargo-fuzz.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
secs="${1:-60}"
for target in kernel f32_vs_f64; do
  echo "== fuzz $target (${secs}s)"
  cargo +nightly fuzz run "$target" --release -- -max_total_time="$secs" -print_final_stats=1 2>&1 \
    | grep -E "stat::number_of_executed_units|panicked|ERROR|SUMMARY" || true
  test "${PIPESTATUS[0]}" -eq 0
done
