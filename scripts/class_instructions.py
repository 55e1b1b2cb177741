#!/usr/bin/env python3
"""Instructions per ray, counted by callgrind, of the default path (or the Gauss–Legendre-in-angle
peer) on one scene class of tests/reference/classes.jsonl: deterministic where the classes
bench's times move by ±30 % on shared machines, so a change to the kernel can be judged ray for
ray before it is timed. Each count is callgrind's total for `repetitions` passes over the class
minus that for none (the reference file's parsing), divided by passes × scenes.

Usage:
  python3 scripts/class_instructions.py f32 hg_0.9 1e-1 [more tolerances or pN / sN …]
  python3 scripts/class_instructions.py --level 1e-3 f32 hg_0.9 hg_0.8 …
With --level, each class at the loosest tolerance of 1e-1, 3e-2, … 1e-12 whose largest error is at
most the level (the classes bench's ladder and pick). Needs valgrind; builds the example first.
"""
import re
import subprocess
import sys
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.path.join(ROOT, "target", "release", "examples", "class_cost")
REPETITIONS = 10


def count(precision, cls, method):
    def total(reps):
        out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", BIN, precision, cls, method, str(reps)],
                             capture_output=True, text=True, check=True)
        ir = int(re.search(r"Collected : (\d+)", out.stderr).group(1))
        scenes, worst = re.search(r"scenes (\d+) worst (\S+)", out.stdout).groups()
        return ir, int(scenes), float(worst)
    full, scenes, worst = total(REPETITIONS)
    base, _, _ = total(0)
    return (full - base) / (REPETITIONS * scenes), worst


def main(args):
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "airlight-tests", "--example", "class_cost"], cwd=ROOT, check=True)
    if args[0] == "--level":
        level, precision, classes = float(args[1]), args[2], args[3:]
        for cls in classes:
            for tol in ["1e-1", "3e-2", "1e-2", "3e-3", "1e-3", "3e-4", "1e-4", "3e-5", "1e-5", "3e-6", "1e-6", "3e-7", "1e-7", "3e-8", "1e-8", "3e-9", "1e-9", "3e-10", "1e-10", "3e-11", "1e-11", "3e-12", "1e-12"]:
                ir, worst = count(precision, cls, tol)
                if worst <= level:
                    print(f"{cls} {precision} at {level:g}: tolerance {tol}, {ir:.0f} instructions per ray, largest error {worst:.2e}")
                    break
            else:
                print(f"{cls} {precision}: no tolerance down to 1e-12 reaches {level:g}")
    else:
        precision, cls, methods = args[0], args[1], args[2:]
        for method in methods:
            ir, worst = count(precision, cls, method)
            print(f"{cls} {precision} {method}: {ir:.0f} instructions per ray, largest error {worst:.2e}")


if __name__ == "__main__":
    main(sys.argv[1:])
