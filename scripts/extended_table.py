#!/usr/bin/env python3
"""Prints BENCHMARKS.md's extended-light table from `cargo bench -p airlight-tests --bench
extended`: criterion's median time per iteration (target/criterion/extended_<precision>_<shape>_
<class>/<bench>/new/estimates.json; one iteration evaluates every record of the class once)
divided by the record count, joined with the accuracy the bench measured first
(target/criterion/extended_accuracy.jsonl: largest relative error against the references;
evaluated: Gauss–Kronrod panels per segment, point lights per disc, rectangle or sphere, median /
max); then the segments at 1e-3, the loosest tolerance whose largest error is at most 1e-3."""
import json
import os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")


def ns(group, bench, n):
    path = os.path.join(root, group, bench, "new", "estimates.json")
    return json.load(open(path))["median"]["point_estimate"] / n


print("| precision | shape | class | records | default: largest error | evaluated | ns/light | 1e-3: largest error | evaluated | ns/light | point light, ns | default / point | 1e-3 / point |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
levels = []
for line in open(os.path.join(root, "extended_accuracy.jsonl")):
    r = json.loads(line)
    g = f"extended_{r['precision']}_{r['class']}"
    shape, cls = r["class"].split("_", 1)
    n = r["records"]
    d, l, p = ns(g, "emitter_default", n), ns(g, "emitter_1e-3", n), ns(g, "point", n)
    print(f"| {r['precision']} | {shape} | {cls} | {n} | {r['default']:.1e} | {r['default_panels'][0]} / {r['default_panels'][1]} | {d:.0f} "
          f"| {r['loose']:.1e} | {r['loose_panels'][0]} / {r['loose_panels'][1]} | {l:.0f} | {p:.0f} | {d / p:.1f}× | {l / p:.1f}× |")
    if "level_tolerance" in r:
        a = ns(g, "emitter_at_1e-3", n)
        levels.append(f"| {r['precision']} | {cls} | {n} | {r['level_tolerance']:.0e} | {r['level']:.1e} | {r['level_panels'][0]} / {r['level_panels'][1]} "
                      f"| {a:.0f} | {p:.0f} | {a / p:.1f}× |")
print()
print("Segments at 1e-3 (the loosest tolerance whose largest error over the class is at most 1e-3):")
print()
print("| precision | class | records | tolerance | largest error | panels | ns/light | point light, ns | at 1e-3 / point |")
print("|---|---|---|---|---|---|---|---|---|")
for row in levels:
    print(row)
