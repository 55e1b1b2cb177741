#!/usr/bin/env python3
"""Prints BENCHMARKS.md's per-class table from `cargo bench -p airlight-tests --bench classes`:
criterion's median time per iteration (target/criterion/classes_<precision>_<class>/<bench>/new/
estimates.json; one iteration evaluates every scene of the class once) divided by the class's
scene count, joined with the accuracy the bench measured first
(target/criterion/classes_accuracy.jsonl: largest error over the class against the mpmath
references, error = |x − exact| / max(|exact|, tau·scale))."""
import json
import os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")


def ns(group, bench, scenes):
    path = os.path.join(root, group, bench, "new", "estimates.json")
    if not os.path.exists(path):
        return None
    return json.load(open(path))["median"]["point_estimate"] / scenes


rows = [json.loads(l) for l in open(os.path.join(root, "classes_accuracy.jsonl"))]
for prec in ("f64", "f32"):
    print(f"\n### {prec} (tau = {'1e-10' if prec == 'f64' else '1e-4'})\n")
    print("| class | scenes | airlight: largest error | ns/ray | panels median / max | peer at equal error: nodes | its error | ns/ray | airlight / peer time | peer, 24 nodes: error | ns/ray | airlight at that error: tolerance | ns/ray | ratio |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["precision"] != prec:
            continue
        g = f"classes_{prec}_{r['class']}"
        n = r["scenes"]
        a, pe, p24, a24 = (ns(g, b, n) for b in ("airlight", "peer_equal", "peer_24", "airlight_at_peer_24"))
        fmt = lambda x: "–" if x is None else f"{x:.0f}"
        ratio = lambda x, y: "–" if x is None or y is None else f"{x / y:.2f}×"
        reached = "" if r["peer_equal_reached"] else " (not reached: its best)"
        print(
            f"| {r['class']} | {n} | {r['airlight']:.1e} | {fmt(a)} | {r['panels_median']} / {r['panels_max']} | "
            f"{r['peer_equal_nodes']}{reached} | {r['peer_equal']:.1e} | {fmt(pe)} | {ratio(a, pe)} | "
            f"{r['peer_24']:.1e} | {fmt(p24)} | {r['airlight_at_peer_24_tolerance']:.0e} → {r['airlight_at_peer_24']:.1e} | {fmt(a24)} | {ratio(a24, p24)} |"
        )

special = {}
for b in ("e1_scaled_f64", "exp_f64", "e1_scaled_f32", "exp_f32"):
    special[b] = ns("special", b, 256)
if all(special.values()):
    print("\n### complex E1 against one libm exp (256 points, |z| from 1e-3 to 1e3, Re z ≥ 0)\n")
    print("| precision | e^z E1(z), ns | exp, ns | ratio |")
    print("|---|---|---|---|")
    for p in ("f64", "f32"):
        e, x = special[f"e1_scaled_{p}"], special[f"exp_{p}"]
        print(f"| {p} | {e:.1f} | {x:.1f} | {e / x:.1f}× |")
