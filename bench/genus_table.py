#!/usr/bin/env python3
"""The large-genus table of docs/large_genus.md: per genus, the dummy count
against the area lower bound, the first and the cached hdt_create, the peak
memory and the insertion time per point, each run a fresh process of
bench/triangulation_bench (CPU times; peak resident size from the kernel).

    python3 bench/genus_table.py --build-dir build [--n 100000,1000000] [--genus 2,3,4,8,16,32,64,128,256]

--genus takes ranges too: `--genus 2-256 --n 10` sweeps every genus (about
an hour here) and ends with the worst dummy ratio from genus 4 on and the
slowest first creation up to genus 128 and beyond.

The creation times and the peak memory come from the run with the first n;
each further n is one more fresh process for its µs/pt column.

Genera above HDT_CREATE_GENUS_MAX (read from include/hdt.h) are listed as
refused without a run (hdt_create returns HDT_ENOTSUP at once; drawing the
bench's points alone takes minutes there). Prints a Markdown table.
"""
import argparse
import math
import os
import re
import subprocess


def area_bound(g):
    """Fewest vertices a triangulation of M_g with every circumradius < sys/4
    can have: each of its F = 2 (V + 2g - 2) faces has less area than the
    equilateral triangle of circumradius sys/4, whose angles alpha satisfy
    cot(alpha / 2) = sqrt(3) cosh(rho) (the right triangle centre, vertex,
    edge midpoint), and the faces cover the area 4 pi (g - 1)."""
    sys_ = 2 * math.acosh(1 + 2 * math.cos(math.pi / (2 * g)))
    rho = sys_ / 4
    alpha = 2 * math.atan(1 / (math.sqrt(3) * math.cosh(rho)))
    area = math.pi - 3 * alpha
    faces = math.floor(4 * math.pi * (g - 1) / area) + 1
    faces += faces % 2  # F is even
    return max(1, faces // 2 - 2 * g + 2)


def run(bench, g, n, timeout):
    try:
        out = subprocess.run([bench, '--n', str(n), '--genus', str(g)], capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return {'error': f'not done in {timeout} s'}
    m = re.search(r'^RESULT (.*)$', out.stdout, re.M)
    if not m:
        last = (out.stderr.strip() or out.stdout.strip()).splitlines()
        return {'error': last[-1] if last else f'exit {out.returncode}'}
    return dict(kv.split('=', 1) for kv in m.group(1).split())


def genera(spec):
    """'2,4,8-10' -> [2, 4, 8, 9, 10]."""
    out = []
    for item in spec.split(','):
        lo, _, hi = item.partition('-')
        out.extend(range(int(lo), int(hi or lo) + 1))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build-dir', default='build')
    ap.add_argument('--n', default='100000,1000000', help='point counts, comma-separated')
    ap.add_argument('--genus', default='2,3,4,8,16,32,64,128,256')
    ap.add_argument('--timeout', type=int, default=600)
    a = ap.parse_args()
    bench = os.path.join(a.build_dir, 'bench', 'triangulation_bench')
    header = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'include', 'hdt.h')
    create_max = int(re.search(r'#define HDT_CREATE_GENUS_MAX (\d+)', open(header).read()).group(1))
    ns = [int(x) for x in a.n.split(',')]
    columns = ' | '.join(f'µs/pt at {n:.0e}' for n in ns)
    print(f'| g | dummies | area bound | ratio | first create ms, CPU / wall | cached create ms, CPU | peak MiB | {columns} |')
    print('|---:|---:|---:|---:|---:|---:|---:|' + '---:|' * len(ns))
    dashes = ' | '.join('-' for _ in ns)
    worst_ratio, slowest = (0, 0), {128: (0, 0), 'beyond': (0, 0)}
    for g in genera(a.genus):
        b = area_bound(g)
        if g > create_max:
            print(f'| {g} | - | {b} | - | refused: above HDT_CREATE_GENUS_MAX = {create_max} | - | - | {dashes} |')
            continue
        r = run(bench, g, ns[0], a.timeout)
        if 'error' in r:
            why = 'refused: above HDT_CREATE_GENUS_MAX' if 'HDT_CREATE_GENUS_MAX' in r['error'] else r['error']
            print(f'| {g} | - | {b} | - | {why} | - | - | {dashes} |')
            continue
        per_point = [f'{float(r["cpu_us_per_pt"]):.2f}']
        for n in ns[1:]:
            more = run(bench, g, n, a.timeout)
            per_point.append(more['error'] if 'error' in more else f'{float(more["cpu_us_per_pt"]):.2f}')
        d = int(r['dummies'])
        create = float(r['create_cpu_ms'])
        if g >= 4: worst_ratio = max(worst_ratio, (d / b, g))
        key = 128 if g <= 128 else 'beyond'
        slowest[key] = max(slowest[key], (create, g))
        print(f'| {g} | {d} | {b} | {d / b:.2f} | {float(r["create_cpu_ms"]):.0f} / {float(r["create_ms"]):.0f} | '
              f'{float(r["cached_cpu_ms"]):.1f} | {int(r["peak_kib"]) / 1024:.0f} | {" | ".join(per_point)} |', flush=True)
    print()
    if worst_ratio[1]:
        print(f'Worst dummies / area bound from genus 4 on: {worst_ratio[0]:.3f} (genus {worst_ratio[1]}).')
    for key, where in ((128, 'up to genus 128'), ('beyond', 'above genus 128')):
        if slowest[key][1]:
            print(f'Slowest first hdt_create {where}, CPU: {slowest[key][0]:.0f} ms (genus {slowest[key][1]}).')


if __name__ == '__main__':
    main()
