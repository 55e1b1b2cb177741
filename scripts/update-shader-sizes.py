#!/usr/bin/env python3
"""Rewrites the byte sizes (and SPIR-V instruction counts, via spirv-dis) in the file table of
shaders-out/README.md from the files as they are. Run after `airlight emit`; the test
`tests/tests/shaders.rs::readme_sizes_are_current` fails until the table is current."""
import os
import re
import subprocess

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "shaders-out")
ROW = re.compile(r"\| `([a-z]+/airlight_(?:lib_)?)\{8,12\}([^`]*)` \|(.*)\| ([\d ]+) / ([\d ]+) \|$")


def spaced(n):
    return f"{n:,}".replace(",", " ")


def instructions(path):
    dis = subprocess.run(["spirv-dis", path], check=True, capture_output=True, text=True).stdout
    return sum(1 for line in dis.splitlines() if " Op" in line)


def row(m):
    prefix, suffix, what = m.group(1), m.group(2), m.group(3)
    paths = [os.path.join(ROOT, f"{prefix}{t}{suffix}") for t in (8, 12)]
    sizes = [os.path.getsize(p) for p in paths]
    if suffix == ".spv":
        counts = [instructions(p) for p in paths]
        what = re.sub(r"\([\d ]+ / [\d ]+ instructions", f"({spaced(counts[0])} / {spaced(counts[1])} instructions", what)
    return f"| `{prefix}{{8,12}}{suffix}` |{what}| {spaced(sizes[0])} / {spaced(sizes[1])} |"


readme = os.path.join(ROOT, "README.md")
lines = open(readme).read().split("\n")
lines = [row(m) if (m := ROW.match(line)) else line for line in lines]
open(readme, "w").write("\n".join(lines))
