#!/usr/bin/env python3
"""Writes the seeds of fuzz_load (tests/fuzz/corpus-load/): small
triangulations saved by hdt_save, through the Python package and a built
libhdt. Re-run after a change of the saved format (docs/format.md):

    HDT_LIBRARY=build/lib/libhdt.so.0 PYTHONPATH=bindings/python \\
        python3 tests/fuzz/make_load_seeds.py [OUTPUT_DIR]

Each seed stays under fuzz_load's -max_len (16384 bytes, .ci/fuzz).
"""
import os
import sys

import hdt

SEEDS = {
    # name: (genus, points, vertices to remove, remove the dummies)
    "dummies-g2": (2, [], [], False),
    "five-points-one-removed-g2": (2, [(0.1, 0.2), (-0.3, 0.25), (0.05, -0.4), (0.6, 0.1), (-0.85, -0.3)], [17], False),
    "points-outside-F-g2": (2, [(0.95, 0.01), (-0.2, -0.97), (0.5, 0.5), (0.0, 0.0)], [], False),
    "dummies-removed-g2": (2, [(0.2 * (k % 7) - 0.6, 0.2 * (k // 7) - 0.5) for k in range(36)], [], True),
    "dummies-g3": (3, [], [], False),
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus-load")
    os.makedirs(out, exist_ok=True)
    for name, (genus, points, removals, remove_dummies) in SEEDS.items():
        with hdt.Triangulation(genus) as t:
            if points:
                t.insert_many(points)
            for v in removals:
                t.remove(v)
            if remove_dummies:
                t.remove_dummies()
            data = t.to_bytes()
        if len(data) > 16384:
            raise SystemExit(f"{name}: {len(data)} bytes, above fuzz_load's -max_len")
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
        print(f"{name}: {len(data)} bytes")


if __name__ == "__main__":
    main()
