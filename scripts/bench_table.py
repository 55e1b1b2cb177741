#!/usr/bin/env python3
"""Prints BENCHMARKS.md's tables from `cargo bench -p airlight --bench in_scatter`: criterion's
median time per iteration (target/criterion/<group>/<bench>/new/estimates.json, 256 rays per
iteration) joined with the accuracy the bench measured first (target/criterion/accuracy.json:
largest and median relative error over the same rays against the f64 equiangular 2^16-step
reference), then the issue's targets as ratios measured in the same run."""
import json
import os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
accuracy = json.load(open(os.path.join(root, "accuracy.json")))
RAYS = 256

groups = {}
for a in accuracy:
    groups.setdefault(a["group"], {})[a["bench"]] = a


def ns(group, bench):
    path = os.path.join(root, group.replace("/", "_"), bench, "new", "estimates.json")
    if not os.path.exists(path):
        path = os.path.join(root, group, bench, "new", "estimates.json")
    if not os.path.exists(path):
        return None
    return json.load(open(path))["median"]["point_estimate"] / RAYS


LABELS = {
    "ours_4": "this kernel, 4 terms (Chebyshev)",
    "ours_6": "this kernel, 6 terms (Chebyshev)",
    "ours_1e-3": "this kernel, fewest terms reaching 1e-3",
    "ours_1e-5": "this kernel, fewest terms reaching 1e-5",
    "taylor_6": "this kernel, 6 terms (Taylor, the paper's expansion)",
    "paper_4": "paper's algorithm, 4 terms (as published)",
    "paper_6": "paper's algorithm, 6 terms (as published)",
    "paper_eq4": "paper's algorithm at ours-4 accuracy",
    "paper_eq6": "paper's algorithm at ours-6 accuracy",
    "atan_form": "atan form (no extinction, isotropic only)",
    "march_uniform_1e-3": "ray marching, uniform steps, 1e-3",
    "march_uniform_1e-5": "ray marching, uniform steps, 1e-5",
    "march_equiangular_1e-3": "ray marching, equiangular steps, 1e-3",
    "march_equiangular_1e-5": "ray marching, equiangular steps, 1e-5",
}

targets = []
for group, rows in groups.items():
    ref = rows.get("reference")
    print(f"\n### {group}\n")
    if ref:
        print(f"Reference: {ref['config']}, largest difference {ref['max_err']:.1e}.\n")
    print("| method | config | ns / ray | largest rel. error | median rel. error | time / ours 4 |")
    print("|---|---|---|---|---|---|")
    base = ns(group, "ours_4")
    times = {}
    for bench, label in LABELS.items():
        if bench not in rows:
            continue
        r = rows[bench]
        t = ns(group, bench)
        times[bench] = t
        config = "" if r["config"] is None else (f"{r['config']} steps" if isinstance(r["config"], int) else str(r["config"]))
        med = "-" if r["median_err"] is None else f"{r['median_err']:.1e}"
        tt = "-" if t is None else f"{t:.1f}"
        ratio = "-" if t is None or base is None else f"{t / base:.2f}"
        print(f"| {label} | {config} | {tt} | {r['max_err']:.1e} | {med} | {ratio} |")

    def ratio(a, b):
        return times[a] / times[b] if times.get(a) and times.get(b) else None

    if group.endswith("/iso"):
        targets.append((group, "ours 4 / atan form", ratio("ours_4", "atan_form"), "≤ 8", lambda x: x <= 8))
    for tag in ("1e-3", "1e-5"):
        ours = f"ours_{tag}"
        if ours not in rows:
            targets.append((group, f"ray marching at {tag} / ours: ours does not reach {tag} with 12 terms", None, "≥ 20", None))
            continue
        for march in (f"march_uniform_{tag}", f"march_equiangular_{tag}"):
            if march in rows:
                targets.append((group, f"{march} / ours at {tag} ({rows[ours]['config']})", ratio(march, ours), "≥ 20", lambda x: x >= 20))
            else:
                targets.append((group, f"{march}: does not reach {tag} in this precision", None, "≥ 20", None))
    for n in ("4", "6"):
        if f"paper_eq{n}" in rows:
            targets.append((group, f"paper at equal accuracy ({rows['paper_eq' + n]['config']}) / ours {n}", ratio(f"paper_eq{n}", f"ours_{n}"), "≥ 3", lambda x: x >= 3))
        else:
            targets.append((group, f"paper at equal accuracy / ours {n}: no configuration of the paper's algorithm reaches ours' largest error", None, "≥ 3", None))

print("\n### Targets\n")
print("| group | ratio | measured | target | met |")
print("|---|---|---|---|---|")
for group, what, value, target, ok in targets:
    v = "-" if value is None else f"{value:.2f}"
    met = "-" if value is None or ok is None else ("yes" if ok(value) else "no")
    print(f"| {group} | {what} | {v} | {target} | {met} |")
