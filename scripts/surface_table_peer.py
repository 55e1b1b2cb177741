#!/usr/bin/env python3
"""Prints BENCHMARKS.md's baked-table table from `cargo bench -p airlight-tests --bench
surface_table`: per table (axis, n), its size, bake time, largest error over the bench's random
points and over the Lambertian omni isotropic records, its lookup time per point, and ours (f32
`SurfaceScene::air_light_counted`) at the loosest tolerance as accurate as the table, with its
time and the ratio; then, per level (1e-3, 1e-5), the smallest table that reaches it.
Criterion's median per iteration (target/criterion/surface_table/<bench>/new/estimates.json)
over the bench's points; accuracy from target/criterion/surface_table.jsonl."""
import json
import os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
POINTS = 2000


def ns(bench):
    path = os.path.join(root, "surface_table", bench, "new", "estimates.json")
    return json.load(open(path))["median"]["point_estimate"] / POINTS


ours, tables = {}, []
for line in open(os.path.join(root, "surface_table.jsonl")):
    r = json.loads(line)
    if "ours" in r:
        ours[r["ours"]] = r["error"]
    else:
        tables.append(r)


def size(b):
    return f"{b // 1024} KiB" if b < 1 << 20 else f"{b / (1 << 20):.0f} MiB"


print("ours (f32, `air_light_counted`) over the points: " + ", ".join(f"tolerance {t:.0e}: {e:.1e}" for t, e in sorted(ours.items(), reverse=True)))
print()
print("| T axis | n × n | size (f32) | bake | largest error, points | at (T, θ_s) | largest error, records | lookup, ns | ours: tolerance | its error | ns | ours / table |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in tables:
    look = ns(f"table_{r['axis']}_{r['n']}")
    tol = r["ours_tolerance"]
    if tol is None:
        ours_cols = "not reached | – | – | –"
    else:
        t = ns(f"ours_{tol:.0e}".replace("e-0", "e-"))
        ours_cols = f"{tol:.0e} | {r['ours_error']:.1e} | {t:.0f} | {t / look:.0f}×"
    w = r["worst_at"]
    print(f"| {r['axis']} | {r['n']}² | {size(r['bytes'])} | {r['bake_s']:.2f} s | {r['error']:.1e} | ({w[0]:.3f}, {w[1]:.2f}) | {r['error_records']:.1e} | {look:.1f} | {ours_cols} |")
print()
for level in (1e-3, 1e-5):
    for axis in ("linear", "sqrt"):
        hit = [r for r in tables if r["axis"] == axis and r["error"] <= level]
        if hit:
            r = hit[0]
            look = ns(f"table_{axis}_{r['n']}")
            print(f"* {level:.0e}, {axis} axis: {r['n']}² ({size(r['bytes'])}, bake {r['bake_s']:.1f} s, lookup {look:.1f} ns)")
        else:
            last = [r for r in tables if r["axis"] == axis][-1]
            print(f"* {level:.0e}, {axis} axis: not reached by {last['n']}² ({size(last['bytes'])}; largest error {last['error']:.1e})")
