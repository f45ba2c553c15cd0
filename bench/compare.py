#!/usr/bin/python3
"""libhdt's benchmarks, side by side with CGAL: build, run, write docs/benchmarks.md.

    /usr/bin/python3 bench/compare.py --max 100000 --write docs/benchmarks.md   (a few minutes)
    /usr/bin/python3 bench/compare.py                       (N up to 10^6: about ten minutes more)

Configures the build directory build-bench (-Dbuildtype=release, and
-Dcgal_peers=enabled when CGAL is there), builds the benchmark programs, and
runs, one at a time and each in its own process (so its peak memory is its
own):

  libhdt       bench/triangulation_bench.c: hdt_insert_many ("range") and
               hdt_insert one by one ("one"), then hdt_remove_dummies and
               hdt_validate; every genus of --genera;
  cgal-bolza   bench/cgal_bolza_bench.cpp: CGAL 5.5's
               Periodic_4_hyperbolic_Delaunay_triangulation_2 (default
               traits) on the same genus-2 points, range and one by one,
               then try_to_remove_dummy_vertices() and is_valid();
  cgal-euclid  bench/cgal_euclid_bench.cpp: CGAL's Delaunay_triangulation_2
               with Exact_predicates_inexact_constructions_kernel on as many
               points uniform in the unit square, range and one by one;

for N = 10^3, 10^4, ... up to --max. All programs draw their points from the
same generator (bench/uniform_points.h) with the same seed. At N <= the
--compare-max the genus-2 programs also write their face sets (triangles as
input point indices), and the script checks that they are the same
triangulation. Then, unless told not to: bench/curves_bench.c (points along
curves against random points, side by side in one process), the predicates
microbenchmark bench/predicates_bench.cpp, and callgrind's instruction count
of hdt_insert_many (--callgrind).

CGAL is used when Debian's libcgal-dev is installed; without it the CGAL
columns are left out and the document says so (--install-cgal installs it
with apt-get, as root or through sudo; --no-cgal leaves it out anyway).

Per-point times are the process's CPU time over the insertion call(s) by
default (--clock wall for the wall clock; the tables show both): every
program is single-threaded, and CPU time is what other work sharing the
machine disturbs least. Runs predicted to take under --repeat-below seconds
are repeated --repeat times and the fastest kept. A run whose predicted wall
time (extrapolated from the smaller N of the same program, mode and genus)
exceeds --budget seconds is skipped and noted.

The document (a header naming the date, machine, commit and compiler, the
method, then the tables) goes to stdout, to BUILD_DIR/bench-table.md (--out)
and, with --write FILE, to FILE: `--write docs/benchmarks.md` is how that
file is made; it is never edited by hand. Standard library only.
"""
import argparse
import datetime
import os
import platform
import re
import shlex
import shutil
import tempfile
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROGRAMS = {"libhdt": "triangulation_bench", "cgal-bolza": "cgal_bolza_bench", "cgal-euclid": "cgal_euclid_bench"}
EXTRA_PROGRAMS = ["curves_bench", "predicates_bench", "near_circle_bench"]
# The figures include/hdt.h and the docs point to (its "docs/benchmarks.md"):
# (the program, its arguments, where the figures are cited). Each runs once,
# its output kept as printed, under the command that made it.
CITED_RUNS = [
    ("batch_bench", ["--n", "100000", "--genus", "2", "--repeat", "3"],
     "hdt.h at hdt_insert_many (calls of a few points) and hdt_locate"),
    ("batch_bench", ["--n", "1000000", "--genus", "2", "--repeat", "1", "--calls", "1000"],
     "hdt.h at hdt_locate (queries at 10^6 vertices)"),
    ("dual_bench", ["--n", "1000000", "--genus", "2", "--calls", "4", "--load-rounds", "3"],
     "hdt.h at hdt_vertex_stars, hdt_voronoi_cells and hdt_load; docs/dual.md, docs/format.md"),
    ("refine_bench", ["--genus", "2"], "hdt.h at hdt_refine and hdt_epsilon_net; docs/refinement.md"),
    ("words_bench", ["--genus", "1024"],
     "hdt.h at HDT_GENUS_MAX and HDT_WORD_MAX_LENGTH (the linear pass, the first call of a genus)"),
    ("surface_bench", [], "docs/polygons.md (the systole's cost)"),
    ("polygon_mesh_bench", ["--n", "100000", "--rounds", "5"], "docs/polygons.md (insertion and epsilon-nets on polygon surfaces)"),
]
# Figures measured once, by a command this script does not rerun (too long
# here, or a driver that is not a program of bench/): (figure, where it was
# measured, where it is cited).
RECORDED_FIGURES = [
    ("first `hdt_create` of a genus: at most 0.6 to 0.7 s of CPU for every genus up to 128 (0.2 s at 64), "
     "1.5 to 1.6 s and 146 MiB (10^5 points included) at 256; a cached one 0.9 ms at 128, 4 ms at 256",
     "`/usr/bin/python3 bench/genus_table.py --build-dir build --genus 2-256 --n 10` (about an hour), "
     "2 December 2026; docs/large_genus.md", "hdt.h at HDT_CREATE_GENUS_MAX"),
    ("`hdt_point_representative` at genus 1024, points 10^-15 to 2 * 10^-15 from the unit circle: "
     "mean 2.4 ms, slowest 0.23 s, longest word 1908 letters (300 points)",
     "a driver calling `hdt_point_representative` at random angles, one process, the first call left out, "
     "3 December 2026; docs/large_genus.md", "hdt.h at HDT_GENUS_MAX and hdt_point_representative"),
    ("`hdt_word_reduce` of g_0^n, which takes the run-time precision: genus 2 g_0^1500 0.31 s, g_0^3000 1.6 s; "
     "genus 1024 g_0^1000 1.4 s, g_0^2048 6.4 s, g_0^4096 43 s",
     "3 December 2026; docs/large_genus.md", "hdt.h at hdt_word_reduce"),
    ("a long reduced word that still fits in double at genus 1024 (a chain of half relators): up to about "
     "10 µs a letter of it, 1.5 s in all", "1 December 2026 (commit f99c118, the figure hdt.h carried until now; no program of `bench/` makes such a word)",
     "hdt.h at HDT_WORD_MAX_LENGTH"),
    ("the layer split (issue 34) against the tree before it (3db7357), release builds, callgrind: instructions in `hdt_insert_many` a point at 10^5 points 6,401.2 before / 6,393.8 after at genus 2, 7,841.5 / 7,833.7 at genus 32; in the process's two `hdt_create` calls (the first builds the dummies) 3,860,638,441 / 3,853,310,817 at genus 128, 10,181,759,636 / 10,149,458,518 at genus 256 (CPU time of the first, median of three alternating runs: 606 / 585 ms at 128, 1,480 / 1,372 ms at 256)",
     '`valgrind --tool=callgrind --toggle-collect=hdt_insert_many triangulation_bench --n 100000 --genus G` and `--toggle-collect=hdt_create ... --n 10 --genus G` in a worktree of each commit, 7 December 2026',
     "issue 34's must-hold (not cited by hdt.h)"),
    ("the mesh as one template for M_g and polygon surfaces (8ecd568, issue 35) against the tree before it (d1810b3), release builds, callgrind: instructions in `hdt_insert_many` at 10^5 points 639,379,581 / 639,211,176 at genus 2, 783,367,830 / 782,954,132 at genus 32; in `hdt_create` at genus 8 (the dummy construction templated too, 72175cc) 1,069,339,886 / 1,069,340,223",
     '`valgrind --tool=callgrind --toggle-collect=hdt_insert_many triangulation_bench --n 100000 --genus G` (and `--toggle-collect=hdt_create ... --n 10 --genus 8`) in a worktree of each commit, 8 December 2026',
     "issue 35's must-hold (not cited by hdt.h)"),
]


# The per-point time shown: "cpu_us_per_pt" (the process's CPU time: robust
# when other work shares the machine; all programs are single-threaded) or
# "us_per_pt" (wall clock). Set from --clock.
TIME_KEY = "cpu_us_per_pt"


def log(*args):
    print(*args, file=sys.stderr, flush=True)


# ---- setup -----------------------------------------------------------------

def as_root():
    return [] if os.geteuid() == 0 else ["sudo"]


def cgal_installed():
    try:
        probe = subprocess.run(["dpkg-query", "-W", "-f=${Status}", "libcgal-dev"], capture_output=True, text=True)
    except OSError:
        return False
    return "install ok installed" in probe.stdout


def install_cgal():
    """Installs libcgal-dev with apt-get (--install-cgal)."""
    log("installing libcgal-dev (apt-get)")
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(as_root() + ["apt-get", "update", "-qq"], check=True, env=env)
    subprocess.run(as_root() + ["apt-get", "install", "-y", "-qq", "--no-install-recommends", "libcgal-dev"],
                   check=True, env=env)


def build(build_dir, cgal, jobs):
    """Configures and builds the benchmark programs; returns the names of the
    extra programs that failed to build (they are left out, not fatal)."""
    options = ["-Dbuildtype=release", "-Dbenchmarks=true", "-Dcgal_peers=" + ("enabled" if cgal else "disabled")]
    if os.path.exists(os.path.join(build_dir, "build.ninja")):
        subprocess.run(["meson", "configure", build_dir] + options, check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    else:
        subprocess.run(["meson", "setup", build_dir] + options, check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    targets = ["bench/" + p for p in PROGRAMS.values() if cgal or not p.startswith("cgal")]
    log("building " + " ".join(targets) + " in " + build_dir + (" (CGAL's headers take a few minutes)" if cgal else ""))
    subprocess.run(["ninja", "-C", build_dir, "-j", str(jobs)] + targets, check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL)
    failed = []
    for program in EXTRA_PROGRAMS + sorted({run[0] for run in CITED_RUNS}):
        built = subprocess.run(["ninja", "-C", build_dir, "-j", str(jobs), "bench/" + program], cwd=ROOT,
                               capture_output=True, text=True)
        if built.returncode != 0:
            log(f"bench/{program} does not build; left out")
            failed.append(program)
    return failed


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


# ---- the other benchmarks -----------------------------------------------------

def run_extra(cmd, name, seconds_limit):
    """An extra program's stdout, or (None, why) when it fails or runs out of time."""
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=seconds_limit)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, f"{name} did not finish: {e}"
    if proc.returncode != 0:
        return None, f"{name} failed (exit {proc.returncode}): {proc.stderr.strip()[:300]}"
    return proc.stdout, None


def run_curves(build_dir, repeat, seconds_limit):
    """curves_bench's Markdown table (its own header line dropped), or None."""
    cmd = [os.path.join(build_dir, "bench", "curves_bench"), "--repeat", str(repeat)]
    log("run " + shlex.join(cmd[1:]) + " (curves_bench)")
    stdout, why = run_extra(cmd, "curves_bench", seconds_limit)
    if why:
        return None, why
    rows = [line for line in stdout.splitlines() if line.startswith("|")]
    return rows, None


def run_near_circle(build_dir, genera, counts, seconds_limit):
    """near_circle_bench's NEAR lines as dicts (the "ratio" lines under points="ratio"), or None."""
    cmd = [os.path.join(build_dir, "bench", "near_circle_bench"), "--genus", ",".join(map(str, genera)),
           "--n", ",".join(map(str, counts))]
    log("run " + shlex.join(cmd[1:]) + " (near_circle_bench, minutes at genus 256)")
    stdout, why = run_extra(cmd, "near_circle_bench", seconds_limit)
    if why:
        return None, why
    rows = []
    for line in stdout.splitlines():
        if not line.startswith("NEAR "):
            continue
        fields = dict(kv.split("=", 1) for kv in line.split()[1:] if "=" in kv)
        if line.startswith("NEAR ratio"):
            fields["points"] = "ratio"
        rows.append(fields)
    return rows, None


def run_predicates(build_dir, calls, seconds_limit):
    """predicates_bench's lines, parsed: ([(g, name, filtered, exact, ratio)], {g: decided text})."""
    cmd = [os.path.join(build_dir, "bench", "predicates_bench"), str(calls)]
    log(f"run predicates_bench {calls}")
    stdout, why = run_extra(cmd, "predicates_bench", seconds_limit)
    if why:
        return None, why
    rows, decided = [], {}
    for line in stdout.splitlines():
        m = re.match(r"(\d+)\s+(\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)$", line.strip())
        if m:
            rows.append((int(m.group(1)), m.group(2), float(m.group(3)), float(m.group(4)), float(m.group(5))))
        m = re.match(r"(\d+)\s+filter decided (\d+) of (\d+) calls \(([\d.]+)%\)", line.strip())
        if m:
            decided[int(m.group(1))] = (int(m.group(2)), int(m.group(3)), float(m.group(4)))
    return (rows, decided), None


def run_cited(build_dir, seconds_limit, failed):
    """Each of CITED_RUNS once: [(command text, where cited, output lines or None, why)]."""
    done = []
    for program, argv, cited in CITED_RUNS:
        text = shlex.join([os.path.join(os.path.relpath(build_dir, ROOT), "bench", program)] + argv)
        if program in failed:
            done.append((text, cited, None, "did not build"))
            continue
        log("run " + text)
        try:
            proc = subprocess.run([os.path.join(build_dir, "bench", program)] + argv, capture_output=True,
                                  text=True, timeout=seconds_limit)
        except (OSError, subprocess.TimeoutExpired) as e:
            done.append((text, cited, None, f"did not finish: {e}"))
            continue
        if proc.returncode != 0:
            done.append((text, cited, None, f"failed (exit {proc.returncode}): {proc.stderr.strip()[:300]}"))
            continue
        done.append((text, cited, proc.stdout.rstrip("\n").splitlines(), None))
    return done


def callgrind_command(build_dir, g, n, out_file=None):
    cmd = ["valgrind", "--tool=callgrind", "--toggle-collect=hdt_insert_many"]
    if out_file:
        cmd.append("--callgrind-out-file=" + out_file)
    return cmd + [os.path.join(build_dir, "bench", "triangulation_bench"), "--n", str(n), "--genus", str(g)]


def run_callgrind(build_dir, g, n, seed_dir):
    """Instructions collected inside hdt_insert_many, or (None, why)."""
    out_file = os.path.join(seed_dir, f"callgrind.g{g}.out")
    cmd = callgrind_command(build_dir, g, n, out_file)
    log(f"run callgrind g={g} N={n} (a minute or two)")
    t0 = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=1800)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, f"callgrind g={g}: {e}"
    if proc.returncode != 0:
        return None, f"callgrind g={g} failed (exit {proc.returncode}): {proc.stderr.strip()[-300:]}"
    total = None
    with open(out_file) as f:
        for line in f:
            m = re.match(r"(?:summary|totals):\s+(\d+)", line)
            if m:
                total = int(m.group(1))
    if total is None:
        return None, f"callgrind g={g}: no total in {out_file}"
    seconds = time.monotonic() - t0
    log(f"    {total} instructions, {total / n:.0f} per point, {seconds:.0f} s")
    return (total, seconds), None


def build_baseline(rev, jobs):
    """A release build of triangulation_bench at the commit rev, in a
    temporary git worktree: (its build directory, a cleanup function), or
    (None, why)."""
    top = tempfile.mkdtemp(prefix="hdt-baseline-")
    tree = os.path.join(top, "tree")

    def cleanup():
        subprocess.run(["git", "worktree", "remove", "--force", tree], cwd=ROOT, capture_output=True)
        shutil.rmtree(top, ignore_errors=True)

    try:
        subprocess.run(["git", "worktree", "add", "--detach", tree, rev], cwd=ROOT, check=True, capture_output=True)
        build_dir = os.path.join(tree, "build-baseline")
        log(f"building triangulation_bench at {rev} (the callgrind baseline)")
        # -Dbenchmarks=true where the option exists (it came with the
        # benchmarks' opt-in; before, they always built).
        setup = ["meson", "setup", build_dir, "-Dbuildtype=release", "-Dtests=false"]
        if subprocess.run(setup + ["-Dbenchmarks=true"], cwd=tree, capture_output=True).returncode != 0:
            shutil.rmtree(build_dir, ignore_errors=True)
            subprocess.run(setup, cwd=tree, check=True, capture_output=True)
        subprocess.run(["ninja", "-C", build_dir, "-j", str(jobs), "bench/triangulation_bench"], cwd=tree, check=True,
                       capture_output=True)
    except (OSError, subprocess.CalledProcessError) as e:
        cleanup()
        return None, f"callgrind baseline {rev}: {e}"
    return (build_dir, cleanup), None


# ---- the document ------------------------------------------------------------

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
    """Which libhdt was measured: --label, else `git describe` of the tree
    (with a word when lib/ or include/ have uncommitted changes)."""
    if label:
        return label
    head = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"], capture_output=True, text=True)
    if head.returncode != 0:
        return f"the source tree {ROOT} (not a git checkout)"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--", "lib", "include"],
                           capture_output=True, text=True).stdout.strip()
    return f"`{head.stdout.strip()}` (git describe)" + (", with uncommitted changes in lib/ or include/" if dirty else "")


def loadavg():
    try:
        with open("/proc/loadavg") as f:
            return " ".join(f.read().split()[:3])
    except OSError:
        return "?"


def header(w, args, info):
    w("# Benchmarks")
    w("")
    w("Written by `bench/compare.py`; rerun it rather than editing this file:")
    w("")
    w("```sh")
    w(shlex.join(["/usr/bin/python3", "bench/compare.py"] + sys.argv[1:]))
    w("```")
    w("")
    w("| | |")
    w("|---|---|")
    w(f"| date | {info['started']:%Y-%m-%d %H:%M} UTC |")
    w(f"| machine | {machine_description()} |")
    w(f"| load average | {info['load_start']} at the start, {loadavg()} at the end (other work on the machine) |")
    w(f"| libhdt | {source_description(args.label)} |")
    w(f"| compiler | {tool_version(['c++', '--version'])} |")
    w(f"| build | `{os.path.relpath(info['build_dir'], ROOT)}`: release (`-Dbuildtype=release`: -O3, NDEBUG) |")
    w(f"| CGAL | {info['cgal_text']} |")
    w(f"| duration | {info['elapsed'] / 60:.1f} min of runs"
      + (f", {info['build_s'] / 60:.1f} min of building before them" if info['build_s'] >= 1 else "") + " |")
    w("")


def method(w, args, cgal, sizes):
    w("## Method")
    w("")
    w("| program | what it runs |")
    w("|---|---|")
    w("| `bench/triangulation_bench.c` | libhdt through the public C API: `hdt_create` (first in the process, "
      "then a second, cached), `hdt_insert_many` (range) or `hdt_insert` one point at a time in input order, "
      "`hdt_remove_dummies`, `hdt_validate`; any genus (without `--n`, a per-genus sweep of its own) |")
    w("| `bench/cgal_bolza_bench.cpp` | CGAL's `Periodic_4_hyperbolic_Delaunay_triangulation_2` with its default "
      "traits (`Periodic_4_hyperbolic_Delaunay_triangulation_traits_2<>`, whose kernel is "
      "`Exact_predicates_exact_constructions_kernel_with_sqrt`, i.e. `CORE::Expr` coordinates) on the same "
      "genus-2 points: `insert(first, last, false)` (CGAL's spatial sort; dummies kept) or `insert(p)` one at a "
      "time without a hint, then `try_to_remove_dummy_vertices()` and `is_valid()`"
      + ("" if cgal else " (not run here)") + " |")
    w("| `bench/cgal_euclid_bench.cpp` | the Euclidean reference: CGAL's `Delaunay_triangulation_2` with "
      "`Exact_predicates_inexact_constructions_kernel` on as many points uniform in the unit square, range "
      "insert or one at a time, then `is_valid()`" + ("" if cgal else " (not run here)") + " |")
    w("| `bench/curves_bench.c` | points along curves (`bench/curve_points.h`) against random points, "
      "side by side in one process |")
    w("| `bench/near_circle_bench.c` | points 1e-15 from the unit circle (`bench/near_circle_points.h`) against "
      "points uniform in F_g: insertion, validation, save and load |")
    w("| `bench/predicates_bench.cpp` | the predicates alone: filtered and forced through the exact field |")
    w("| `bench/surface_bench.c` | polygon surfaces: the exact checks of `hdt_surface_random_symmetric`'s octagons "
      "and decagons, and their certified systole |")
    w("| `bench/polygon_mesh_bench.cpp` | the same points inserted into the built-in M_2, the Bolza octagon given "
      "as a polygon and a random rational octagon, side by side, then an epsilon-net on each (the C++ core) |")
    w("")
    sizes_text = ", ".join(f"10^{len(str(n)) - 1}" if str(n).strip("0") == "1" else str(n) for n in sizes)
    w(f"- **Points.** All programs draw from one generator, `bench/uniform_points.h` (splitmix64, seed "
      f"{args.seed}): uniform for hyperbolic area in F_g (cosh r uniform in [1, cosh R] with R the circumradius "
      "of F_g, a uniform angle, rejection outside F_g, keeping a margin of 1e-9 from every side so that no point "
      "is on or within rounding of the boundary), or uniform in the unit square for the Euclidean reference. "
      "The same seed gives the same points bit for bit in every program. CGAL's Bolza octagon is libhdt's F_2 "
      "(vertices at the odd multiples of pi/8, side midpoints at the multiples of pi/4), so CGAL gets the "
      f"points unchanged, converted exactly from double. N = {sizes_text}.")
    clock = "the process's CPU time" if TIME_KEY == "cpu_us_per_pt" else "the wall clock"
    w(f"- **Times.** The per-point time is {clock} over the insertion call(s) only (no point generation, no "
      "dummy removal, no check), divided by N; the tables also show the "
      + ("wall-clock" if TIME_KEY == "cpu_us_per_pt" else "CPU") + " time. Every program is single-threaded, "
      "and CPU time is what other work on a shared machine disturbs least. Each run is a process of its own, "
      f"one at a time; a run predicted to take under {args.repeat_below:g} s is repeated {args.repeat} times "
      "and the fastest kept (best of). Dummy removal, creation and validation are timed on their own. "
      "Ratios are libhdt / CGAL: below 1, libhdt is faster.")
    w("- **Memory.** Peak MiB is the process's peak resident size (`VmHWM`) after insertion and dummy removal "
      "(the validity check and the face export come later and are not counted); bytes/vertex is that peak "
      "minus the resident size once the input array exists (before the triangulation is created), per vertex."
      + (" CGAL's figure includes its `CORE::Expr` points, created from the doubles inside the measured span."
         if cgal else ""))
    w("- **Validity.** libhdt: `hdt_validate` (every invariant, empty circles included, with exact predicates)"
      + (". CGAL Euclidean: `is_valid()` (combinatorics and the empty-circle property). CGAL Bolza: "
         "`is_valid()`, which in a release build checks only that every face is positively oriented (its "
         "other checks are assertions, compiled out with `NDEBUG`)." if cgal else "."))
    w(f"- **Same triangulation.** Up to N = {args.compare_max} each genus-2 program writes its triangles as the "
      "input indices of their 3 vertices, counterclockwise and rotated to start at the smallest, and the "
      "script compares the sets as oriented triangles and as unordered triples: "
      + ("between libhdt and CGAL's Bolza triangulation, and " if cgal else "")
      + "between range and one-by-one insertion, once the dummies are gone.")
    w(f"- **Skips.** Before each run the script extrapolates its wall time from the smaller N of the same "
      f"series (last time x 10 x the growth of the per-point time); a run predicted over {args.budget:g} s is "
      "skipped and listed under Notes.")
    w("")


def make_document(runner, args, sizes, info):
    R = runner.results
    cgal = info["cgal"]
    get = lambda prog, mode, g, n: R.get((prog, mode, g, n))
    lines = []
    w = lines.append

    def cell(prog, mode, g, n):
        if (prog, mode, g, n) in runner.missing:
            return runner.missing[(prog, mode, g, n)]
        return us(R.get((prog, mode, g, n)))

    header(w, args, info)
    method(w, args, cgal, sizes)

    clock = "CPU" if TIME_KEY == "cpu_us_per_pt" else "wall-clock"
    w("## Genus 2, range insertion")
    w("")
    if cgal:
        w(f"libhdt `hdt_insert_many`, CGAL `insert(first, last)`; {clock} µs per point.")
        w("")
        w("| N | libhdt µs/pt | CGAL Bolza µs/pt | CGAL Euclid µs/pt | libhdt/Bolza | libhdt/Euclid "
          "| wall µs/pt (libhdt / Bolza / Euclid) | dummy removal ms (libhdt / Bolza) "
          "| peak MiB (libhdt / Bolza / Euclid) | bytes/vertex (libhdt / Bolza / Euclid) "
          "| valid (libhdt / Bolza / Euclid) |")
        w("|---:|---:|---:|---:|---:|---:|---|---|---|---|---|")
    else:
        w(f"libhdt `hdt_insert_many`; {clock} µs per point.")
        w("")
        w("| N | libhdt µs/pt | wall µs/pt | dummy removal ms | peak MiB | bytes/vertex | valid |")
        w("|---:|---:|---:|---:|---:|---:|---|")
    for n in sizes:
        h, b, e = get("libhdt", "range", 2, n), get("cgal-bolza", "range", 2, n), get("cgal-euclid", "range", 0, n)
        if not any(k in R for k in [("libhdt", "range", 2, n), ("cgal-bolza", "range", 2, n),
                                     ("cgal-euclid", "range", 0, n)]):
            continue
        if cgal:
            w(f"| {n} | {cell('libhdt', 'range', 2, n)} | {cell('cgal-bolza', 'range', 2, n)} "
              f"| {cell('cgal-euclid', 'range', 0, n)} | {ratio(h, b)} | {ratio(h, e)} "
              f"| {wall(h)} / {wall(b)} / {wall(e)} "
              f"| {ms(h, 'remove_ms')} / {ms(b, 'remove_ms')} "
              f"| {mib(h)} / {mib(b)} / {mib(e)} | {bpv(h)} / {bpv(b)} / {bpv(e)} "
              f"| {valid(h)} / {valid(b)} / {valid(e)} |")
        else:
            w(f"| {n} | {cell('libhdt', 'range', 2, n)} | {wall(h)} | {ms(h, 'remove_ms')} | {mib(h)} "
              f"| {bpv(h)} | {valid(h)} |")
    w("")

    if any(k[1] == "one" for k in R):
        w("## Genus 2, one-by-one insertion")
        w("")
        if cgal:
            w(f"libhdt `hdt_insert`, CGAL `insert(p)`, in input order, no hint; {clock} µs per point.")
            w("")
            w("| N | libhdt µs/pt | CGAL Bolza µs/pt | CGAL Euclid µs/pt | libhdt/Bolza | libhdt/Euclid "
              "| wall µs/pt (libhdt / Bolza / Euclid) | peak MiB (libhdt / Bolza / Euclid) "
              "| valid (libhdt / Bolza / Euclid) |")
            w("|---:|---:|---:|---:|---:|---:|---|---|---|")
        else:
            w(f"libhdt `hdt_insert` in input order; {clock} µs per point.")
            w("")
            w("| N | libhdt µs/pt | wall µs/pt | libhdt one / range | peak MiB | valid |")
            w("|---:|---:|---:|---:|---:|---|")
        for n in sizes:
            h, b, e = get("libhdt", "one", 2, n), get("cgal-bolza", "one", 2, n), get("cgal-euclid", "one", 0, n)
            keys = [("libhdt", "one", 2, n), ("cgal-bolza", "one", 2, n), ("cgal-euclid", "one", 0, n)]
            if not any(k in R for k in keys):
                continue
            if cgal:
                w(f"| {n} | " + " | ".join(cell(*k) for k in keys)
                  + f" | {ratio(h, b)} | {ratio(h, e)} | {wall(h)} / {wall(b)} / {wall(e)} "
                  f"| {mib(h)} / {mib(b)} / {mib(e)} | {valid(h)} / {valid(b)} / {valid(e)} |")
            else:
                w(f"| {n} | {cell(*keys[0])} | {wall(h)} | {ratio(h, get('libhdt', 'range', 2, n))} | {mib(h)} "
                  f"| {valid(h)} |")
        w("")

    genera = args.genera
    w("## libhdt per genus")
    w("")
    w(f"Range insertion; {clock} times. `hdt_create` is timed twice: the first in the process builds and "
      "certifies the genus's dummy point set, a second copies it.")
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

    w("## Same triangulation?")
    w("")
    w(f"Genus 2, after dummy removal. Face sets (N <= {args.compare_max}): each triangle as its 3 input point "
      "indices; 'oriented' compares them as counterclockwise cycles, 'as sets' as unordered triples.")
    w("")

    def faces_cell(pa, ma, pb, mb, n):
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

    vef = lambda r: f"{r['V']} / {r['E']} / {r['F']}"
    if cgal:
        w("| N | libhdt V / E / F | CGAL Bolza V / E / F | counts equal | libhdt vs CGAL Bolza faces "
          "| libhdt one vs range | CGAL one vs range |")
        w("|---:|---|---|---|---|---|---|")
    else:
        w("| N | libhdt V / E / F | libhdt one vs range |")
        w("|---:|---|---|")
    for n in sizes:
        h, b = get("libhdt", "range", 2, n), get("cgal-bolza", "range", 2, n)
        if not h or (cgal and not b):
            continue
        if not cgal:
            w(f"| {n} | {vef(h)} | {faces_cell('libhdt', 'one', 'libhdt', 'range', n)} |")
            continue
        if h["dummies_left"] or b["dummies_left"]:
            eq = f"not compared: dummies left (libhdt {h['dummies_left']}, CGAL {b['dummies_left']})"
        else:
            eq = "yes" if (h["V"], h["E"], h["F"]) == (b["V"], b["E"], b["F"]) else "**NO**"
        w(f"| {n} | {vef(h)} | {vef(b)} | {eq} | {faces_cell('libhdt', 'range', 'cgal-bolza', 'range', n)} "
          f"| {faces_cell('libhdt', 'one', 'libhdt', 'range', n)} "
          f"| {faces_cell('cgal-bolza', 'one', 'cgal-bolza', 'range', n)} |")
    w("")

    w("## Summary")
    w("")
    big = max(sizes)
    h, b, e = get("libhdt", "range", 2, big), get("cgal-bolza", "range", 2, big), get("cgal-euclid", "range", 0, big)
    if cgal:
        w(f"- genus 2, N = {big}, range insertion: libhdt {us(h)} µs/pt, libhdt/CGAL-Bolza = {ratio(h, b)}, "
          f"libhdt/CGAL-Euclidean = {ratio(h, e)}")
    else:
        w(f"- genus 2, N = {big}, range insertion: libhdt {us(h)} µs/pt")
    one_n = [n for n in sizes if get("libhdt", "one", 2, n)]
    if one_n:
        n = 100000 if 100000 in one_n else max(one_n)
        h1, b1 = get("libhdt", "one", 2, n), get("cgal-bolza", "one", 2, n)
        if cgal and b1:
            w(f"- genus 2, N = {n}, one by one: libhdt {us(h1)} µs/pt, CGAL Bolza {us(b1)} µs/pt, "
              f"libhdt/CGAL-Bolza = {ratio(h1, b1)}")
        else:
            w(f"- genus 2, N = {n}, one by one: libhdt {us(h1)} µs/pt")
    per_genus = []
    for g in genera:
        r = get("libhdt", "range", g, big)
        if r and h:
            per_genus.append(f"g={g}: {us(r)} µs/pt ({ratio(r, h)}x)")
    if per_genus:
        w(f"- per-point time against genus 2 at N = {big}: " + ", ".join(per_genus))
    if h:
        w(f"- libhdt peak memory at N = {big}, genus 2: {bpv(h)} bytes/vertex"
          + (f" (CGAL Bolza {bpv(b)}, CGAL Euclidean {bpv(e)})" if cgal else ""))
    w("")

    near = info.get("near_circle")
    if near is not None:
        w("## Points near the circle")
        w("")
        w("Points with 1 - |z| uniform in [1e-15, 2e-15] at uniform random angles (`bench/near_circle_points.h`) "
          "against as many points uniform in F_g, each set timed in the same process by "
          "`bench/near_circle_bench.c`: `hdt_insert` one by one (mean and max a point, ms), `hdt_insert_many` "
          "into a fresh handle, `hdt_validate`, `hdt_save` (both calls) and `hdt_load` of the result, wall "
          f"clock, one run (`near_circle_bench --genus {','.join(map(str, args.near_genera))} "
          f"--n {','.join(map(str, args.near_n))}`). Ratio: near-circle over uniform.")
        w("")
        w("| genus | n | points | insert mean | insert max | insert_many | validate | save | load |")
        w("|---|---|---|---|---|---|---|---|---|")
        keys = ["insert_mean", "insert_max", "insert_many", "validate", "save", "load"]
        for r in near:
            if r["points"] == "ratio":
                cells = [r[k] + "x" for k in keys]
            else:
                cells = [r[k + "_ms"] for k in keys]
            w(f"| {r['g']} | {r['n']} | {r['points']} | " + " | ".join(cells) + " |")
        w("")

    curves = info.get("curves")
    if curves is not None:
        w("## Points along curves")
        w("")
        w("Points sampled along a curve give the dummies thousands of neighbours and put many points exactly on "
          "one Euclidean line or circle. `bench/curves_bench.c` (shapes in `bench/curve_points.h`) times "
          f"`hdt_insert_many` of 10^4 points and `hdt_remove_dummies`, CPU time, best of {args.curves_repeat}, "
          "against 10^4 random points of F_g, side by side in the same process "
          f"(`curves_bench --repeat {args.curves_repeat}`).")
        w("")
        for row in curves:
            w(row)
        w("")
        within = []
        beyond = []
        for row in curves[2:]:
            cells = [c.strip() for c in row.strip("|").split("|")]
            if len(cells) >= 5 and cells[1] != "random":
                try:
                    factor = float(cells[4].rstrip("x"))
                except ValueError:
                    continue
                (within if factor < 3 else beyond).append(f"{cells[1]} (g = {cells[0]}, {cells[4]})")
        w("The target is under 3x random. Within it: " + (", ".join(within) or "none") + ". Beyond it: "
          + (", ".join(beyond) or "none") + ".")
        w("")

    predicates = info.get("predicates")
    if predicates is not None:
        rows, decided = predicates
        w("## Predicates")
        w("")
        w(f"`bench/predicates_bench.cpp` ({args.predicates_calls} calls per predicate and genus): nanoseconds per "
          "call on random non-degenerate input (points of the disk of radius 0.8, random translations of N), "
          "through the filters as the triangulation calls them, and the same calls forced through the exact "
          "field K_g (fewer of them).")
        w("")
        w("| genus | predicate | filtered ns | exact ns | exact / filtered |")
        w("|---:|---|---:|---:|---:|")
        for g, name, filtered, exact, r in rows:
            w(f"| {g} | {name} | {filtered:.0f} | {exact:,.0f} | {r:,.0f} |")
        w("")
        if decided:
            w("The filters decided " + "; ".join(
                f"{d} of {t} calls at genus {g} ({p:.4f}%)" for g, (d, t, p) in sorted(decided.items())) + ".")
            w("")

    callgrind = info.get("callgrind")
    if callgrind is not None:
        w("## Instructions per point (callgrind)")
        w("")
        w("Timings on a shared machine are noisy; instruction counts are not. The instructions executed inside "
          f"`hdt_insert_many` for N = {args.callgrind_n} points uniform in F_g (seed 1), counted by callgrind "
          "from the release build above:")
        w("")
        w("```sh")
        w(shlex.join(callgrind_command(os.path.relpath(info["build_dir"], ROOT), "G", args.callgrind_n)))
        w("```")
        w("")
        w(f"Instructions per point = the total / {args.callgrind_n}. The last column is the wall time of the "
          "whole run under valgrind (the program's other work, such as `hdt_create`, runs instrumented too).")
        w("")
        baseline = dict(info.get("callgrind_baseline") or [])
        if baseline:
            w(f"Against `{args.callgrind_baseline}` (`--callgrind-baseline`), built the same way in a temporary "
              "worktree and counted in the same run:")
            w("")
            w(f"| genus | instructions in hdt_insert_many | per point | at {args.callgrind_baseline}, per point "
              "| change | run s |")
            w("|---:|---:|---:|---:|---:|---:|")
        else:
            w("| genus | instructions in hdt_insert_many | per point | run s |")
            w("|---:|---:|---:|---:|")
        for g, (total, seconds) in callgrind:
            if baseline:
                before = baseline.get(g)
                was = f"{before[0] / args.callgrind_n:,.0f}" if before else "-"
                change = f"{100 * (total / before[0] - 1):+.1f}%" if before else "-"
                w(f"| {g} | {total:,} | {total / args.callgrind_n:,.0f} | {was} | {change} | {seconds:.0f} |")
            else:
                w(f"| {g} | {total:,} | {total / args.callgrind_n:,.0f} | {seconds:.0f} |")
        w("")

    w("## Figures cited by the header and the docs")
    w("")
    w("`include/hdt.h` states what a caller can rely on (complexity, bounds, limits) and points here for "
      "measured times. Each command below ran once, in this run, from the release build above; its output "
      "is as printed (CPU times unless it says otherwise).")
    w("")
    for text, cited, output, why in info.get("cited") or []:
        w(f"`{text}` (cited in {cited}):")
        w("")
        if output is None:
            w(f"not measured: {why}")
        elif any(line.startswith("|") for line in output) and not any(line[:1].isspace() for line in output):
            w("\n".join(output))
        else:
            w("```text")
            w("\n".join(output))
            w("```")
        w("")
    if info.get("cited") is None:
        w("Not run (`--no-cited`).")
        w("")
    w("Figures measured once by a command this script does not rerun (too long for it, or a driver that is "
      "not a program of `bench/`); the date is that of the measurement:")
    w("")
    w("| figure | measured by, when | cited in |")
    w("|---|---|---|")
    for figure, how, cited in RECORDED_FIGURES:
        w(f"| {figure} | {how} | {cited} |")
    w("")

    if runner.notes:
        w("## Notes")
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
    ap.add_argument("--no-cgal", action="store_true", help="libhdt only, even when CGAL is installed")
    ap.add_argument("--install-cgal", action="store_true",
                    help="install Debian's libcgal-dev with apt-get when it is missing")
    ap.add_argument("--no-build", action="store_true", help="use the programs already built")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="ninja's parallel jobs (default: the cores)")
    ap.add_argument("--curves-repeat", type=int, default=5, help="curves_bench --repeat (best of)")
    ap.add_argument("--no-curves", action="store_true", help="skip curves_bench")
    ap.add_argument("--no-near-circle", action="store_true", help="skip near_circle_bench")
    ap.add_argument("--near-genera", type=int, nargs="+", default=[16, 64, 256], help="near_circle_bench --genus")
    ap.add_argument("--near-n", type=int, nargs="+", default=[100, 100, 20],
                    help="near_circle_bench --n, one a genus (the last for the rest)")
    ap.add_argument("--predicates-calls", type=int, default=50000, help="predicates_bench's calls per predicate")
    ap.add_argument("--no-predicates", action="store_true", help="skip predicates_bench")
    ap.add_argument("--no-cited", action="store_true",
                    help="skip the runs of the figures hdt.h and the docs cite (CITED_RUNS)")
    ap.add_argument("--callgrind", default="2,32",
                    help="genera whose hdt_insert_many instructions callgrind counts ('' for none)")
    ap.add_argument("--callgrind-n", type=int, default=100000, help="points of the callgrind runs")
    ap.add_argument("--callgrind-baseline", default=None, metavar="REV",
                    help="also count the commit REV (built in a temporary worktree) and show the change")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build-bench"))
    ap.add_argument("--label", default=None, help="what libhdt is measured (default: git describe)")
    ap.add_argument("--out", default=None, help="a copy of the document (default BUILD_DIR/bench-table.md)")
    ap.add_argument("--write", default=None, metavar="FILE",
                    help="write the document to FILE too: --write docs/benchmarks.md")
    args = ap.parse_args()
    global TIME_KEY
    TIME_KEY = "cpu_us_per_pt" if args.clock == "cpu" else "us_per_pt"
    args.genera = sorted({2} | {int(g) for g in args.genera.split(",") if g})
    callgrind_genera = [int(g) for g in args.callgrind.split(",") if g.strip()]
    build_dir = os.path.abspath(args.build_dir)
    out = args.out or os.path.join(build_dir, "bench-table.md")

    # CGAL: used when installed (or installed on request), else left out and said so.
    if args.no_cgal:
        cgal, cgal_text = False, "not measured (`--no-cgal`)"
    else:
        if not cgal_installed() and args.install_cgal:
            install_cgal()
        cgal = cgal_installed()
        cgal_text = (f"{cgal_version()} (Debian libcgal-dev)" if cgal else
                     "not measured: Debian's libcgal-dev is not installed on this machine, so the CGAL "
                     "columns are left out (`--install-cgal` installs it)")
    if not cgal and not args.no_cgal:
        log("libcgal-dev is not installed: libhdt only (--install-cgal installs it)")

    build_t0 = time.monotonic()
    failed_extra = []
    if not args.no_build:
        if shutil.which("meson") is None:
            sys.exit("meson not found: run bash .ci/install-deps first")
        failed_extra = build(build_dir, cgal, args.jobs)
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
    for program in failed_extra:
        runner.notes.append(f"bench/{program} did not build; its table is left out")
    modes = ["range"] + ([] if args.no_one else ["one"])
    peers = ["cgal-bolza", "cgal-euclid"] if cgal else []
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

    info = {"started": started, "load_start": load_start, "build_dir": build_dir, "build_s": build_s,
            "cgal": cgal, "cgal_text": cgal_text}
    if not args.no_curves and "curves_bench" not in failed_extra:
        info["curves"], why = run_curves(build_dir, args.curves_repeat, max(3 * args.budget, 60))
        if why:
            runner.notes.append(why)
    if not args.no_near_circle and "near_circle_bench" not in failed_extra:
        info["near_circle"], why = run_near_circle(build_dir, args.near_genera, args.near_n,
                                                   max(20 * args.budget, 900))
        if why:
            runner.notes.append(why)
    if not args.no_predicates and "predicates_bench" not in failed_extra:
        info["predicates"], why = run_predicates(build_dir, args.predicates_calls, max(3 * args.budget, 60))
        if why:
            runner.notes.append(why)
    if not args.no_cited:
        info["cited"] = run_cited(build_dir, max(3 * args.budget, 60), failed_extra)
    else:
        info["cited"] = None
    if callgrind_genera:
        if shutil.which("valgrind") is None:
            runner.notes.append("valgrind is not installed: no instruction counts")
        else:
            counts = []
            for g in callgrind_genera:
                total, why = run_callgrind(build_dir, g, args.callgrind_n, runner.faces_dir)
                if why:
                    runner.notes.append(why)
                else:
                    counts.append((g, total))
            info["callgrind"] = counts
            if args.callgrind_baseline:
                built, why = build_baseline(args.callgrind_baseline, args.jobs)
                if why:
                    runner.notes.append(why)
                else:
                    baseline_dir, cleanup = built
                    try:
                        before = []
                        for g in callgrind_genera:
                            total, why = run_callgrind(baseline_dir, g, args.callgrind_n, runner.faces_dir)
                            if why:
                                runner.notes.append(why)
                            else:
                                before.append((g, total))
                        info["callgrind_baseline"] = before
                    finally:
                        cleanup()
    info["elapsed"] = time.monotonic() - t0

    document = make_document(runner, args, sizes, info)
    print(document)
    targets = [out] + ([os.path.join(os.getcwd(), args.write)] if args.write else [])
    for path in targets:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        with open(path, "w") as f:
            f.write(document + "\n")
        log(f"written to {path}")
    bad = [k for k, r in runner.results.items() if r and (r["valid"] == 0 or r.get("failed"))]
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
