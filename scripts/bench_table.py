#!/usr/bin/env python3
"""Prints the ns-per-ray table of `cargo bench -p airlight --bench in_scatter` from criterion's
estimates (target/criterion/<group>/<function>/new/estimates.json), with ratios to the atan
form and to the paper's algorithm at the same term count."""
import json, os, sys
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
rows = []
for prec in ("f32", "f64"):
    for kind in ("iso", "aniso"):
        g = os.path.join(root, f"{prec}_{kind}")
        if not os.path.isdir(g):
            g = os.path.join(root, f"{prec}/{kind}")
        est = {}
        for f in ("ours_4", "ours_6", "taylor_6", "paper_4", "paper_6", "atan_form"):
            p = os.path.join(g, f, "new", "estimates.json")
            if os.path.exists(p):
                est[f] = json.load(open(p))["median"]["point_estimate"] / 256.0
        if est:
            rows.append((prec, kind, est))
print("| precision | scene | ours 4 | ours 6 | Taylor 6 | paper 4 | paper 6 | atan | ours 4 / atan | paper 4 / ours 4 | paper 6 / ours 6 |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for prec, kind, e in rows:
    f = lambda k: f"{e[k]:.1f}" if k in e else "-"
    r = lambda a, b: f"{e[a] / e[b]:.2f}" if a in e and b in e else "-"
    print(f"| {prec} | {kind} | {f('ours_4')} | {f('ours_6')} | {f('taylor_6')} | {f('paper_4')} | {f('paper_6')} | {f('atan_form')} | {r('ours_4', 'atan_form')} | {r('paper_4', 'ours_4')} | {r('paper_6', 'ours_6')} |")
