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
fmt = lambda x: "–" if x is None else f"{x:.0f}"
ratio = lambda x, y: "–" if x is None or y is None else f"{x / y:.2f}×"


def rung(p):
    """The peer's rung: nodes per part, with its composition when it has several panels, and
    "plain" for one panel over the whole segment (not split at the foot); an unreached rung is
    the ladder's last, and the true peer at that error costs more."""
    total = p["nodes"] * p["panels"]
    name = f"{total}" if p["panels"] == 1 else f"{total} ({p['panels']}×{p['nodes']})"
    if not p.get("split", True):
        name += " plain"
    return name if p["reached"] else f"{name}, not reached"


for prec in ("f64", "f32"):
    levels = [r["levels"] for r in rows if r["precision"] == prec][0]
    print(f"\n### {prec} (tau = {'1e-10' if prec == 'f64' else '1e-4'})\n")
    head = "| class | scenes | default: largest error | ns/ray | panels median / max | peer at that error: nodes | ns/ray | ratio |"
    rule = "|---|---|---|---|---|---|---|---|"
    for lv in levels:
        head += f" at {lv['level']:.0e}: tolerance | ns/ray | peer nodes | ns/ray | ratio |"
        rule += "---|---|---|---|---|"
    print(head)
    print(rule)
    for r in rows:
        if r["precision"] != prec:
            continue
        g = f"classes_{prec}_{r['class']}"
        n = r["scenes"]
        a, pd = ns(g, "airlight", n), ns(g, "peer_default", n)
        line = (
            f"| {r['class']} | {n} | {r['airlight']:.1e} | {fmt(a)} | {r['panels_median']} / {r['panels_max']} | "
            f"{rung(r['peer_default'])} | {fmt(pd)} | {ratio(a, pd)} |"
        )
        for lv in r["levels"]:
            key = f"{lv['level']:.0e}".replace("e-0", "e-")
            al, pl = ns(g, f"airlight_{key}", n), ns(g, f"peer_{key}", n)
            tol = "default, not reached" if lv["tolerance"] is None else f"{lv['tolerance']:.0e}"
            line += f" {tol} | {fmt(al)} | {rung(lv['peer'])} | {fmt(pl)} | {ratio(al, pl)} |"
        print(line)

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

node_path = os.path.join(root, "node_count.jsonl")
if os.path.exists(node_path):
    print("\n### node count of the default path (every scene of every class, default tolerance)\n")
    print("| precision | nodes per panel | largest error | ns/ray | largest error at tolerance 1e-3 |")
    print("|---|---|---|---|---|")
    for line in open(node_path):
        r = json.loads(line)
        t = ns(f"node_count_{r['precision']}", str(r["node_count"]), r["scenes"])
        print(f"| {r['precision']} | {r['node_count']} | {r['error']:.1e} | {fmt(t)} | {r['error_at_1e-3']:.1e} |")
