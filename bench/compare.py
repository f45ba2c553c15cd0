#!/usr/bin/python3
"""libhdt side by side with CGAL: build, run, print one markdown table.

    /usr/bin/python3 bench/compare.py [--max 1000000] [--genera 2,3,4,8,16,32]
    /usr/bin/python3 bench/compare.py --max 100000      (a quick run, ~3 min)

Installs Debian's libcgal-dev when missing (apt-get, as root or with sudo),
configures the build directory build-bench (-Dbuildtype=release
-Dcgal_peers=enabled), builds the three benchmark programs, and runs, one at
a time and each in its own process (so its peak memory is its own):

  libhdt       bench/triangulation_bench: hdt_insert_many ("range") and
               hdt_insert one by one ("one"), then hdt_remove_dummies and
               hdt_validate; every genus of --genera;
  cgal-bolza   bench/cgal_bolza_bench: CGAL 5.5's
               Periodic_4_hyperbolic_Delaunay_triangulation_2 (default
               traits) on the same genus-2 points, range and one by one,
               then try_to_remove_dummy_vertices() and is_valid();
  cgal-euclid  bench/cgal_euclid_bench: CGAL's Delaunay_triangulation_2 with
               Exact_predicates_inexact_constructions_kernel on as many
               points uniform in the unit square, range and one by one.

for N = 10^3, 10^4, ... up to --max. All programs draw their points from the
same generator (bench/uniform_points.h) with the same seed. At N <= the
--compare-max the genus-2 programs also write their face sets (triangles as
input point indices), and the script checks that libhdt and CGAL's Bolza
triangulation are the same triangulation.

Per-point times are the process's CPU time over the insertion call(s) by
default (--clock wall for the wall clock; the table shows both): every
program is single-threaded, and CPU time is what other work sharing this
2-core machine disturbs least. Runs predicted to take under --repeat-below
seconds are repeated --repeat times and the fastest kept. A run whose
predicted wall time (extrapolated from the smaller N of the same program,
mode and genus) exceeds --budget seconds is skipped and noted.

The table goes to stdout and to build-bench/bench-table.md (--out).
Standard library only.
"""
import argparse
import datetime
import os
import platform
import re
import shlex
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROGRAMS = {"libhdt": "triangulation_bench", "cgal-bolza": "cgal_bolza_bench", "cgal-euclid": "cgal_euclid_bench"}


# The per-point time shown: "cpu_us_per_pt" (the process's CPU time: robust
# when other work shares the machine; all programs are single-threaded) or
# "us_per_pt" (wall clock). Set from --clock.
TIME_KEY = "cpu_us_per_pt"


def log(*args):
    print(*args, file=sys.stderr, flush=True)


# ---- setup -----------------------------------------------------------------

def as_root():
    return [] if os.geteuid() == 0 else ["sudo"]


def ensure_cgal():
    """Installs libcgal-dev with apt-get when it is not installed."""
    probe = subprocess.run(["dpkg-query", "-W", "-f=${Status}", "libcgal-dev"], capture_output=True, text=True)
    if "install ok installed" in probe.stdout:
        return
    log("installing libcgal-dev (apt-get)")
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(as_root() + ["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(as_root() + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "libcgal-dev"],
                   check=True, env=env)


def build(build_dir, cgal):
    options = ["-Dbuildtype=release", "-Dcgal_peers=" + ("enabled" if cgal else "disabled")]
    if os.path.exists(os.path.join(build_dir, "build.ninja")):
        subprocess.run(["meson", "configure", build_dir] + options, check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    else:
        subprocess.run(["meson", "setup", build_dir] + options, check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    targets = ["bench/" + p for p in PROGRAMS.values() if cgal or not p.startswith("cgal")]
    log("building " + " ".join(targets) + " in " + build_dir + " (CGAL's headers take a few minutes)")
    subprocess.run(["ninja", "-C", build_dir] + targets, check=True, cwd=ROOT, stdout=subprocess.DEVNULL)


# ---- runs ------------------------------------------------------------------

def parse_result(stdout):
    for line in stdout.splitlines():
        if line.startswith("RESULT "):
            fields = dict(kv.split("=", 1) for kv in line.split()[1:])
            out = {}
            for k, v in fields.items():
                try:
                    out[k] = float(v) if re.search(r"[.eE]", v) else int(v)
                except ValueError:
                    out[k] = v
            return out
    return None


class Runner:
    def __init__(self, args, build_dir):
        self.args = args
        self.build_dir = build_dir
        self.results = {}  # (prog, mode, g, n) -> result dict, or None
        self.missing = {}  # (prog, mode, g, n) -> why there is no result
        self.notes = []
        self.faces_dir = os.path.join(build_dir, "bench-faces")
        shutil.rmtree(self.faces_dir, ignore_errors=True)
        os.makedirs(self.faces_dir)

    def faces_path(self, prog, mode, n):
        return os.path.join(self.faces_dir, f"{prog}-{mode}-{n}.txt")

    def predicted_seconds(self, prog, mode, g, n):
        """Wall time of the run (prog, mode, g, n) extrapolated from the two
        largest smaller runs of the same series: the last run's wall time x
        (n / its n) x the growth of the per-point time over the last step."""
        done = sorted((m, r) for (p, md, gg, m), r in self.results.items()
                      if (p, md, gg) == (prog, mode, g) and m < n and r)
        if not done:
            return 0.0
        m, r = done[-1]
        growth = 1.0
        if len(done) >= 2:
            m0, r0 = done[-2]
            if r0["us_per_pt"] > 0:
                growth = max(1.0, r["us_per_pt"] / r0["us_per_pt"])
        return r["wall_s"] * (n / m) * growth

    def run_once(self, prog, mode, g, n, cmd):
        t0 = time.monotonic()
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=max(3 * self.args.budget, 60))
        except subprocess.TimeoutExpired:
            self.notes.append(f"{prog} {mode} g={g} N={n}: killed after {max(3 * self.args.budget, 60):.0f} s")
            log(self.notes[-1])
            return None
        wall = time.monotonic() - t0
        r = parse_result(proc.stdout)
        if r is None:
            self.notes.append(f"{prog} {mode} g={g} N={n}: failed (exit {proc.returncode}): "
                              + proc.stderr.strip().replace("\n", " / ")[:300])
            log(self.notes[-1])
            return None
        r["wall_s"] = wall
        r["exit"] = proc.returncode
        if proc.stderr.strip():
            note = f"{prog} {mode} g={g} N={n}: " + proc.stderr.strip().replace("\n", " / ")[:300]
            if note not in self.notes:
                self.notes.append(note)
        return r

    def run(self, prog, mode, g, n, faces=False):
        key = (prog, mode, g, n)
        predicted = self.predicted_seconds(prog, mode, g, n)
        if predicted > self.args.budget:
            self.notes.append(f"skipped {prog} {mode} g={g} N={n}: predicted ~{predicted:.0f} s "
                              f"> budget {self.args.budget:.0f} s")
            log(self.notes[-1])
            self.results[key] = None
            self.missing[key] = "skipped"
            return None
        cmd = [os.path.join(self.build_dir, "bench", PROGRAMS[prog]), "--n", str(n), "--mode", mode,
               "--seed", str(self.args.seed)]
        if prog != "cgal-euclid":
            cmd += ["--genus", str(g)]
        if n <= self.args.validate_max:
            cmd.append("--validate")
        if faces:
            cmd += ["--faces", self.faces_path(prog, mode, n)]
        log(f"run {prog:11s} {mode:5s} g={g:<2d} N={n:<8d}" + (f" (predicted ~{predicted:.0f} s)" if predicted else ""))
        # Cheap runs are repeated and the fastest insertion kept (less noise
        # from the rest of the machine); expensive ones run once.
        repeats = self.args.repeat if predicted <= self.args.repeat_below else 1
        best = None
        for _ in range(max(1, repeats)):
            r = self.run_once(prog, mode, g, n, cmd)
            if r is None:
                best = None
                break
            if best is None or r[TIME_KEY] < best[TIME_KEY]:
                best = r
        r = best
        if r is None:
            self.missing[key] = "failed"
        else:
            log(f"    {r['us_per_pt']:.3f} us/pt wall, {r['cpu_us_per_pt']:.3f} cpu, valid={r['valid']}, "
                f"{r['wall_s']:.1f} s" + (f" (fastest of {repeats})" if repeats > 1 else ""))
        self.results[key] = r
        return r


# ---- face sets ---------------------------------------------------------------

def read_faces(path):
    with open(path) as f:
        return [tuple(int(x) for x in line.split()) for line in f if line.strip()]


def compare_faces(path_a, path_b):
    """(oriented equal, unordered equal, |A - B|, |B - A|, |A|) or None."""
    if not (os.path.exists(path_a) and os.path.exists(path_b)):
        return None
    a, b = read_faces(path_a), read_faces(path_b)
    oriented = sorted(a) == sorted(b)
    sa = sorted(tuple(sorted(t)) for t in a)
    sb = sorted(tuple(sorted(t)) for t in b)
    only_a = len(set(sa) - set(sb))
    only_b = len(set(sb) - set(sa))
    return oriented, sa == sb, only_a, only_b, len(a)


# ---- table -----------------------------------------------------------------

def fmt(x, digits=2):
    if x is None:
        return "-"
    if isinstance(x, float):
        if x >= 100:
            return f"{x:.0f}"
        if x >= 10:
            return f"{x:.1f}"
        return f"{x:.{digits}f}"
    return str(x)


def ratio(a, b):
    if a is None or b is None or b[TIME_KEY] <= 0:
        return "-"
    return f"{a[TIME_KEY] / b[TIME_KEY]:.3g}"


def us(r):
    return fmt(r[TIME_KEY]) if r else "-"


def ms(r, key):
    """r[key] (a *_ms field) on the clock chosen, '-' when absent or not run."""
    if r is None:
        return "-"
    if TIME_KEY == "cpu_us_per_pt" and key.replace("_ms", "_cpu_ms") in r:
        key = key.replace("_ms", "_cpu_ms")
    v = r.get(key)
    return "-" if v is None or v < 0 else fmt(float(v))


def wall(r):
    return fmt(r["us_per_pt"]) if r else "-"


def mib(r):
    return f"{r['peak_kib'] / 1024:.1f}" if r else "-"


def bpv(r):
    return f"{r['bytes_per_vtx']:.0f}" if r else "-"


def valid(r):
    if r is None:
        return "-"
    v = r["valid"]
    mark = {1: "yes", 0: "**NO**", -1: "not run"}.get(v, str(v))
    if r.get("failed"):
        mark += f" ({r['failed']} not inserted)"
    return mark


def machine_description():
    model, cores = "unknown CPU", 0
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name") and model == "unknown CPU":
                    model = line.split(":", 1)[1].strip()
                if line.startswith("processor"):
                    cores += 1
    except OSError:
        pass
    mem = ""
    try:
        with open("/proc/meminfo") as f:
            kib = int(f.readline().split()[1])
            mem = f", {kib / 1024 / 1024:.0f} GiB RAM"
    except (OSError, ValueError, IndexError):
        pass
    return f"{model}, {cores} cores{mem}, Linux {platform.release()}"


def tool_version(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True).stdout.splitlines()[0].strip()
    except (OSError, IndexError):
        return "unknown"


def cgal_version():
    probe = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libcgal-dev"], capture_output=True, text=True)
    return probe.stdout.strip() or "unknown"


def source_description(label):
    """Which libhdt was measured: --label, else the git commit of the tree
    (with a mark when lib/ or include/ have uncommitted changes)."""
    if label:
        return label
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    if head.returncode != 0:
        return f"the source tree {ROOT}"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--", "lib", "include"],
                           capture_output=True, text=True).stdout.strip()
    return f"commit {head.stdout.strip()}" + (" with uncommitted changes in lib/ or include/" if dirty else "")


def loadavg():
    try:
        with open("/proc/loadavg") as f:
            return " ".join(f.read().split()[:3])
    except OSError:
        return "?"


def make_table(runner, args, sizes, started, elapsed, build_s, load_start):
    R = runner.results
    get = lambda prog, mode, g, n: R.get((prog, mode, g, n))
    lines = []
    w = lines.append

    def cell(prog, mode, g, n):
        if (prog, mode, g, n) in runner.missing:
            return runner.missing[(prog, mode, g, n)]
        return us(R.get((prog, mode, g, n)))
    w("## libhdt and CGAL side by side")
    w("")
    w(f"libhdt {source_description(args.label)}. "
      f"Measured {started:%Y-%m-%d %H:%M} UTC on {machine_description()}; "
      f"{tool_version(['c++', '--version'])}; CGAL {cgal_version()} (Debian libcgal-dev); "
      f"release build (-O3, NDEBUG). Runs one at a time, each in its own process; seed {args.seed}; "
      f"load average at start {load_start}, at end {loadavg()}; the runs took {elapsed / 60:.1f} min "
      f"(the build before them {build_s / 60:.1f} min). "
      f"Command: `{shlex.join(['bench/compare.py'] + sys.argv[1:])}`.")
    w("")
    clock = ("CPU-time (the process's CPU time, which other work on the machine disturbs less "
             "than the wall clock; every program is single-threaded)" if TIME_KEY == "cpu_us_per_pt"
             else "wall-clock")
    w(f"Times are {clock} microseconds per inserted point (the insertion call(s) only: not the dummy "
      "removal, not the check). Ratios are libhdt / CGAL (below 1: libhdt is faster). Peak MiB is the "
      "process's peak resident size (VmHWM) after insertion and dummy removal; bytes/vertex is that peak "
      "minus the resident size before the triangulation was created, per vertex. Valid: libhdt "
      "hdt_validate, CGAL is_valid().")
    w("")

    w("### Genus 2, range insertion (libhdt hdt_insert_many, CGAL insert(first, last))")
    w("")
    w("| N | libhdt µs/pt | CGAL Bolza µs/pt | CGAL Euclid µs/pt | libhdt/Bolza | libhdt/Euclid "
      "| wall µs/pt (libhdt / Bolza / Euclid) | dummy removal ms (libhdt / Bolza) "
      "| peak MiB (libhdt / Bolza / Euclid) | bytes/vertex (libhdt / Bolza / Euclid) "
      "| valid (libhdt / Bolza / Euclid) |")
    w("|---:|---:|---:|---:|---:|---:|---|---|---|---|---|")
    for n in sizes:
        h, b, e = get("libhdt", "range", 2, n), get("cgal-bolza", "range", 2, n), get("cgal-euclid", "range", 0, n)
        if not any(k in R for k in [("libhdt", "range", 2, n), ("cgal-bolza", "range", 2, n),
                                     ("cgal-euclid", "range", 0, n)]):
            continue
        w(f"| {n} | {cell('libhdt', 'range', 2, n)} | {cell('cgal-bolza', 'range', 2, n)} "
          f"| {cell('cgal-euclid', 'range', 0, n)} | {ratio(h, b)} | {ratio(h, e)} "
          f"| {wall(h)} / {wall(b)} / {wall(e)} "
          f"| {ms(h, 'remove_ms')} / {ms(b, 'remove_ms')} "
          f"| {mib(h)} / {mib(b)} / {mib(e)} | {bpv(h)} / {bpv(b)} / {bpv(e)} "
          f"| {valid(h)} / {valid(b)} / {valid(e)} |")
    w("")

    if any(k[1] == "one" for k in R):
        w("### Genus 2, one-by-one insertion (libhdt hdt_insert, CGAL insert(p), input order, no hint)")
        w("")
        w("| N | libhdt µs/pt | CGAL Bolza µs/pt | CGAL Euclid µs/pt | libhdt/Bolza | libhdt/Euclid "
          "| wall µs/pt (libhdt / Bolza / Euclid) | peak MiB (libhdt / Bolza / Euclid) "
          "| valid (libhdt / Bolza / Euclid) |")
        w("|---:|---:|---:|---:|---:|---:|---|---|---|")
        for n in sizes:
            h, b, e = get("libhdt", "one", 2, n), get("cgal-bolza", "one", 2, n), get("cgal-euclid", "one", 0, n)
            keys = [("libhdt", "one", 2, n), ("cgal-bolza", "one", 2, n), ("cgal-euclid", "one", 0, n)]
            if not any(k in R for k in keys):
                continue
            w(f"| {n} | " + " | ".join(cell(*k) for k in keys)
              + f" | {ratio(h, b)} | {ratio(h, e)} | {wall(h)} / {wall(b)} / {wall(e)} "
              f"| {mib(h)} / {mib(b)} / {mib(e)} | {valid(h)} / {valid(b)} / {valid(e)} |")
        w("")

    genera = args.genera
    w("### libhdt per genus (range insertion)")
    w("")
    w("| g | N | hdt_create ms (first / cached) | dummies | µs/pt | vs g = 2 | remove dummies ms | left "
      "| hdt_validate ms | peak MiB | bytes/vertex | valid |")
    w("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for g in genera:
        for n in sizes:
            r = get("libhdt", "range", g, n)
            if r is None:
                if ("libhdt", "range", g, n) in runner.missing:
                    w(f"| {g} | {n} | {runner.missing[('libhdt', 'range', g, n)]} | | | | | | | | | |")
                continue
            base = get("libhdt", "range", 2, n)
            w(f"| {g} | {n} | {ms(r, 'create_ms')} / {ms(r, 'cached_ms')} | {r['dummies']} "
              f"| {us(r)} | {ratio(r, base) if g != 2 else '1'} | {ms(r, 'remove_ms')} | {r['dummies_left']} "
              f"| {ms(r, 'validate_ms')} | {mib(r)} | {bpv(r)} | {valid(r)} |")
    w("")

    w("### Same triangulation? (genus 2, after dummy removal)")
    w("")
    w("Counts: vertices / edges / faces of libhdt and of CGAL's Bolza triangulation, range insertion. "
      "Face sets (N <= %d): each triangle as its 3 input point indices; 'oriented' compares them as "
      "counterclockwise cycles, 'as sets' as unordered triples." % args.compare_max)
    w("")
    w("| N | libhdt V / E / F | CGAL Bolza V / E / F | counts equal | libhdt vs CGAL Bolza faces "
      "| libhdt one vs range | CGAL one vs range |")
    w("|---:|---|---|---|---|---|---|")
    for n in sizes:
        h, b = get("libhdt", "range", 2, n), get("cgal-bolza", "range", 2, n)
        if not (h and b):
            continue
        vef = lambda r: f"{r['V']} / {r['E']} / {r['F']}"
        if h["dummies_left"] or b["dummies_left"]:
            eq = f"not compared: dummies left (libhdt {h['dummies_left']}, CGAL {b['dummies_left']})"
        else:
            eq = "yes" if (h["V"], h["E"], h["F"]) == (b["V"], b["E"], b["F"]) else "**NO**"

        def faces_cell(pa, ma, pb, mb):
            if n > args.compare_max:
                return "not written (N > --compare-max)"
            c = compare_faces(runner.faces_path(pa, ma, n), runner.faces_path(pb, mb, n))
            if c is None:
                return "-"
            oriented, unordered, only_a, only_b, count = c
            if oriented:
                return f"same ({count} faces, oriented)"
            if unordered:
                return f"same as sets ({count}), orientation differs"
            return f"**differ**: {only_a} / {only_b} faces only in one"

        w(f"| {n} | {vef(h)} | {vef(b)} | {eq} | {faces_cell('libhdt', 'range', 'cgal-bolza', 'range')} "
          f"| {faces_cell('libhdt', 'one', 'libhdt', 'range')} "
          f"| {faces_cell('cgal-bolza', 'one', 'cgal-bolza', 'range')} |")
    w("")

    w("### Targets (issue 6)")
    w("")
    big = max(sizes)
    h, b, e = get("libhdt", "range", 2, big), get("cgal-bolza", "range", 2, big), get("cgal-euclid", "range", 0, big)
    w(f"- genus 2, N = {big}, range insertion: libhdt {us(h)} µs/pt, libhdt/CGAL-Bolza = {ratio(h, b)}, "
      f"libhdt/CGAL-Euclidean = {ratio(h, e)}")
    one_n = [n for n in sizes if get("libhdt", "one", 2, n) and get("cgal-bolza", "one", 2, n)]
    if one_n:
        n = 100000 if 100000 in one_n else max(one_n)
        h1, b1 = get("libhdt", "one", 2, n), get("cgal-bolza", "one", 2, n)
        w(f"- genus 2, N = {n}, one by one: libhdt {us(h1)} µs/pt, CGAL Bolza {us(b1)} µs/pt, "
          f"libhdt/CGAL-Bolza = {ratio(h1, b1)}")
    per_genus = []
    for g in genera:
        r = get("libhdt", "range", g, big)
        if r and h:
            per_genus.append(f"g={g}: {us(r)} µs/pt ({ratio(r, h)}x)")
    if per_genus:
        w(f"- per-point time vs genus 2 at N = {big}: " + ", ".join(per_genus))
    if h:
        w(f"- libhdt peak memory at N = {big}, genus 2: {bpv(h)} bytes/vertex "
          f"(CGAL Bolza {bpv(b)}, CGAL Euclidean {bpv(e)})")
    if runner.notes:
        w("")
        w("Notes:")
        w("")
        for note in runner.notes:
            w(f"- {note}")
    w("")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--max", type=int, default=1000000, help="largest N (10^3, 10^4, ... up to it)")
    ap.add_argument("--min", type=int, default=1000, help="smallest N")
    ap.add_argument("--genera", default="2,3,4,8,16,32", help="genera of the libhdt runs (2 is always run)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--budget", type=float, default=600, help="skip a run predicted to take longer (seconds)")
    ap.add_argument("--validate-max", type=int, default=1000000, help="run the validity checks up to this N")
    ap.add_argument("--compare-max", type=int, default=100000, help="compare face sets up to this N")
    ap.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                    help="per-point times from the process's CPU time (default) or the wall clock")
    ap.add_argument("--repeat", type=int, default=3, help="repeat cheap runs, keep the fastest")
    ap.add_argument("--repeat-below", type=float, default=5, help="a run is cheap below this predicted time (s)")
    ap.add_argument("--no-one", action="store_true", help="skip the one-by-one runs")
    ap.add_argument("--no-cgal", action="store_true", help="libhdt only (no install, no CGAL build)")
    ap.add_argument("--no-build", action="store_true", help="use the programs already built")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build-bench"))
    ap.add_argument("--label", default=None, help="what libhdt is measured (default: its git commit)")
    ap.add_argument("--out", default=None, help="markdown output (default BUILD_DIR/bench-table.md)")
    args = ap.parse_args()
    global TIME_KEY
    TIME_KEY = "cpu_us_per_pt" if args.clock == "cpu" else "us_per_pt"
    args.genera = sorted({2} | {int(g) for g in args.genera.split(",") if g})
    build_dir = os.path.abspath(args.build_dir)
    out = args.out or os.path.join(build_dir, "bench-table.md")

    build_t0 = time.monotonic()
    if not args.no_build:
        if not args.no_cgal:
            ensure_cgal()
        if shutil.which("meson") is None:
            sys.exit("meson not found: run bash .ci/install-deps first")
        build(build_dir, not args.no_cgal)

    build_s = time.monotonic() - build_t0
    sizes = []
    n = args.min
    while n <= args.max:
        sizes.append(n)
        n *= 10
    started = datetime.datetime.now(datetime.timezone.utc)
    load_start = loadavg()
    t0 = time.monotonic()
    runner = Runner(args, build_dir)
    modes = ["range"] + ([] if args.no_one else ["one"])
    peers = [] if args.no_cgal else ["cgal-bolza", "cgal-euclid"]
    # Genus 2 first: every program and mode, N ascending, so that the
    # extrapolation of each series sees its smaller runs.
    for mode in modes:
        for prog in ["libhdt"] + peers:
            for n in sizes:
                g = 0 if prog == "cgal-euclid" else 2
                runner.run(prog, mode, g, n, faces=(prog != "cgal-euclid" and n <= args.compare_max))
    for g in args.genera:
        if g == 2:
            continue
        for n in sizes:
            runner.run("libhdt", "range", g, n)
    elapsed = time.monotonic() - t0

    table = make_table(runner, args, sizes, started, elapsed, build_s, load_start)
    print(table)
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, "w") as f:
        f.write(table + "\n")
    log(f"table written to {out}")
    bad = [k for k, r in runner.results.items() if r and (r["valid"] == 0 or r.get("failed"))]
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
