# The shader on the mpmath class references: pipes tests/reference/classes.jsonl through
# `airlight eval --backend gpu` (8 and 12 nodes per panel) and the f32 CPU default, and prints
# the per-class error table (|x − exact| / max(|exact|, 1e-4·scale), records with exact ≥ 1e-30).
# Run from the workspace root after `cargo build --release -p airlight-codegen`.
import json, subprocess, sys, collections
lines = [json.loads(l) for l in open('tests/reference/classes.jsonl') if l.strip()]
def run(args):
    inp = "\n".join(json.dumps(l) for l in lines) + "\n"
    out = subprocess.run(['./target/release/airlight', 'eval'] + args, input=inp, capture_output=True, text=True, check=True).stdout.splitlines()
    return [json.loads(o) for o in out]
cols = {}
for name, args in [('gpu8', ['--backend', 'gpu', '--terms', '8']), ('gpu12', ['--backend', 'gpu', '--terms', '12']), ('cpu32', ['--precision', 'f32'])]:
    res = run(args)
    t = collections.defaultdict(list)
    for l, r in zip(lines, res):
        exact, scale = l['in_scatter'], l['scale']
        if exact < 1e-30: continue
        v = r.get('in_scatter')
        v = float('inf') if v == 'inf' or v is None else v
        t[l['category']].append(abs(v - exact) / max(abs(exact), 1e-4 * scale))
    cols[name] = t
print("| class | n | shader 8 nodes max / median | shader 12 nodes max / median | CPU f32 default max |")
print("|---|---|---|---|---|")
allw = collections.defaultdict(float)
for c in sorted(cols['gpu8']):
    row = []
    for name in ['gpu8', 'gpu12']:
        e = sorted(cols[name][c]); row.append(f"{e[-1]:.1e} / {e[len(e)//2]:.1e}"); allw[name] = max(allw[name], e[-1])
    e = cols['cpu32'][c]; allw['cpu32'] = max(allw['cpu32'], max(e))
    print(f"| {c} | {len(cols['gpu8'][c])} | {row[0]} | {row[1]} | {max(e):.1e} |")
print("worst:", dict(allw))
