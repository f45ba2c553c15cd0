#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets from readable lists, in the
byte formats the targets decode: fuzz_api's (tests/fuzz/corpus/) and
fuzz_brute_force's (tests/fuzz/corpus-brute-force/). Re-run after a change
of either format:

    python3 tests/fuzz/make_seeds.py [OUTPUT_DIR]   (OUTPUT_DIR gets both, as
                                                    corpus/ and corpus-brute-force/)

A fuzz_api seed is a short program: byte 0 picks the first triangulation's
genus (bytes 0..4 give 2..6), then one byte per operation kind followed by
its arguments. A fuzz_brute_force seed is a header byte (genus, insertion
mode, flags) and point records. The seeds only need to reach the
interesting paths quickly; the fuzzer mutates them from there.
HDT_FUZZ_TRACE=1 build-fuzz/tests/fuzz/fuzz_api_replay SEED (or
fuzz_brute_force_replay) prints the C calls a seed makes.
"""
import os
import struct
import sys

# Operation kinds: indices into the ops[] table of fuzz_api.c.
CREATE, INSERT, INSERT_MANY, REMOVE, REMOVE_DUMMIES, LOCATE, FACES, TRANSLATION, VERTEX, WORDS, NULL, VERTICES = (
    0, 1, 5, 7, 10, 11, 13, 14, 15, 16, 17, 18)
DUAL, SAVE_LOAD, REFINE, SVG = 19, 21, 22, 23


def u8(b):
    return bytes([b & 0xFF])


def u16(v):
    return struct.pack("<H", v & 0xFFFF)


def u32(v):
    return struct.pack("<I", v & 0xFFFFFFFF)


def f64(x):
    return struct.pack("<d", x)


NO_PERTURB = 0x80


def ulps(dx, dy):
    """Perturbation byte: dx, dy in -4..3 ulps."""
    return u8(((dx + 4) & 7) | (((dy + 4) & 7) << 3))


# ---- Points (gen_point) ----
def raw(x, y):
    return u8(0) + f64(x) + f64(y)


def special(i, j):
    return u8(1) + u8(i) + u8(j)


def polygon_vertex(k, perturb=NO_PERTURB):
    return u8(2) + u8(k) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def side_midpoint(k, perturb=NO_PERTURB):
    return u8(3) + u8(k) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def on_side(k, t, perturb=NO_PERTURB):
    return u8(4) + u8(k) + u16(int(t * 65535)) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def near_circle(angle16, radius_index, perturb=NO_PERTURB):
    return u8(5) + u16(angle16) + u8(radius_index) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def previous(i, perturb=NO_PERTURB):
    """Needs a remembered point (else it is (0, 0) and reads nothing more)."""
    return u8(6) + u8(i) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def vertex_point(v, perturb=NO_PERTURB):
    return u8(8) + u16(v) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def coarse(x, y):
    return u8(9) + u16(int(x / 1.2 * 32768)) + u16(int(y / 1.2 * 32768))


def image(i, letters):
    """An image of remembered point i (needs one) under a short word."""
    return u8(10) + u8(i) + word(letters)


def dyadic(x, y):
    return u8(11) + u8(int(x * 128)) + u8(int(y * 128))


def tiny(mx, my, e):
    return u8(12) + u8(mx) + u8(my) + u16(e)


def raw_x_special_y(x, j):
    return u8(13) + u8(1) + f64(x) + u8(j)


def word(letters, wild=False):
    n = len(letters)
    b = n | (0xE0 if wild else 0)
    assert b % 25 == n
    return u8(b) + b"".join(u32(k) if wild else u8(k) for k in letters)


# ---- Operations ----
def create(slot, genus):
    return u8(CREATE) + u8(slot) + u8(genus - 2)


def create_bad(i):
    return u8(CREATE) + u8(0) + u8(0xF0 + i)


def insert(point, slot=0, null_out=False):
    return u8(INSERT) + u8(slot) + point + u8(0x10 if null_out else 0)


def insert_many(points, slot=0, null_out=False):
    assert len(points) <= 48
    return u8(INSERT_MANY) + u8(slot) + u8(len(points) | (0x40 if null_out else 0)) + b"".join(points)


def remove(v, slot=0):
    return u8(REMOVE) + u8(slot) + u8(2) + u16(v)  # v mod the id bound


def remove_raw(v, slot=0):
    return u8(REMOVE) + u8(slot) + u8(0) + u32(v)


def remove_dummies(slot=0):
    return u8(REMOVE_DUMMIES) + u8(slot) + u8(1)


def locate(point, slot=0, flags=1):
    return u8(LOCATE) + u8(slot) + point + u8(flags)


def nearest(point, slot=0):
    return u8(LOCATE) + u8(slot) + point + u8(0)


def faces(mode, slot=0, null_v=False, null_t=False, null_count=False, all_ones=False, extra=b""):
    """hdt_faces with capacity mode (op_faces: 0 none, 1 F-1, 2 F, 3 more,
    4 extra=u16 mod 2F+2, 5 huge) and the NULL arguments asked for."""
    for b in range(256):
        if (b % 6 == mode and bool(b & 0x40) == null_v and bool(b & 0x20) == null_t
                and ((b & 0x18) == 0x18) == null_count and bool(b & 0x80) == all_ones):
            return u8(FACES) + u8(slot) + u8(b) + extra + (u8(1) if null_count else b"")
    raise ValueError("no byte for that faces call")


def translation(id16, cap, slot=0):
    return u8(TRANSLATION) + u8(slot) + u8(2 | (1 << 2)) + u16(id16) + u8(cap)


def translation_raw(id32, slot=0):
    return u8(TRANSLATION) + u8(slot) + u8(0) + u32(id32)


def vertex(v, slot=0, flags=0):
    return u8(VERTEX) + u8(slot) + u8(2) + u16(v) + u8(flags)


def words(genus_byte, letters, what, point, k, nid=0, cap=None):
    out = u8(WORDS) + u8(genus_byte) + word(letters) + u8(what)
    if not what & 1:
        out += u8(cap if cap is not None else len(letters))
    out += point + u32(k)
    return out + (u32(nid) if genus_byte < 0xF0 else b"")


def null():
    return u8(NULL)


def vertices(mode, slot=0, null_ids=False, null_xy=False, null_dummy=False, null_count=False):
    """hdt_vertices with capacity mode (op_vertices: 0 none, 1 V-1, 2 V,
    3 more, 4 huge) and the NULL arguments asked for."""
    for b in range(256):
        if (b % 5 == mode and bool(b & 0x08) == null_ids and bool(b & 0x10) == null_xy
                and bool(b & 0x20) == null_dummy and bool(b & 0x40) == null_count):
            return u8(VERTICES) + u8(slot) + u8(b) + (u8(1) if null_count else b"")
    raise ValueError("no byte for that vertices call")


def dual(kind, cap_mode, drop=0, v=5, slot=0):
    """op_dual: kind 0 neighbours, 1 star, 2 edges, 3 face points, 4 Voronoi
    vertices, 5 Voronoi edges, 6 cell (of vertex v mod the id bound);
    capacity mode 0 asks, 1 one short, 2 exact, 3 more; drop: NULL outputs."""
    out = u8(DUAL) + u8(slot) + u8(kind) + u8(cap_mode | (drop << 2))
    return out + (u8(2) + u16(v) if kind in (1, 6) else b"")


def save_load(cap_mode, cut, at, xor, replace=False, slot=0):
    """op_save_load: save (capacity mode as dual's, 0 = exact), load, then a
    prefix of cut bytes and the bytes with byte `at` xor-ed (both mod the size)."""
    return u8(SAVE_LOAD) + u8(slot) + u8(cap_mode | (0x80 if replace else 0)) + u16(cut) + u16(at) + u8(xor)


def refine(what, radius_i, ratio_i, cap, progress=None, slot=0):
    """op_refine: what (the low two bits, mod 3) 0 hdt_refine, 1 hdt_epsilon_net, 2 hdt_quality; radius
    and ratio index op_refine's tables; progress: None (unchanged), 'set',
    'off', 'nan' (an invalid interval)."""
    b = what | {None: 0, "set": 0x10, "off": 0x90, "nan": 0x50}[progress]
    return u8(REFINE) + u8(slot) + u8(b) + u8(radius_i) + u8(ratio_i) + u8(cap)


def svg(size_i, flags, title=False, cap_mode=2, slot=0):
    """op_svg: size index into op_svg's table, flags (8 = unknown), capacity mode."""
    b = size_i | (0x80 if flags == 8 else (flags & 6) << 3) | (0x40 if title else 0)
    return u8(SVG) + u8(slot) + u8(b) + u8(cap_mode)


def genus(g):
    return u8(g - 2)


def grid(n, r=0.6):
    pts = []
    for i in range(n):
        for j in range(n):
            x = -r + 2 * r * (i + 0.5) / n
            y = -r + 2 * r * (j + 0.5) / n
            pts.append(dyadic(x, y))
    return pts


SEEDS = {
    "insert-basic": genus(2) + insert(dyadic(0.1, 0.2)) + insert(dyadic(-0.3, 0.25)) + insert(coarse(0.5, -0.1))
    + faces(2) + locate(dyadic(0.1, 0.2)) + nearest(dyadic(0.4, 0.4)),
    "insert-polygon": genus(2) + b"".join(insert(polygon_vertex(k, ulps(k % 3 - 1, 0))) for k in range(4))
    + b"".join(insert(side_midpoint(k, ulps(0, k % 3 - 1))) for k in range(4))
    + b"".join(insert(on_side(k, 0.3)) for k in range(8)),
    "insert-sides-g3": genus(3) + b"".join(insert(on_side(k, t)) for k in range(12) for t in (0.001, 0.5, 0.999)),
    "near-circle": genus(2) + b"".join(insert(near_circle(a * 4099, r)) for a in range(3) for r in range(9)),
    "domain-errors": genus(2) + insert(special(27, 0)) + insert(special(28, 1)) + insert(special(29, 2))
    + insert(special(2, 0)) + insert(special(6, 6)) + insert(special(19, 19)) + insert(special(18, 18))
    + insert(raw_x_special_y(1e308, 3)) + insert(tiny(3, 5, 1074)),
    "duplicates": genus(2) + insert(dyadic(0.25, 0.125)) + insert(previous(0)) + insert(previous(0, ulps(1, 0)))
    + insert(image(0, [0])) + insert(image(0, [3, 5])) + insert_many([previous(0), previous(0), dyadic(0.5, 0)]),
    "dummy-to-user": genus(2) + insert(vertex_point(0)) + insert(vertex_point(3)) + insert(vertex_point(5, ulps(1, 1)))
    + remove_dummies() + vertex(0) + vertex(3),
    "many-g2": genus(2) + insert_many(grid(5)) + remove_dummies() + b"".join(remove(7 * i) for i in range(6)),
    "many-g3": genus(3) + insert_many(grid(6)) + remove_dummies() + faces(3),
    "many-g4": genus(4) + insert_many(grid(4, 0.8)) + remove_dummies() + remove(2) + remove(40),
    "many-g5": genus(5) + insert_many(grid(4, 0.9)) + remove_dummies(),
    "many-g6": genus(6) + insert_many(grid(3, 0.9)) + insert_many(grid(3, 0.5), null_out=True) + remove_dummies(),
    "many-bad-point": genus(2) + insert_many([dyadic(0.1, 0.1), special(27, 0), dyadic(0.2, 0.1)])
    + insert_many([dyadic(0.1, 0.1), near_circle(0, 1)]),
    "remove": genus(2) + insert_many(grid(3)) + b"".join(remove(v) for v in range(0, 24, 2)) + remove_raw(0xFFFFFFFF)
    + remove_raw(5) + remove_raw(5),
    "faces-capacities": genus(2) + insert(dyadic(0.1, 0.2)) + faces(0) + faces(1) + faces(2) + faces(3, null_t=True)
    + faces(4, extra=u16(17)) + faces(5) + faces(5, all_ones=True) + faces(2, null_v=True)
    + faces(2, null_count=True) + faces(0, null_v=True, null_t=True),
    "translations": genus(3) + insert_many(grid(3)) + b"".join(translation(i, 9) for i in (0, 1, 13, 120, 121, 150))
    + translation_raw(-5) + translation_raw(0x7FFFFFFF),
    "vertices": genus(2) + insert(dyadic(0.1, 0.2)) + vertex(0) + vertex(14) + vertex(200) + vertex(1, flags=1)
    + vertex(1, flags=2),
    "words": genus(2) + words(0, [0, 5, 2, 7, 4, 1, 6, 3], 1, dyadic(0.1, 0.1), 3, 10)
    + words(1, [0, 6, 0, 6, 11], 0, polygon_vertex(1), 7, 120, cap=2)
    + words(4, list(range(24)), 4, near_circle(100, 0), -1, 5) + words(0xF2, [1, 2], 1, dyadic(0, 0), 0)
    + words(6, [3] * 20, 1, raw(0.5, 0.5), 1 << 31, 999),
    "null-and-bad-create": genus(2) + null() + b"".join(create_bad(i) for i in range(6)),
    "two-triangulations": genus(2) + create(1, 4) + insert(dyadic(0.1, 0.2), slot=1) + insert(dyadic(0.1, 0.2))
    + insert_many(grid(2), slot=1) + insert(polygon_vertex(0), slot=0) + remove_dummies(slot=1)
    + faces(2, slot=1),
    "recreate": genus(3) + insert(dyadic(0.1, 0.2)) + create(0, 5) + insert(dyadic(0.1, 0.2)) + remove_dummies(),
    "vertices-list": genus(2) + insert(dyadic(0.1, 0.2)) + insert(on_side(1, 0.5)) + vertices(0) + vertices(1)
    + vertices(2) + vertices(3, null_xy=True) + vertices(4) + vertices(2, null_ids=True, null_dummy=True)
    + vertices(2, null_count=True) + remove_dummies() + vertices(2),
    "locate-nasty": genus(2) + locate(polygon_vertex(0)) + locate(on_side(1, 0.5)) + locate(near_circle(7, 0))
    + locate(special(27, 0)) + nearest(polygon_vertex(2, ulps(-1, 1))) + nearest(near_circle(123, 2))
    + locate(tiny(1, 1, 1074), flags=7),
    "dual": genus(2) + insert_many(grid(3)) + b"".join(dual(k, m) for k in range(7) for m in (1, 2))
    + dual(0, 2, drop=1) + dual(2, 2, drop=7) + dual(1, 2, v=40000) + dual(4, 3, drop=2) + remove_dummies()
    + dual(6, 2, v=3),
    "dual-capacities": genus(3) + insert(dyadic(0.1, 0.2)) + b"".join(dual(k, m) for k in range(7) for m in (0, 3)),
    "save-load": genus(3) + insert_many(grid(3)) + save_load(0, 100, 7, 1) + save_load(1, 0, 0, 0x80)
    + save_load(2, 5, 60, 3, replace=True) + remove_dummies() + faces(2),
    "refine": genus(2) + refine(0, 0, 0, 8, progress="set") + refine(1, 1, 0, 4) + refine(2, 0, 0, 0)
    + refine(0, 7, 0, 3) + refine(0, 0, 4, 3) + refine(1, 4, 0, 3, progress="nan") + refine(0, 4, 3, 8)
    + insert_many(grid(2)) + refine(0, 2, 1, 8, progress="off"),
    "svg": genus(2) + insert(dyadic(0.1, 0.2)) + svg(0, 0) + svg(1, 4, title=True, cap_mode=1) + svg(2, 2, cap_mode=3)
    + svg(3, 0) + svg(5, 0) + svg(7, 0) + svg(0, 8),
    "subnormals": genus(2) + insert(tiny(1, 0, 0)) + insert(tiny(0, 1, 1074)) + insert(tiny(-1, 1, 1070))
    + insert(special(11, 12)) + insert(special(13, 0)) + insert(special(9, 10)),
}


# ---- fuzz_brute_force (read_header, read_record) ----
def bf_header(g, mode=0, drop_dummies=False, compare_early=False):
    """mode: 0 insert_many, 1 insert, 2 half and half, 3 insert in reverse."""
    return u8({2: 0, 3: 4, 4: 7}[g] | (mode << 3) | (0x20 if drop_dummies else 0) | (0x40 if compare_early else 0))


def bf_spread(radius, angle):
    """radius, angle in [0, 1): uniform for area in F_g's circumdisk."""
    return u8(0) + u16(int(radius * 65536)) + u16(int(angle * 65536))


def bf_dyadic(x, y):
    return u8(1) + u8(int(x * 128)) + u8(int(y * 128))


def bf_symmetric(x, y, mask=0xFF):
    """(x, y) under the quarter turns and reflections picked by mask."""
    return u8(2) + u8(int(x * 128)) + u8(int(y * 128)) + u8(mask)


def bf_cocircular(cx, cy, radius_byte, angles):
    assert 3 <= len(angles) <= 6
    return u8(3) + u8(int(cx * 256)) + u8(int(cy * 256)) + u8(radius_byte) + u8(len(angles) - 3) + bytes(angles)


def bf_on_side(k, t, perturb=NO_PERTURB):
    return u8(4) + u8(k) + u16(int(t * 65535)) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def bf_moved(direction, exponent):
    """perturb_or_move byte: 2^-(8 + exponent) (exponent 0..4) in direction 0..7 (eighths of a turn)."""
    assert 0 <= exponent <= 4
    return u8(0x40 | (exponent << 3) | (direction & 7))


def bf_polygon(k, vertex=True, perturb=NO_PERTURB):
    return u8(5) + u8((k << 1) | int(vertex)) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def bf_near_circle(angle16, radius_index, perturb=NO_PERTURB):
    return u8(6) + u16(angle16) + u8(radius_index) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def bf_duplicate(i):
    return u8(7) + u8(i)


def bf_dummy(d, perturb=NO_PERTURB):
    return u8(8) + u8(d) + (perturb if isinstance(perturb, bytes) else u8(perturb))


def bf_close(i, direction, exponent):
    """Point i moved 2^-(6 + exponent) (exponent 0..6) in direction 0..15 (sixteenths of a turn)."""
    assert 0 <= exponent <= 6
    return u8(9) + u8(i) + u8((direction << 4) | exponent)


def bf_remove(i):
    return u8(10) + u8(i)


def spread_points(n, salt):
    return [bf_spread(((i * 0.618034 + salt) % 1), ((i * 0.414214 + 2 * salt) % 1)) for i in range(n)]


BF_SEEDS = {
    "spread-g2": bf_header(2) + b"".join(spread_points(20, 0.1)),
    "spread-g3-no-dummies": bf_header(3, mode=2, drop_dummies=True) + b"".join(spread_points(22, 0.3)),
    "spread-g4-one-by-one": bf_header(4, mode=1, drop_dummies=True) + b"".join(spread_points(16, 0.7)),
    "symmetric-g2": bf_header(2, mode=1, drop_dummies=True) + bf_symmetric(0.25, 0.125) + bf_symmetric(0.5, 0.5, 0x0F)
    + bf_symmetric(0.375, 0, 0x33) + b"".join(spread_points(4, 0.2)),
    "symmetric-g3-dummies": bf_header(3) + bf_symmetric(0.3, 0.1) + bf_symmetric(0.2, 0.2, 0x0F),
    "cocircular-g2": bf_header(2, mode=3, drop_dummies=True) + bf_cocircular(0.1, -0.05, 40, [0, 40, 90, 160, 200, 250])
    + bf_cocircular(-0.2, 0.2, 120, [10, 70, 130, 190]) + b"".join(spread_points(8, 0.5)),
    "sides-g2": bf_header(2, mode=2, drop_dummies=True)
    + b"".join(bf_on_side(k, t) for k in range(4) for t in (0.25, 0.6))
    + b"".join(bf_on_side(k, t) for k in range(4, 8) for t in (0.2, 0.85))
    + bf_on_side(1, 0.4, ulps(1, -1)) + b"".join(spread_points(4, 0.9)),
    "polygon-g3": bf_header(3, mode=1) + bf_polygon(0) + bf_polygon(0, vertex=False) + bf_polygon(1, vertex=False)
    + bf_polygon(2, vertex=False, perturb=ulps(-1, 1)) + b"".join(spread_points(10, 0.4)),
    "near-polygon-g2": bf_header(2, mode=2, drop_dummies=True) + bf_polygon(0, perturb=bf_moved(1, 4))
    + bf_polygon(1, vertex=False, perturb=bf_moved(5, 3)) + bf_dummy(0, perturb=bf_moved(2, 3))
    + bf_dummy(5, perturb=bf_moved(6, 0)) + b"".join(spread_points(10, 0.45)),
    "near-circle-g2": bf_header(2, mode=1, drop_dummies=True) + bf_near_circle(1000, 4)
    + b"".join(spread_points(12, 0.6))
    + bf_near_circle(30000, 0),
    "duplicates-g2": bf_header(2, mode=0, drop_dummies=True) + b"".join(spread_points(12, 0.8)) + bf_duplicate(0)
    + bf_duplicate(3) + bf_close(1, 3, 0) + bf_close(2, 9, 5) + bf_close(4, 12, 6),
    "dummies-g2": bf_header(2, mode=1, drop_dummies=True) + bf_dummy(0) + bf_dummy(3) + bf_dummy(9)
    + b"".join(spread_points(12, 0.15)),
    "removals-g3": bf_header(3, mode=2, drop_dummies=True, compare_early=True) + b"".join(spread_points(20, 0.35))
    + bf_remove(0) + bf_remove(5) + bf_remove(11),
    "grid-g2": bf_header(2, mode=0, drop_dummies=True) + b"".join(bf_dyadic(x / 8, y / 8) for x in range(-3, 4, 2)
                                                                     for y in range(-3, 4, 2)),
}


def write(out, seeds):
    os.makedirs(out, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
    print(f"{len(seeds)} seeds in {out}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else here
    write(os.path.join(out, "corpus"), SEEDS)
    write(os.path.join(out, "corpus-brute-force"), BF_SEEDS)


if __name__ == "__main__":
    main()
