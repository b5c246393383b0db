#!/usr/bin/env python3
"""Alternating whole-process timings with phase marks taken from the stderr lines as they arrive.
usage: scripts/cold-start-ab.py N label1 'cmd1' label2 'cmd2' ..."""
import subprocess, sys, time, re, os, statistics, resource
n = int(sys.argv[1]); cfgs = list(zip(sys.argv[2::2], sys.argv[3::2]))
marks = [('tiles', r'loading tiles'), ('rendering', r'\] rendering'), ('stitching', r'\] stitching'),
         ('distances', r'\] distances'), ('wrote', r'\] wrote')]
res = {l: [] for l, _ in cfgs}
load0 = os.getloadavg()
for i in range(n):
    for label, cmd in cfgs:
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter()
        p = subprocess.Popen(['bash', '-c', cmd], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        seen = {}
        text = []
        for line in p.stderr:
            now = time.perf_counter() - t
            text.append(line)
            for k, pat in marks:
                if k not in seen and re.search(pat, line):
                    seen[k] = now
        p.wait()
        wall = time.perf_counter() - t
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
        err = ''.join(text)
        wm = re.search(r'writing (\d+) ms', err)
        st = re.search(r'stages \{(.*?)\} ms', err)
        stages = {k.strip(): float(v) for k, v in (kv.split('=') for kv in st.group(1).split(','))} if st else {}
        if p.returncode != 0:
            print('FAILED', label, err[-1500:], file=sys.stderr)
        r = dict(wall=wall, cpu=cpu, seen=seen, stages=stages, writing=float(wm.group(1)) if wm else None)
        res[label].append(r)
        print(label, i, f"wall {wall:.2f} cpu {cpu:.2f}", {k: round(v, 2) for k, v in seen.items()}, flush=True)
load1 = os.getloadavg()
print(f"\nload average (1 min, 5 min) before {load0[0]:.2f} {load0[1]:.2f}, after {load1[0]:.2f} {load1[1]:.2f}; n={n} alternating; medians")
med = lambda xs: statistics.median(xs) if xs else float('nan')
def phase(r, a, b):
    ta = 0 if a is None else r['seen'].get(a); tb = r['wall'] if b is None else r['seen'].get(b)
    return None if ta is None or tb is None else tb - ta
cols = [('start→tiles', None, 'tiles'), ('tiles+mesh(+context)', 'tiles', 'rendering'), ('draw+readback+triangles', 'rendering', 'stitching'),
        ('stitch', 'stitching', 'distances'), ('finish+writing', 'distances', 'wrote'), ('exit', 'wrote', None)]
print('| config | whole process s | CPU s | ' + ' | '.join(c[0] for c in cols) + ' | mesh stage | writing stage |')
print('|---|' + '---:|' * (len(cols) + 4))
for l, rs in res.items():
    row = [f"{med([r['wall'] for r in rs]):.2f}", f"{med([r['cpu'] for r in rs]):.2f}"]
    for name, a, b in cols:
        xs = [x for x in (phase(r, a, b) for r in rs) if x is not None]
        row.append(f"{med(xs):.2f}" if xs else '–')
    ms = [r['stages']['mesh'] for r in rs if 'mesh' in r['stages']]
    row.append(f"{med(ms)/1000:.2f}" if ms else '–')
    ws = [r['writing'] for r in rs if r['writing'] is not None]
    row.append(f"{med(ws)/1000:.2f}" if ws else '–')
    print(f"| {l} | " + ' | '.join(row) + ' |')
