#!/usr/bin/env python3
"""Instructions per ray, counted by callgrind, of the default path (or the Gauss–Legendre-in-angle
peer) on one scene class of tests/reference/classes.jsonl: deterministic where the classes
bench's times move by ±30 % on shared machines, so a change to the kernel can be judged ray for
ray before it is timed. Each count is callgrind's total for `repetitions` passes over the class
minus that for none (the reference file's parsing), divided by passes × scenes. With --surface,
the same per surface point of a class of tests/reference/surface.jsonl
(`SurfaceScene::air_light_counted`, f64 unless f32 is named).

Usage:
  python3 scripts/class_instructions.py f32 hg_0.9 1e-1 [more tolerances or pN / sN …]
  python3 scripts/class_instructions.py --level 1e-3 f32 hg_0.9 hg_0.8 …
  python3 scripts/class_instructions.py --surface [f32] lambert_thin 1e-1 [more tolerances …]
With --level, each class at the loosest tolerance of 1e-1, 3e-2, … 1e-12 whose largest error is at
most the level (the classes bench's ladder and pick). Needs valgrind; builds the examples first.
"""
import re
import subprocess
import sys
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
EXAMPLES = os.path.join(ROOT, "target", "release", "examples")
REPETITIONS = 10
# the classes bench's tolerances: 1e-1, 3e-2, 1e-2, … 1e-12
LADDER = [f"{m}e-{k}" for k in range(1, 13) for m in (3, 1)][1:]


def count(example, *args):
    """Instructions per item of `example ARGS… passes` (it prints `scenes N worst E`)."""
    def total(reps):
        out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", os.path.join(EXAMPLES, example), *args, str(reps)],
                             capture_output=True, text=True, check=True)
        ir = int(re.search(r"Collected : (\d+)", out.stderr).group(1))
        scenes, worst = re.search(r"scenes (\d+) worst (\S+)", out.stdout).groups()
        return ir, int(scenes), float(worst)
    full, scenes, worst = total(REPETITIONS)
    base, _, _ = total(0)
    return (full - base) / (REPETITIONS * scenes), worst


def main(args):
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "airlight-tests", "--example", "class_cost", "--example", "surface_cost"], cwd=ROOT, check=True)
    if args[0] == "--level":
        level, precision, classes = float(args[1]), args[2], args[3:]
        for cls in classes:
            for tol in LADDER:
                ir, worst = count("class_cost", precision, cls, tol)
                if worst <= level:
                    print(f"{cls} {precision} at {level:g}: tolerance {tol}, {ir:.0f} instructions per ray, largest error {worst:.2e}")
                    break
            else:
                print(f"{cls} {precision}: no tolerance down to {LADDER[-1]} reaches {level:g}")
    elif args[0] == "--surface":
        precision, rest = (args[1], args[2:]) if args[1] in ("f32", "f64") else ("f64", args[1:])
        cls, tolerances = rest[0], rest[1:]
        for tol in tolerances:
            ir, worst = count("surface_cost", precision, cls, tol)
            print(f"{cls} {precision} {tol}: {ir:.0f} instructions per surface point, largest error {worst:.2e}")
    else:
        precision, cls, methods = args[0], args[1], args[2:]
        for method in methods:
            ir, worst = count("class_cost", precision, cls, method)
            print(f"{cls} {precision} {method}: {ir:.0f} instructions per ray, largest error {worst:.2e}")


if __name__ == "__main__":
    main(sys.argv[1:])
