#!/usr/bin/env python3
"""Tests of hdt-triangulate, run as a user runs it.

    python3 test_cli.py PATH/TO/hdt-triangulate [--surface-demo PATH] [TEST...]

(TEST: names of the test functions to run, default all but test_pictures,
which meson runs as the test 'pictures' since libhdt's changes move it;
--surface-demo: the examples' surface_demo, which draws one of the pictures.)

Checks: --help/--version; random points in text and JSON (they parse, agree,
and satisfy Euler's relation with the edges identified geometrically through
the faces' translation words; every face's canonical copy has sides shorter
than sys/2); the dummy point set; CSV and whitespace input give
the same output, from a file, "-" and standard input; coordinates round-trip;
bad lines are reported as FILE:LINE with a nonzero status and nothing written
(no -o/--svg file, an existing one untouched, no temporary left, empty
standard output); usage errors exit 2; the SVG is well-formed XML; a UTF-8
byte order mark is skipped; a decimal comma gets a hint; --html writes a
self-contained viewer page holding the output's data; an empty input
warns; --random's cap is documented and named; an output that cannot be
written names the directory and the cause; the committed pictures are what
the commands of examples/pictures/commands.txt draw, byte for byte.
Standard library only.
"""
import cmath
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

TOOL = None
SURFACE_DEMO = None
REPOSITORY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
FAILURES = []


def run(*args, stdin=None, cwd=None, **popen):
    p = subprocess.run([TOOL, *map(str, args)], input=stdin, capture_output=True, text=True, cwd=cwd,
                       timeout=60, **popen)
    return p.returncode, p.stdout, p.stderr


def run_bytes(*args, stdin):
    """run() with standard input given as bytes (a byte order mark, exactly)."""
    p = subprocess.run([TOOL, *map(str, args)], input=stdin, capture_output=True, timeout=60)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def check(condition, what):
    if not condition:
        FAILURES.append(what)
        print("FAIL:", what)


# ---- The formats ----

def parse_text(text):
    """The text format as the dict the JSON format gives."""
    lines = [l for l in text.splitlines() if l and not l.startswith("#")]
    out = {"vertices": [], "faces": [], "translations": {}, "points": []}
    i = 0
    key, value = lines[i].split()
    assert key == "genus"
    out["genus"] = int(value)
    i += 1
    while i < len(lines):
        name, count = lines[i].split()
        count = int(count)
        rows = [l.split() for l in lines[i + 1:i + 1 + count]]
        assert len(rows) == count, f"section {name}: {len(rows)} rows, header says {count}"
        i += 1 + count
        if name == "vertices":
            for r in rows:
                assert len(r) == 4 and r[3] in ("0", "1"), r
                out["vertices"].append({"id": int(r[0]), "x": float(r[1]), "y": float(r[2]), "dummy": r[3] == "1"})
        elif name == "faces":
            for r in rows:
                assert len(r) == 6, r
                out["faces"].append({"vertices": [int(v) for v in r[:3]], "translations": [int(t) for t in r[3:]]})
        elif name == "translations":
            for r in rows:
                assert int(r[1]) == len(r) - 2, r
                out["translations"][r[0]] = [int(k) for k in r[2:]]
        elif name == "points":
            for j, r in enumerate(rows):
                assert int(r[0]) == j, r
                out["points"].append(int(r[1]))
        elif name == "voronoi_vertices":
            out.setdefault("voronoi", {})["vertices"] = [
                {"x": float(r[0]), "y": float(r[1]), "radius": float(r[2])} for r in rows]
        elif name == "voronoi_edges":
            out.setdefault("voronoi", {})["edges"] = [
                {"faces": [int(r[0]), int(r[1])], "from": [float(r[2]), float(r[3])],
                 "to": [float(r[4]), float(r[5])]} for r in rows]
        else:
            raise AssertionError(f"unknown section {name}")
    return out


# ---- Geometry, from the documented conventions ----

def generators(g):
    a = 1 / math.tan(math.pi / (4 * g))
    b = math.sqrt(a * a - 1)
    return [(complex(a), b * cmath.exp(1j * k * math.pi / (2 * g))) for k in range(4 * g)]


def multiply(m, n):
    """The product of SU(1,1) matrices [[a, b], [conj b, conj a]] given as (a, b)."""
    (a, b), (c, d) = m, n
    return a * c + b * d.conjugate(), a * d + b * c.conjugate()


def word_matrix(gens, word):
    """SU(1,1) matrix (a, b) of g_k1 ... g_km."""
    m = (complex(1), complex(0))
    for k in word:
        m = multiply(m, gens[k])
    return m


def apply(m, z):
    a, b = m
    return (a * z + b) / (b.conjugate() * z + a.conjugate())


def distance(p, q):
    """Hyperbolic distance in the Poincare disk."""
    return math.acosh(1 + 2 * abs(p - q) ** 2 / ((1 - abs(p) ** 2) * (1 - abs(q) ** 2)))


def inverse(m):
    a, b = m
    return a.conjugate(), -b


def check_triangulation(data, genus, what, dummies_removed=True, gens=None):
    """Euler's relation with edges identified geometrically, and the
    documented face conventions. gens: the matrices of the words' letters
    (M_g's generators by default)."""
    check(data["genus"] == genus, f"{what}: genus")
    V, F = len(data["vertices"]), len(data["faces"])
    ids = {v["id"]: complex(v["x"], v["y"]) for v in data["vertices"]}
    check(len(ids) == V, f"{what}: vertex ids are distinct")
    check(all(abs(z) < 1 for z in ids.values()), f"{what}: vertices in the disk")
    check(F == 2 * (V + 2 * genus - 2), f"{what}: F = 2 (V + 2g - 2)")
    gens = gens or generators(genus)
    words = data["translations"]
    check(words.get("0") == [], f"{what}: translation 0 is the identity")
    mats = {int(k): word_matrix(gens, w) for k, w in words.items()}
    half_systole = math.acosh(1 + 2 * math.cos(math.pi / (2 * genus)))
    edges = {}  # (u, v) -> list of [position of v seen from u at its representative, times seen]
    for f in data["faces"]:
        vs, ts = f["vertices"], f["translations"]
        check(len(set(vs)) == 3, f"{what}: a face with three distinct vertices")
        check(all(t in mats for t in ts), f"{what}: every translation id has a word")
        check(ts[vs.index(min(vs))] == 0, f"{what}: the smallest vertex id sits at its representative")
        # The canonical copy is a small triangle: its sides are shorter than
        # its circumdiameter, < sys/2 (this checks the words and the points).
        corners = [apply(mats[t], ids[v]) for v, t in zip(vs, ts)]
        for p, q in ((0, 1), (1, 2), (2, 0)):
            check(distance(corners[p], corners[q]) < half_systole + 1e-9,
                  f"{what}: face {vs} side {p}{q} shorter than sys/2")
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if vs[a] > vs[b]:
                a, b = b, a
            # Map the copy so that corner a sits at its representative.
            q = apply(multiply(inverse(mats[ts[a]]), mats[ts[b]]), ids[vs[b]])
            bucket = edges.setdefault((vs[a], vs[b]), [])
            for entry in bucket:
                if abs(entry[0] - q) < 1e-7:
                    entry[1] += 1
                    break
            else:
                bucket.append([q, 1])
    E = sum(len(b) for b in edges.values())
    check(all(n == 2 for b in edges.values() for _, n in b), f"{what}: every edge in exactly two faces")
    check(2 * E == 3 * F, f"{what}: E = 3F/2 ({E}, {F})")
    check(V - E + F == 2 - 2 * genus, f"{what}: V - E + F = 2 - 2g ({V} - {E} + {F})")
    dummies = sum(v["dummy"] for v in data["vertices"])
    if not dummies_removed:
        check(dummies > 0, f"{what}: dummies kept")
    return V, E, F


# ---- The tests ----

def test_help_and_version():
    code, out, err = run("--help")
    check(code == 0 and "usage: hdt-triangulate" in out and err == "", "--help exits 0 with the usage")
    code, out, _ = run("-V")
    check(code == 0 and out.startswith("hdt-triangulate ") and "libhdt" in out, "--version")


def test_random_text_and_json(tmp):
    code, text, err = run("--genus", 2, "--random", 80, "--seed", 5)
    check(code == 0 and err == "", f"random text run: {err}")
    t = parse_text(text)
    check(len(t["points"]) == 80, "text: one vertex per input point")
    check(sum(not v["dummy"] for v in t["vertices"]) == 80, "text: 80 user vertices")
    check_triangulation(t, 2, "genus 2 text")
    code, js, err = run("--genus", 2, "--random", 80, "--seed", 5, "--format", "json")
    check(code == 0, f"random json run: {err}")
    j = json.loads(js)
    j.pop("libhdt", None)
    check(t == j, "text and JSON hold the same triangulation")
    # Same seed, same points; another seed, other points.
    check(run("--genus", 2, "--random", 80, "--seed", 5)[1] == text, "--seed is reproducible")
    check(run("--genus", 2, "--random", 80, "--seed", 6)[1] != text, "another seed, other points")
    # Genus 3, dummies kept.
    code, js, err = run("-g3", "--random", 40, "--seed", 2, "-f", "json", "--keep-dummies", "--validate")
    check(code == 0, f"genus 3 keep-dummies: {err}")
    check_triangulation(json.loads(js), 3, "genus 3 with dummies", dummies_removed=False)
    # The file is the same as standard output.
    out = os.path.join(tmp, "g4.json")
    code, stdout, err = run("--genus=4", "--random=30", "--format=json", "-o", out, "--stats")
    check(code == 0 and stdout == "" and "V - E + F = -6" in err, f"-o and --stats: {err}")
    with open(out) as f:
        check_triangulation(json.load(f), 4, "genus 4 from -o")
    # Standard tools accept the JSON.
    p = subprocess.run([sys.executable, "-m", "json.tool", out], capture_output=True)
    check(p.returncode == 0, "python3 -m json.tool accepts the output")


def test_dummies(tmp):
    for genus in (2, 5):
        code, js, err = run("--genus", genus, "--random", 0, "--keep-dummies", "--format", "json")
        check(code == 0, f"dummy set of genus {genus}: {err}")
        d = json.loads(js)
        check(len(d["vertices"]) > 0 and all(v["dummy"] for v in d["vertices"]), f"genus {genus}: only dummies")
        check(d["points"] == [], f"genus {genus}: no input points")
        check_triangulation(d, genus, f"dummy set of genus {genus}", dummies_removed=False)
    # Empty input: the same as --random 0.
    code, text, _ = run("--keep-dummies", "-", stdin="# nothing\n\n")
    check(code == 0 and text == run("--random", 0, "--keep-dummies")[1], "empty input is the dummy set")


def sample_points(genus, n, seed):
    """User vertices of a random run: points of F_g, as the tool printed them."""
    d = json.loads(run("--genus", genus, "--random", n, "--seed", seed, "--format", "json")[1])
    return [(v["x"], v["y"]) for v in d["vertices"] if not v["dummy"]]


def test_input_forms(tmp):
    pts = sample_points(2, 50, 11)
    plain = "".join(f"{x!r} {y!r}\n" for x, y in pts)
    forms = ["{x},{y}", "{x}, {y}", "{x} {y}", "\t{x}\t{y}  ", "{x} ,  {y}", "{x},{y}\r"]
    mixed = "# a comment line\n\n"
    for i, (x, y) in enumerate(pts):
        mixed += forms[i % len(forms)].format(x=repr(x), y=repr(y)) + ("  # trailing comment" if i % 7 == 3 else "") + "\n"
        if i % 10 == 0:
            mixed += "   \n#\n"
    files = {}
    for name, content in (("plain.txt", plain), ("mixed.csv", mixed)):
        files[name] = os.path.join(tmp, name)
        with open(files[name], "w", newline="") as f:
            f.write(content)
    ref = run(files["plain.txt"], "-f", "json")
    check(ref[0] == 0, f"plain file: {ref[2]}")
    check(run(files["mixed.csv"], "-f", "json")[1] == ref[1], "CSV/mixed lines give the same output as plain")
    check(run("-f", "json", stdin=mixed)[1] == ref[1], "standard input (no file) gives the same output")
    check(run("-", "-f", "json", stdin=plain)[1] == ref[1], "'-' reads standard input")
    d = json.loads(ref[1])
    by_id = {v["id"]: (v["x"], v["y"]) for v in d["vertices"]}
    check(len(d["points"]) == len(pts) and all(by_id[v] == p for v, p in zip(d["points"], pts)),
          "points of F_g come back exactly, in input order through \"points\"")
    check_triangulation(d, 2, "points from a file")
    # A repeated point is not an error; it maps to the same vertex.
    code, js, err = run("-f", "json", "--stats", stdin=plain + plain.splitlines()[0] + "\n")
    d2 = json.loads(js) if code == 0 else {"points": [0, 1]}
    check(code == 0 and d2["points"][-1] == d2["points"][0] and "1 repeat" in err, "a repeated point")


def listing(directory):
    return sorted(os.listdir(directory))


def test_bad_input(tmp):
    good = sample_points(2, 6, 3)
    lines = [f"{x!r} {y!r}" for x, y in good]
    cases = [
        ("third column", 4, "0.1 0.2 0.3", "more than two"),
        ("not a number", 3, "0.1 abc", "not a number: 'abc'"),
        ("one number", 5, "0.25", "only one number"),
        ("outside the disk", 2, "0.8,0.8", "not inside the open unit disk"),
        ("on the circle", 6, "1 0", "not inside the open unit disk"),
        ("NaN", 7, "nan 0.1", "not finite"),
        ("trailing comma", 3, "0.1,0.2,", "more than two"),
    ]
    for what, line, bad, message in cases:
        content = lines[:line - 1] + [bad] + lines[line - 1:]
        path = os.path.join(tmp, "bad.txt")
        with open(path, "w") as f:
            f.write("\n".join(content) + "\n")
        outdir = os.path.join(tmp, "out-" + what.replace(" ", "-"))
        os.mkdir(outdir)
        out, svg = os.path.join(outdir, "faces.txt"), os.path.join(outdir, "picture.svg")
        code, stdout, err = run(path, "-o", out, "--svg", svg)
        check(code == 1, f"{what}: exit status 1 (got {code})")
        check(f"{path}:{line}: " in err and message in err, f"{what}: '{path}:{line}: ...{message}' in {err!r}")
        check(listing(outdir) == [], f"{what}: no -o, no --svg, no temporary file: {listing(outdir)}")
        # An existing destination is left as it was.
        with open(out, "w") as f:
            f.write("keep me\n")
        code, stdout, err = run(path, "-o", out, "--svg", svg)
        check(code == 1 and open(out).read() == "keep me\n", f"{what}: an existing -o file is untouched")
        check(listing(outdir) == ["faces.txt"], f"{what}: no --svg, no temporary: {listing(outdir)}")
        # Standard output gets nothing.
        code, stdout, err = run("-", stdin="\n".join(content) + "\n")
        check(code == 1 and stdout == "" and f"<stdin>:{line}: " in err, f"{what}: stdin, nothing on stdout")
    # Several bad lines are all reported, in line order.
    code, _, err = run("-", stdin="0.1 0.1\n2 0\nx y\n0.2 0.2\n0.3 0.1 9\n")
    reported = [l.split(":")[1] for l in err.splitlines() if l.startswith("<stdin>:")]
    check(code == 1 and reported == ["2", "3", "5"], f"all bad lines, in order: {err!r}")
    # A header line gets a hint.
    code, _, err = run("-", stdin="x,y\n0.1,0.1\n")
    check(code == 1 and "<stdin>:1: not a number: 'x'" in err and "header" in err, f"header hint: {err!r}")
    # A missing input file.
    code, stdout, err = run(os.path.join(tmp, "missing.txt"))
    check(code == 1 and stdout == "" and "missing.txt" in err, "missing input file: status 1")


def test_usage_errors(tmp):
    for args in (["--bogus"], ["--genus", "1"], ["--genus", "x"], ["-g"], ["--format", "xml"],
                 ["--random", "5", "file.txt"], ["--seed", "3"], ["--neighbours"], ["--side-labels"], ["--random", "-1"],
                 ["a.txt", "b.txt"], ["--random", "3", "-o", "same.svg", "--svg", "same.svg"],
                 ["--keep-dummies=yes"]):
        code, stdout, err = run(*args, cwd=tmp)
        check(code == 2 and stdout == "" and "hdt-triangulate:" in err and "--help" in err,
              f"usage error {args}: status 2 (got {code}, {err!r})")


def test_outputs(tmp):
    svg = os.path.join(tmp, "t.svg")
    out = os.path.join(tmp, "t.txt")
    with open(out, "w") as f:
        f.write("old\n")
    os.chmod(out, 0o640)
    code, stdout, err = run("--genus", 3, "--random", 60, "--svg", svg, "--neighbours", "-o", out)
    check(code == 0 and stdout == "", f"--svg --neighbours run: {err}")
    root = ET.parse(svg).getroot()
    check(root.tag == "{http://www.w3.org/2000/svg}svg", "the SVG parses as XML, root <svg>")
    check(len(root.findall(".//{http://www.w3.org/2000/svg}path")) >= 4, "the SVG has its paths")
    check(parse_text(open(out).read())["genus"] == 3, "an existing -o file is replaced")
    check(os.stat(out).st_mode & 0o777 == 0o640, "a replaced file keeps its permissions")
    check(sorted(os.listdir(tmp)).count("t.svg") == 1 and not any(n.startswith(".t.") for n in os.listdir(tmp)),
          "no temporary files left")
    # The dummy picture; a name that needs escaping in the caption.
    weird = os.path.join(tmp, "a<b&c.txt")
    with open(weird, "w") as f:
        f.write("0.1 0.2\n")
    code, _, err = run(weird, "--svg", svg, "-o", os.devnull)
    check(code == 0, f"-o /dev/null: {err}")
    ET.parse(svg)
    check(os.path.exists(os.devnull) and not os.path.isfile(os.devnull), "/dev/null is still a device")
    code, _, err = run("--random", 0, "--keep-dummies", "--svg", svg, "-o", os.devnull)
    check(code == 0 and "dummy point set" in open(svg).read(), f"dummy picture: {err}")


BOM = b"\xef\xbb\xbf"


def test_utf8_bom(tmp):
    """A UTF-8 byte order mark at the start of the input is skipped."""
    pts = sample_points(2, 20, 4)
    plain = "".join(f"{x!r},{y!r}\r\n" for x, y in pts).encode()
    path = os.path.join(tmp, "bom.csv")
    with open(path, "wb") as f:
        f.write(BOM + plain)
    ref = run_bytes("-f", "json", stdin=plain)
    check(ref[0] == 0, f"no BOM: {ref[2]}")
    code, out, err = run(path, "-f", "json")
    check(code == 0 and err == "" and out == ref[1], f"a file with a BOM reads as without: {code} {err!r}")
    code, out, err = run_bytes("-f", "json", stdin=BOM + plain)
    check(code == 0 and out == ref[1], f"standard input with a BOM: {err!r}")
    code, out, err = run_bytes("-f", "json", stdin=BOM + b"# x y\n" + plain)
    check(code == 0 and out == ref[1], f"a BOM before a comment line: {err!r}")
    # The line after the BOM is the first line: a header gets its hint.
    code, _, err = run_bytes(stdin=BOM + b"x,y\n" + plain)
    check(code == 1 and "<stdin>:1: not a number: 'x' (a header line?" in err, f"BOM then a header: {err!r}")
    # Only at the start: elsewhere it is not part of a number.
    code, _, err = run_bytes(stdin=plain.split(b"\n")[0] + b"\n" + BOM + plain)
    check(code == 1 and "<stdin>:2: not a number" in err, f"a BOM on line 2 is an error: {err!r}")


def test_decimal_comma(tmp):
    """A number with a decimal comma is an error that says so (nothing is guessed)."""
    good = [f"{x!r} {y!r}" for x, y in sample_points(2, 5, 8)]
    cases = [
        ("0,25", "0,25", "0.25"),                # reads as the point (0, 25) otherwise
        ("0,1 0,2", "0,1", "0.1"),
        ("0,1\t0,2", "0,1", "0.1"),
        ("0,1;0,2", "0,1", "0.1"),               # European CSV
        ('"0,1";"0,2"', "0,1", "0.1"),
        ('"-0,3","0,05"', "-0,3", "-0.3"),
    ]
    path = os.path.join(tmp, "comma.csv")
    for bad, field, dotted in cases:
        with open(path, "w") as f:
            f.write("\n".join(good[:2] + [bad] + good[2:]) + "\n")
        code, out, err = run(path)
        expected = f"{path}:3: not a number: '{field}' (a decimal comma? write {dotted})"
        check(code == 1 and out == "" and expected in err and err.count("\n") == 1,
              f"decimal comma {bad!r}: {expected!r} in {err!r}")
    # What a decimal comma is not: "x,y" as documented, and the origin "0,0".
    for line in ("0.1,0.2", "0,0", "0 , 0.5", "1e-1,2e-1"):
        code, _, err = run("-", stdin=line + "\n")
        check(code == 0 and "decimal comma" not in err, f"{line!r} is a point: {err!r}")
    code, _, err = run("-", stdin="0, 1\n")
    check(code == 1 and "decimal comma" not in err and "unit disk" in err, f"'0, 1' is (0, 1): {err!r}")


def test_empty_input_warning(tmp):
    """No points: the dummy set's triangulation, and a warning on standard error."""
    expected = run("--random", 0)[1]
    for what, content in (("empty", b""), ("comments only", b"# nothing\n\n"), ("a BOM only", BOM)):
        code, out, err = run_bytes(stdin=content)
        check(code == 0 and out == expected, f"{what}: status 0 and the dummy set ({code}, {err!r})")
        check(err.startswith("hdt-triangulate: warning: no points in <stdin>") and err.count("\n") == 1,
              f"{what}: one warning line: {err!r}")
    path = os.path.join(tmp, "empty.txt")
    open(path, "w").close()
    svg = os.path.join(tmp, "empty.svg")
    code, _, err = run(path, "--svg", svg, "-o", os.devnull)
    check(code == 0 and f"no points in {path}" in err and os.path.getsize(svg) > 0,
          f"empty file: warns, names it, still draws: {err!r}")
    # --random 0 asks for no points: no warning.
    code, _, err = run("--random", 0, "-o", os.devnull)
    check(code == 0 and err == "", f"--random 0 does not warn: {err!r}")


def test_random_cap(tmp):
    """--random's cap, 10^8, is in --help and in the error for more."""
    _, out, _ = run("--help")
    check("N <= 10^8" in out, "--help names --random's cap")
    for value in ("100000001", "18446744073709551616", "999999999999999999999999"):
        code, out, err = run("--random", value)
        check(code == 2 and out == "" and f"--random {value}: more than the cap of 10^8 (100000000) points" in err,
              f"--random {value}: names the cap: {err!r}")
    code, _, err = run("--random", "1e9")
    check(code == 2 and "from 0 to 10^8" in err, f"--random 1e9: {err!r}")


def test_output_errors(tmp):
    """An output that cannot be written: the message names the directory and
    the errno text. Root ignores permission bits, so the sure cases are paths
    that fail for anyone; a read-only directory is tried as an unprivileged
    user."""
    missing = os.path.join(tmp, "missing")
    for option in ("-o", "--svg"):
        target = os.path.join(missing, "out.txt")
        code, out, err = run("--random", 5, option, target, *(["-o", os.devnull] if option == "--svg" else []))
        check(code == 1 and out == "" and
              f"cannot write {target}: cannot create a temporary file in the directory '{missing}': "
              "No such file or directory" in err, f"{option} in a missing directory: {err!r}")
    plain = os.path.join(tmp, "plain")
    open(plain, "w").close()
    code, _, err = run("--random", 5, "-o", os.path.join(plain, "out.txt"))
    check(code == 1 and f"the directory '{plain}': Not a directory" in err, f"a file as directory: {err!r}")
    code, _, err = run("--random", 5, "-o", tmp)
    check(code == 1 and f"cannot write {tmp}: it is a directory" in err, f"a directory as output: {err!r}")
    # A directory without write permission, as a user that permission bits bind.
    readonly = os.path.join(tmp, "readonly")
    os.mkdir(readonly, 0o555)
    user = {}
    if os.geteuid() == 0:
        user = {"user": 65534, "group": 65534, "extra_groups": []}  # nobody
        os.chmod(tmp, 0o755)
        parent = os.path.dirname(tmp)
        os.chmod(parent, 0o755)
        if run("--version", **user)[0] != 0:
            print("test_output_errors: the read-only case skipped (nobody cannot run the tool)")
            return
    target = os.path.join(readonly, "out.txt")
    code, _, err = run("--random", 5, "-o", target, **user)
    check(code == 1 and f"cannot write {target}: cannot create a temporary file in the directory '{readonly}': "
          "Permission denied" in err, f"a read-only directory: {err!r}")
    check(os.listdir(readonly) == [], "nothing left in the read-only directory")


def picture_commands():
    """(file name, argv with the tool's path and the output in examples/pictures) per line of commands.txt."""
    with open(os.path.join(REPOSITORY, "examples", "pictures", "commands.txt")) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                words = shlex.split(line)
                outputs = [w for w in words if w.startswith("examples/pictures/")]
                assert len(outputs) == 1, f"commands.txt: one picture per command: {line!r}"
                yield os.path.basename(outputs[0]), words


def test_voronoi(tmp):
    """--voronoi: the same diagram in text and JSON, nothing more without it,
    and each Voronoi vertex at its radius from the corners of its face
    (recomputed here from the translation words), each Voronoi edge from the
    left face's centre to a point at the right face's radius from the
    Delaunay edge's ends; with --svg, the green path."""
    for genus, dummies in ((2, ()), (3, ("--keep-dummies",))):
        args = ("--genus", genus, "--random", 60, "--seed", 4) + dummies
        code, js, err = run(*args, "--voronoi", "-f", "json")
        check(code == 0, f"--voronoi json: {err}")
        j = json.loads(js)
        j.pop("libhdt", None)
        code, text, err = run(*args, "--voronoi")
        check(code == 0 and parse_text(text) == j, "--voronoi: text and JSON hold the same diagram")
        plain = json.loads(run(*args, "-f", "json")[1])
        check("voronoi" not in plain, "no voronoi member without --voronoi")
        plain.pop("libhdt", None)
        check({k: v for k, v in j.items() if k != "voronoi"} == plain, "--voronoi changes nothing else")
        gens = generators(genus)
        point = {v["id"]: complex(v["x"], v["y"]) for v in j["vertices"]}
        corners = []
        for face in j["faces"]:
            corners.append([apply(word_matrix(gens, j["translations"][str(t)]), point[v])
                            for v, t in zip(face["vertices"], face["translations"])])
        V, F = len(j["vertices"]), len(j["faces"])
        check(len(j["voronoi"]["vertices"]) == F and len(j["voronoi"]["edges"]) * 2 == 3 * F,
              "one Voronoi vertex per face, one edge per Delaunay edge")
        check(V - len(j["voronoi"]["edges"]) + F == 2 - 2 * genus, "Euler's formula for the dual")
        for f, c in enumerate(j["voronoi"]["vertices"]):
            centre = complex(c["x"], c["y"])
            for z in corners[f]:
                check(abs(distance(centre, z) - c["radius"]) < 1e-9, f"genus {genus} face {f}: a corner off the circle")
        for e in j["voronoi"]["edges"]:
            left, right = e["faces"]
            check(complex(*e["from"]) == complex(j["voronoi"]["vertices"][left]["x"],
                                               j["voronoi"]["vertices"][left]["y"]), "an edge starts at its left centre")
            shared = set(j["faces"][left]["vertices"]) & set(j["faces"][right]["vertices"])
            check(len(shared) == 2, "the two faces of an edge share two vertices")
            r = j["voronoi"]["vertices"][right]["radius"]
            for k, v in enumerate(j["faces"][left]["vertices"]):
                if v in shared:
                    check(abs(distance(complex(*e["to"]), corners[left][k]) - r) < 1e-9,
                          "an edge ends at the right face's centre beside the left face")
    svg = os.path.join(tmp, "v.svg")
    code, _, err = run("--random", 50, "--voronoi", "--svg", svg, "-o", os.devnull)
    check(code == 0, f"--voronoi --svg: {err}")
    with open(svg) as f:
        drawn = f.read()
    check(drawn.count('stroke="#2a8a3a"') == 1 and "Voronoi diagram green" in drawn, "--svg draws the diagram")


VIEWER_DATA = '<script id="hdt-data" type="application/json">'


def viewer_data(page):
    """The JSON data inlined in a viewer page (docs/viewer.md)."""
    start = page.index(VIEWER_DATA) + len(VIEWER_DATA)
    return json.loads(page[start:page.index("</script>", start)])


def test_html(tmp):
    """--html: one self-contained page (no reference to the network, no
    external script or style) holding the triangulation of the JSON output
    (vertices, faces, the translations' words), the Voronoi edges only with
    --voronoi, a title escaped for a script element; standard output with
    -o FILE; refused as the same stream or file as another output; nothing
    written when the input is bad. (The same bytes as Python's to_html: the
    python test test_viewer.)"""
    page_path, out = os.path.join(tmp, "v.html"), os.path.join(tmp, "v.json")
    code, _, err = run("--random", 60, "--seed", 4, "-f", "json", "-o", out, "--html", page_path)
    check(code == 0, f"--html: {err}")
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    check("http://" not in page and "https://" not in page, "--html: no http:// or https:// reference")
    check("<script src" not in page and "<link" not in page and "@import" not in page, "--html: nothing loaded")
    check(page.startswith("<!DOCTYPE html>") and page.rstrip().endswith("</html>"), "--html: a whole page")
    data = viewer_data(page)
    with open(out) as f:
        j = json.load(f)
    check(data["format"] == "hdt-viewer" and data["version"] == 1 and data["genus"] == 2, "--html: format, genus")
    check(data["vertices"]["ids"] == [v["id"] for v in j["vertices"]], "--html: the vertices of the output")
    check(data["vertices"]["xy"] == [c for v in j["vertices"] for c in (v["x"], v["y"])], "--html: their points")
    check(data["faces"]["vertices"] == [v for f in j["faces"] for v in f["vertices"]], "--html: the faces")
    check(data["faces"]["translations"] == [t for f in j["faces"] for t in f["translations"]], "--html: corners")
    check({str(i): w for i, w in zip(data["translations"]["ids"], data["translations"]["words"])}
          == j["translations"], "--html: the translation words of the output")
    check(len(data["polygon"]) == 16 and len(data["generators"]) == 32 and len(data["neighbours"]["words"]) == 49,
          "--html: F_2, its 8 generators, the 49 elements of N")
    check(data["voronoi"] is None, "--html: no Voronoi diagram without --voronoi")
    check("60 random points" in data["title"], f"--html: the title names the points: {data['title']!r}")

    code, _, err = run("--random", 60, "--seed", 4, "--voronoi", "-o", os.devnull, "--html", page_path)
    with open(page_path, encoding="utf-8") as f:
        data = viewer_data(f.read())
    check(code == 0 and len(data["voronoi"]["edges"]) == 4 * 3 * len(data["faces"]["vertices"]) // 3 // 2,
          "--html --voronoi: 4 numbers per Voronoi edge")

    # A file name that markup would break: escaped in the data.
    name = os.path.join(tmp, 'a<b>&"q.txt')
    with open(name, "w") as f:
        f.write("0.1 0.2\n0.3 -0.1\n")
    code, _, err = run(name, "-o", os.devnull, "--html", page_path)
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    check(code == 0 and "<b>" not in page and "\\u003cb\\u003e\\u0026\\\"q.txt" in page
          and viewer_data(page)["title"].endswith('of a<b>&"q.txt on M_2'), "--html: the title escaped in the data")

    code, text, err = run("--random", 10, "-o", out, "--html", "-")
    check(code == 0 and text.startswith("<!DOCTYPE html>"), f"--html -: the page on standard output: {err}")
    for args in (("--html", "-"), ("--html", "x.html", "--svg", "x.html"), ("--html", "x.html", "-o", "x.html"),
                 ("--html", "-", "-o", "y", "--save", "-")):
        code, _, err = run("--random", 5, *args, cwd=tmp)
        check(code == 2 and "--html" in err, f"{args}: a usage error naming --html: {err}")
    bad = os.path.join(tmp, "bad.txt")
    with open(bad, "w") as f:
        f.write("0.1 0.2\n2 0\n")
    fresh = os.path.join(tmp, "fresh.html")
    code, _, _ = run(bad, "-o", os.devnull, "--html", fresh)
    check(code == 1 and not os.path.exists(fresh), "--html: nothing written for a bad input")


def test_pictures(tmp):
    """Each committed picture is what its command draws now, byte for byte."""
    directory = os.path.join(REPOSITORY, "examples", "pictures")
    commands = list(picture_commands())
    names = [name for name, _ in commands]
    committed = sorted(n for n in os.listdir(directory) if n.endswith(".svg"))
    check(sorted(names) == committed, f"commands.txt has one command per picture: {sorted(names)} vs {committed}")
    version = run("--version")[1].split()[1]
    programs = {"hdt-triangulate": TOOL, "surface_demo": SURFACE_DEMO}
    for name, words in commands:
        program = programs.get(words[0], "unknown")
        check(program != "unknown", f"commands.txt: unknown program {words[0]}")
        if not program:
            print(f"test_pictures: {name} skipped (no --surface-demo)")
            continue
        out = os.path.join(tmp, name)
        argv = [program] + [out if w.startswith("examples/pictures/") else w for w in words[1:]]
        p = subprocess.run(argv, capture_output=True, timeout=120)
        check(p.returncode == 0, f"{name}: {words}: {p.stderr!r}")
        if p.returncode != 0:
            continue
        with open(out, "rb") as f:
            drawn = f.read()
        with open(os.path.join(directory, name), "rb") as f:
            check(drawn == f.read(), f"examples/pictures/{name} is not what its command draws now; "
                  "redraw: sh examples/pictures/regenerate [BUILD_DIR]")
        # Nothing that changes from run to run or release to release.
        check(version.encode() not in drawn, f"{name}: no version string")


def test_save_and_load(tmp):
    saved, first = os.path.join(tmp, "a.hdtri"), os.path.join(tmp, "a.json")
    code, _, err = run("--random", 120, "--seed", 3, "-f", "json", "-o", first, "--save", saved)
    check(code == 0, f"--save: {err}")
    with open(saved, "rb") as f:
        data = f.read()
    check(data[:8] == b"\x89HDT\r\n\x1a\n", "--save writes libhdt's format (its signature)")
    with open(first) as f:
        before = json.load(f)
    # Loaded alone: the same vertices, faces and translations; no input points.
    code, js, err = run("--load", saved, "-f", "json")
    check(code == 0 and err == "", f"--load: {err}")
    after = json.loads(js)
    for key in ("genus", "vertices", "faces", "translations"):
        check(after[key] == before[key], f"--load gives the saved triangulation's {key}")
    check(after["points"] == [], "--load without points inserts none")
    # Loaded, more points inserted, saved again: a valid triangulation with both sets.
    points = os.path.join(tmp, "more.txt")
    with open(points, "w") as f:
        f.write("0.05 0.01\n-0.2 0.3\n0.31,-0.12\n")
    again = os.path.join(tmp, "b.hdtri")
    code, js, err = run("--load", saved, points, "-f", "json", "--validate", "--save", again)
    check(code == 0, f"--load with points: {err}")
    more = json.loads(js)
    check(len(more["points"]) == 3 and len(more["vertices"]) == len(before["vertices"]) + 3,
          "--load then three points: three more vertices")
    check_triangulation(more, 2, "--load with points")
    code, js2, err = run("--load", again, "-f", "json")
    check(code == 0 and json.loads(js2)["faces"] == more["faces"], f"the second save loads back: {err}")
    # The genus comes from the file; a different --genus is an error.
    code, _, err = run("--load", saved, "--genus", 3)
    check(code == 1 and "genus 2" in err, f"--load with another --genus: {code} {err}")
    # Damaged, truncated, missing: status 1, the byte named, nothing written.
    bad = os.path.join(tmp, "bad.hdtri")
    out = os.path.join(tmp, "never.txt")
    for name, content in (("truncated", data[:-10]), ("damaged", data[:200] + bytes([data[200] ^ 1]) + data[201:]),
                          ("not saved", b"0.1 0.2\n" * 10)):
        with open(bad, "wb") as f:
            f.write(content)
        code, stdout, err = run("--load", bad, "-o", out)
        check(code == 1 and "byte " in err and stdout == "" and not os.path.exists(out),
              f"--load of a {name} file: {code} {err}")
    # A stream with no end stops at once: no signature, or more bytes than the header allows.
    code, _, err = run("--load", "/dev/zero", "-o", out)
    check(code == 1 and "byte 0" in err and not os.path.exists(out), f"--load /dev/zero: {code} {err}")
    p = subprocess.Popen([TOOL, "--load", "-", "-o", out], stdin=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        p.stdin.write(data)
        while p.poll() is None:
            p.stdin.write(bytes(1 << 20))  # the saved bytes, then zeros without end
    except BrokenPipeError:
        pass
    err = p.stderr.read().decode()
    check(p.wait(timeout=60) == 1 and "more bytes than its header allows" in err,
          f"--load of a stream longer than its header: {err}")
    # Refinement that memory cannot hold is refused at once, nothing written.
    code, _, err = run("--epsilon", "1e-9", "--random", 10, "-o", out)
    check(code == 1 and "needs at least" in err and not os.path.exists(out), f"--epsilon 1e-9: {code} {err}")
    code, _, err = run("--load", os.path.join(tmp, "missing.hdtri"))
    check(code == 1 and "cannot open" in err, f"--load of a missing file: {err}")
    # Standard input: --load - reads the saved bytes.
    p = subprocess.run([TOOL, "--load", "-", "-f", "json"], input=data, capture_output=True, timeout=60)
    check(p.returncode == 0 and json.loads(p.stdout)["faces"] == before["faces"], "--load - reads standard input")
    code, _, err = run("--random", 5, "--save", "-")
    check(code == 2, f"--save - with the triangulation on standard output is a usage error: {err}")


def circumradius(p):
    """The hyperbolic circumradius of three disk points, on the hyperboloid:
    the plane through the lifted points, its Lorentz-dual normal C, cosh R =
    <C, P> / |C|."""
    lifted = [((1 + abs(z) ** 2) / (1 - abs(z) ** 2), 2 * z.real / (1 - abs(z) ** 2), 2 * z.imag / (1 - abs(z) ** 2))
              for z in p]
    d1 = [lifted[1][k] - lifted[0][k] for k in range(3)]
    d2 = [lifted[2][k] - lifted[0][k] for k in range(3)]
    n = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0])
    c = (n[0], -n[1], -n[2])
    lorentz = lambda a, b: a[0] * b[0] - a[1] * b[1] - a[2] * b[2]
    return math.acosh(abs(lorentz(c, lifted[0])) / math.sqrt(lorentz(c, c)))


def test_refine(tmp):
    """--refine R,B and --epsilon E: every face's circumradius and shortest
    edge recomputed here from the vertices and translation words; --stats
    names the refinement and the quality; bad values are usage errors."""
    for args, radius, ratio in ((("--random", 0, "--refine", "0.3,1.2"), 0.3, 1.2),
                                (("--genus", 3, "--random", 40, "--refine", "0.4,1"), 0.4, 1.0),
                                (("--random", 0, "--epsilon", 0.25), 0.25, math.inf)):
        code, js, err = run(*args, "-f", "json", "--stats", "--validate")
        check(code == 0, f"{args}: {err}")
        check("refinement   :" in err and "quality      : min angle" in err, f"{args}: --stats: {err}")
        j = json.loads(js)
        gens = generators(j["genus"])
        point = {v["id"]: complex(v["x"], v["y"]) for v in j["vertices"]}
        shortest = math.inf
        for face in j["faces"]:
            p = [apply(word_matrix(gens, j["translations"][str(t)]), point[v])
                 for v, t in zip(face["vertices"], face["translations"])]
            r = circumradius(p)
            e = min(distance(p[i], p[(i + 1) % 3]) for i in range(3))
            shortest = min(shortest, e)
            check(r <= radius * (1 + 1e-9) and r <= ratio * e * (1 + 1e-9),
                  f"{args}: a face of circumradius {r}, shortest edge {e}")
        if ratio == math.inf:
            check(shortest >= radius * (1 - 1e-8), f"{args}: two vertices {shortest} apart")
    for bad in ("0", "-1", "nan", "0.2,0.5", "0.2,", ",1", "0.2,1,3", "x"):
        code, _, err = run("--random", 5, "--refine", bad)
        check(code == 2 and "--refine needs" in err, f"--refine {bad}: {code} {err}")
    for bad in ("0", "inf", "nan", "-0.1"):
        code, _, err = run("--random", 5, "--epsilon", bad)
        check(code == 2 and "--epsilon needs" in err, f"--epsilon {bad}: {code} {err}")
    code, _, err = run("--random", 5, "--refine", 0.3, "--epsilon", 0.3)
    check(code == 2, f"--refine and --epsilon together: {err}")


def test_mesh_formats(tmp):
    """The mesh files agree with the JSON output: one triangle per face, one
    node per distinct (vertex, translation) corner (bindings/python's
    test_mesh reads them back with meshio, VTK and Gmsh)."""
    code, js, err = run("--random", 40, "--seed", 2, "-f", "json")
    check(code == 0, f"json: {err}")
    data = json.loads(js)
    faces = data["faces"]
    corners = {(f["vertices"][c], f["translations"][c]) for f in faces for c in range(3)}
    code, off, err = run("--random", 40, "--seed", 2, "-f", "off")
    check(code == 0, f"--format off: {err}")
    lines = off.split("\n")
    check(lines[0] == "OFF" and lines[1] == f"{len(corners)} {len(faces)} 0", f"--format off header: {lines[:2]}")
    code, obj, err = run("--random", 40, "--seed", 2, "-f", "obj")
    check(code == 0 and sum(l.startswith("v ") for l in obj.split("\n")) == len(corners)
          and sum(l.startswith("f ") for l in obj.split("\n")) == len(faces), f"--format obj: {err}")
    for fmt in ("vtu", "msh"):
        code, text, err = run("--random", 40, "--seed", 2, "-f", fmt)
        check(code == 0 and "vertex" in text, f"--format {fmt}: {err}")
    code, vtu, _ = run("--random", 40, "--seed", 2, "-f", "vtu")
    try:
        ET.fromstring(vtu)
    except ET.ParseError as e:
        check(False, f"--format vtu is not well-formed XML: {e}")
    code, _, err = run("--random", 5, "-f", "vtu", "--voronoi")
    check(code == 2 and "--voronoi" in err, f"--voronoi with a mesh format: {code} {err}")
    code, _, err = run("--random", 5, "-f", "stl")
    check(code == 2 and "vtu" in err, f"an unknown format names the mesh formats: {err}")


def test_polygon(tmp):
    """--polygon: a CGAL polygon read, checked and described; the Bolza octagon
    in Q(a) has M_2's genus, |N| and systole; a bad polygon is refused with
    the reason, and nothing is written; with points, they are triangulated
    on the surface, the words in its pairings."""
    bolza = ("field a^4-2*a^2-1 a 1.5538+/-0.01\n8\n4 5 6 7 0 1 2 3\n"
             "1/2*a 1/2*a^3-a\n1/2*a^3-a 1/2*a\n-1/2*a^3+a 1/2*a\n-1/2*a 1/2*a^3-a\n"
             "-1/2*a -1/2*a^3+a\n-1/2*a^3+a -1/2*a\n1/2*a^3-a -1/2*a\n1/2*a -1/2*a^3+a\n")
    path = os.path.join(tmp, "bolza.txt")
    with open(path, "w") as f:
        f.write(bolza)
    svg = os.path.join(tmp, "bolza.svg")
    code, out, err = run("--polygon", path, "--svg", svg)
    fields = {line.split()[0]: line.split()[1:] for line in out.splitlines() if line and not line.startswith("#")}
    check(code == 0 and fields.get("genus") == ["2"] and fields.get("sides") == ["8"], f"--polygon: {code} {out!r} {err!r}")
    check(fields.get("neighbours") == ["49"] and fields.get("vertex_cycles", [""])[0] == "1:", f"--polygon: {out!r}")
    lo, hi = map(float, fields.get("systole", ["nan", "nan"]))
    check(lo <= 3.0571418389619963 <= hi, f"--polygon: systole [{lo}, {hi}], M_2's is 3.0571418389619963")
    with open(svg) as f:
        check(f.read().startswith("<svg "), "--polygon --svg: no SVG")
    bad = os.path.join(tmp, "square.txt")
    with open(bad, "w") as f:
        f.write("4\n2 3 0 1\n1/2 0 0 1/2 -1/2 0 0 -1/2\n")
    out_file = os.path.join(tmp, "never.txt")
    code, out, err = run("--polygon", bad, "-o", out_file)
    check(code == 1 and "angle sum must be 2 pi" in err and not os.path.exists(out_file),
          f"--polygon on a bad polygon: {code} {err!r}")
    # With points: triangulated on the surface. The Bolza octagon's side k
    # is F_2's side k + 1 (v_0 at angle pi/8), so its pairing g_k, which
    # moves side k + 4 onto side k, is M_2's generator k + 1.
    pairings = [generators(2)[(k + 1) % 8] for k in range(8)]
    code, out, err = run("--polygon", path, "--random", "200", "-f", "json", "--stats")
    check(code == 0 and "the genus-2 surface of" in err, f"--polygon --random: {code} {err!r}")
    data = json.loads(out)
    check(data.get("polygon_sides") == 8, f"--polygon --random: {data.get('polygon_sides')}")
    check_triangulation(data, 2, "--polygon --random", gens=pairings)
    code, out, err = run("--polygon", path, "--epsilon", "0.3", "-", stdin="0.1 0.2\n-0.5 0.3\n0.99 0\n")
    data = parse_text(out)
    check(code == 0 and len(data["points"]) == 3, f"--polygon with an input and --epsilon: {code} {err!r}")
    check_triangulation(data, 2, "--polygon --epsilon", gens=pairings)
    picture = os.path.join(tmp, "triangulated.svg")
    code, out, err = run("--polygon", path, "--random", "30", "--svg", picture, "--voronoi")
    with open(picture) as f:
        drawn = f.read()
    check(code == 0 and "on the genus-2 surface of bolza.txt" in drawn and "8-sided polygon" in drawn,
          f"--polygon with points and --svg: {code} {err!r}")
    code, out, err = run("--polygon", path, "--random", "3", "--html", os.path.join(tmp, "no.html"))
    check(code == 2 and "not supported yet" in err, f"--polygon with points and --html: {code} {err!r}")
    code, out, err = run("--polygon", path, "--random", "3", "-g", "3")
    check(code == 2 and "the polygon's" in err, f"--polygon with -g: {code} {err!r}")
    saved = os.path.join(tmp, "polygon.hdtri")
    code, out, err = run("--polygon", path, "--random", "50", "--save", saved)
    check(code == 0 and os.path.exists(saved), f"--polygon --save: {code} {err!r}")
    code, again, err = run("--load", saved)
    first, loaded = parse_text(out), parse_text(again)
    check(code == 0 and loaded["faces"] == first["faces"] and loaded["vertices"] == first["vertices"]
          and "given by a 8-sided polygon" in again, f"--load of a polygon surface's file: {code} {err!r}")


TESTS = (test_help_and_version, test_random_text_and_json, test_dummies, test_input_forms, test_bad_input,
         test_usage_errors, test_outputs, test_utf8_bom, test_decimal_comma, test_empty_input_warning,
         test_random_cap, test_output_errors, test_save_and_load, test_voronoi, test_refine, test_mesh_formats,
         test_html, test_polygon)


def main():
    global TOOL, SURFACE_DEMO
    args = sys.argv[1:]
    TOOL = os.path.abspath(args.pop(0))
    if args[:1] == ["--surface-demo"]:
        SURFACE_DEMO = os.path.abspath(args[1])
        args = args[2:]
    by_name = {t.__name__: t for t in TESTS + (test_pictures,)}
    unknown = [a for a in args if a not in by_name]
    if unknown:
        print(f"unknown tests: {unknown}; there are {list(by_name)}")
        return 2
    with tempfile.TemporaryDirectory(prefix="hdt-cli-") as tmp:
        for test in [by_name[a] for a in args] or TESTS:
            sub = os.path.join(tmp, test.__name__)
            os.mkdir(sub)
            try:
                test(sub) if test.__code__.co_argcount else test()
            except Exception as e:  # a crash of one test is a failure, the others still run
                FAILURES.append(f"{test.__name__}: {e!r}")
                print(f"FAIL: {test.__name__} raised {e!r}")
            print(f"{test.__name__}: done")
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print("all passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
