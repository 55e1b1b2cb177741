#!/usr/bin/env bash
# Code size of the C ABI in a firmware-style build: the staticlib built `#![no_std]`
# (--no-default-features) with panic = "abort", linked into C programs that call the f32 entry
# points only, or the f32 and f64 ones, with --gc-sections; `size`'s text bytes minus those of a
# program that calls none. Two profiles: the workspace's release (opt-level 3) and one for size
# (opt-level "s", fat LTO, one codegen unit).
#   bash capi/size.sh        (prints the README's table)
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/capi-size
mkdir -p "$out"
echo "| build | f32 only, bytes | f32 + f64, bytes |"
echo "|---|---|---|"
for profile in speed size; do
  if [ "$profile" = size ]; then
    export CARGO_PROFILE_RELEASE_OPT_LEVEL=s CARGO_PROFILE_RELEASE_LTO=fat CARGO_PROFILE_RELEASE_CODEGEN_UNITS=1
  fi
  RUSTFLAGS="-C panic=abort" cargo build -q --release -p airlight-capi --no-default-features --target-dir "$out/$profile"
  lib="$out/$profile/release/libairlight_c.a"
  text() {
    cc -O2 -I capi/include "capi/c/size_$1.c" "$lib" -Wl,--gc-sections -lm -o "$out/$profile/size_$1"
    size "$out/$profile/size_$1" | awk 'NR == 2 {print $1}'
  }
  none=$(text none)
  f32=$(text f32)
  both=$(text both)
  label=$([ "$profile" = speed ] && echo 'release (opt-level 3), panic = "abort"' || echo 'opt-level "s", fat LTO, 1 codegen unit, panic = "abort"')
  echo "| $label | $((f32 - none)) | $((both - none)) |"
done
