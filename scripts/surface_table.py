#!/usr/bin/env python3
"""Prints BENCHMARKS.md's surface-radiance table from `cargo bench -p airlight-tests --bench
surface`: criterion's median time per iteration (target/criterion/surface_<precision>_<class>/
<bench>/new/estimates.json; one iteration evaluates every record of the class once) divided by
the record count, joined with the accuracy the bench measured first
(target/criterion/surface_accuracy.jsonl: largest error against the references, relative to
max(|exact|, τ·scale); rays: ray integrals per surface point, median / max; *at 1e-3*: the
loosest tolerance whose largest error over the class is at most 1e-3)."""
import json
import os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")


def ns(group, bench, n):
    path = os.path.join(root, group, bench, "new", "estimates.json")
    return json.load(open(path))["median"]["point_estimate"] / n


print("| precision | class | records | default: largest error | rays | µs/point | tolerance 1e-3: largest error | rays | µs/point | at 1e-3: tolerance | largest error | rays | µs/point | one ray (default / 1e-3), ns | tolerance 1e-3 / one ray (default) | at 1e-3 / one ray (default) | at 1e-3 / one ray (1e-3) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for line in open(os.path.join(root, "surface_accuracy.jsonl")):
    r = json.loads(line)
    g = f"surface_{r['precision']}_{r['class']}"
    n = r["records"]
    d, l, a = ns(g, "surface_default", n), ns(g, "surface_1e-3", n), ns(g, "surface_at_1e-3", n)
    rd, rl = ns(g, "ray_default", n), ns(g, "ray_1e-3", n)
    print(f"| {r['precision']} | {r['class']} | {n} | {r['default']:.1e} | {r['default_rays'][0]} / {r['default_rays'][1]} | {d / 1e3:.1f} "
          f"| {r['loose']:.1e} | {r['loose_rays'][0]} / {r['loose_rays'][1]} | {l / 1e3:.1f} "
          f"| {r['level_tolerance']:.0e} | {r['level']:.1e} | {r['level_rays'][0]} / {r['level_rays'][1]} | {a / 1e3:.1f} "
          f"| {rd:.0f} / {rl:.0f} | {l / rd:.0f}× | {a / rd:.0f}× | {a / rl:.0f}× |")
