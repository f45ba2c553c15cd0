#!/usr/bin/env python3
"""Every code block of README.md (and docs/*.md), run from the build tree.

    check_readme_blocks.py --source-root DIR --build-root DIR [--cc "cc ..."] [--python PYTHON]

The fenced ```sh, ```c and ```python blocks of README.md and docs/*.md (not
docs/benchmarks.md, which bench/compare.py writes) are run in a temporary
copy of the repository root (its entries linked, `build` linked to the build
root, bindings/python copied so that pip writes nothing into the tree),
with HOME in the temporary directory and no HDT_LIBRARY, LD_LIBRARY_PATH,
PYTHONPATH or PKG_CONFIG_PATH from the caller: a block must say what it
needs, as a newcomer's shell after `bash .ci/demo` has nothing.

- ```sh: run by `bash -e -o pipefail`, in that copy. The README's first
  ```c block is saved there as prog.c first (the sh blocks compile it).
- ```c: compiled with the compiler of --cc against the build tree's
  pkg-config file (build/meson-uninstalled/hdt-uninstalled.pc), with an
  rpath to build/lib, and run.
- ```python: run by --python with HDT_LIBRARY (the build's libhdt.so.0) and
  PYTHONPATH=bindings/python, as README.md says for a build tree. A block
  that imports a module this python lacks (SciPy, say) is skipped, saying so.

A block must exit with status 0 within 60 s. When the next fenced block is a
```text block, with prose only (no heading) between them, it is the
block's expected output: stdout and stderr together must match it line for
line, "..." in it matching anything.

Markers, an HTML comment on the line before the block's fence (blank lines
allowed between):

    <!-- doc-test: skip (REASON) -->     the block is not run (REASON printed)
    <!-- doc-test: env NAME=VALUE ... (REASON) -->
                                         the block runs with these variables
                                         exported first (shell words, so
                                         $PWD is the repository copy)

Any other block of those languages runs, so a new block that fails, fails
the test; one that would change the machine or the build under test (sudo,
apt, ldconfig, dpkg, ninja, meson setup/configure/compile, `meson install`
without --destdir, .ci/run, .ci/demo, .ci/build, .ci/package,
.ci/install-deps) fails unrun until it is marked skip. Standard library only.
"""
import argparse
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

RUN = ("sh", "c", "python")
# The files whose blocks run, README.md first (its first ```c block is prog.c).
FILES = ["README.md", "docs/*.md"]
NOT_RUN = ["docs/benchmarks.md"]  # written by bench/compare.py, which would drop the markers
# What a block must not do on the machine that runs the tests (as root in
# CI), nor to the build under test: such a block fails unrun until it is
# marked skip.
UNSAFE = re.compile(r"\b(sudo|apt|apt-get|ldconfig|dpkg|ninja)\b|\bmeson (setup|configure|compile)\b"
                    r"|\bmeson install\b(?!.*--destdir)|\.ci/(run|demo|build|package|install-deps)\b")
MARKER = re.compile(r"<!--\s*doc-test:\s*(skip|env)\b(.*?)-->\s*$")
TIMEOUT = 60


def blocks(path):
    """[(line of the fence, language, code lines, marker or None)]; the
    marker is (kind, rest) of a doc-test comment before the fence."""
    lines = open(path, encoding="utf-8").read().split("\n")
    found, i = [], 0
    while i < len(lines):
        m = re.match(r"\s*```(\S*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        start, language = i, m.group(1)
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith("```"):
            j += 1
        marker, k = None, start - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        if k >= 0:
            mm = MARKER.search(lines[k])
            if mm:
                marker = (mm.group(1), mm.group(2).strip())
        # Prose only since the previous block's end: no heading.
        heading_before = any(re.match(r"#{1,6} ", line) for line in lines[found[-1][4] if found else 0:start])
        found.append((start + 1, language, lines[start + 1:j], marker, j + 1, heading_before))
        i = j + 1
    return found


def expected_output(found, index):
    """The code lines of the ```text block right after block index, or None."""
    if index + 1 < len(found):
        _, language, code, _, _, heading_before = found[index + 1]
        if language == "text" and not heading_before:
            return code
    return None


def matches(expected, output):
    want = [line.rstrip() for line in expected]
    got = [line.rstrip() for line in output.rstrip("\n").split("\n")]
    while want and not want[-1]:
        want.pop()
    if len(want) != len(got):
        return False
    for w, g in zip(want, got):
        pattern = ".*".join(re.escape(part) for part in w.split("..."))
        if not re.fullmatch(pattern, g):
            return False
    return True


def make_tree(source_root, build_root, tmp):
    """The repository copy the blocks run in."""
    tree = os.path.join(tmp, "repo")
    os.mkdir(tree)
    for name in os.listdir(source_root):
        if name in ("build", "bindings", ".git") or name.startswith("build-"):
            continue
        os.symlink(os.path.join(source_root, name), os.path.join(tree, name))
    os.symlink(build_root, os.path.join(tree, "build"))
    bindings = os.path.join(tree, "bindings")
    os.mkdir(bindings)
    for name in os.listdir(os.path.join(source_root, "bindings")):
        if name != "python":
            os.symlink(os.path.join(source_root, "bindings", name), os.path.join(bindings, name))
    shutil.copytree(os.path.join(source_root, "bindings", "python"), os.path.join(bindings, "python"),
                    ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    return tree


def clean_environment(tmp):
    env = dict(os.environ)
    for name in ("HDT_LIBRARY", "LD_LIBRARY_PATH", "PYTHONPATH", "PYTHONHOME", "PKG_CONFIG_PATH",
                 "PKG_CONFIG_LIBDIR", "PKG_CONFIG_SYSROOT_DIR", "VIRTUAL_ENV", "PIP_FIND_LINKS",
                 "PIP_INDEX_URL", "PIP_EXTRA_INDEX_URL", "PIP_REQUIRE_VIRTUALENV"):
        env.pop(name, None)
    home = os.path.join(tmp, "home")
    os.makedirs(home, exist_ok=True)
    env.update(HOME=home, TMPDIR=tmp, PIP_NO_INDEX="1", PIP_CONFIG_FILE=os.devnull,
               PIP_DISABLE_PIP_VERSION_CHECK="1", PYTHONDONTWRITEBYTECODE="1")
    return env


def env_exports(rest):
    """The `export` lines of an env marker's NAME=VALUE words."""
    words = shlex.split(re.sub(r"\(.*\)\s*$", "", rest))
    for word in words:
        if not re.match(r"[A-Za-z_][A-Za-z0-9_]*=", word):
            raise ValueError(f"not NAME=VALUE: {word}")
        if re.search(r'["\\`]', word):
            raise ValueError(f"no quotes, backslashes or backquotes in a value: {word}")
    # Double quotes: $PWD and the like expand, in the repository copy.
    return "".join('export %s="%s"\n' % tuple(word.split("=", 1)) for word in words)


def missing_module(code, python):
    """A module the block imports that python cannot import, or None."""
    names = []
    for line in code:
        m = re.match(r"(?:from|import)\s+([A-Za-z_]\w*)", line)
        if m and m.group(1) not in names and m.group(1) != "hdt":
            names.append(m.group(1))
    for name in names:
        if subprocess.run([python, "-c", f"import {name}"], capture_output=True).returncode != 0:
            return name
    return None


def run_block(language, code, exports, tree, env, args):
    """(exit status, output, the command shown on failure)."""
    text = "\n".join(code) + "\n"
    if language == "sh":
        command = ["bash", "-e", "-o", "pipefail", "-c", exports + text]
        shown = "bash -e -o pipefail (the block)"
    elif language == "c":
        source = os.path.join(tree, "block.c")
        with open(source, "w") as f:
            f.write(text)
        pc = os.path.join(tree, "build", "meson-uninstalled")
        command = ["bash", "-e", "-c", exports +
                   f"export PKG_CONFIG_PATH={shlex.quote(pc)}\n"
                   f"{args.cc} -std=c99 -Wall -Wextra -Werror -o block block.c $(pkg-config --cflags --libs hdt)"
                   f" -Wl,-rpath,$PWD/build/lib\n./block\n"]
        shown = f"{args.cc} block.c $(pkg-config --cflags --libs hdt) with PKG_CONFIG_PATH={pc}, then ./block"
    else:
        script = os.path.join(tree, "block.py")
        with open(script, "w") as f:
            f.write(text)
        env = dict(env, HDT_LIBRARY=os.path.join(tree, "build", "lib", "libhdt.so.0"),
                   PYTHONPATH=os.path.join(tree, "bindings", "python"))
        command = ["bash", "-e", "-c", exports + f"exec {shlex.quote(args.python)} block.py\n"]
        shown = f"HDT_LIBRARY=build/lib/libhdt.so.0 PYTHONPATH=bindings/python {args.python} block.py"
    try:
        ran = subprocess.run(command, cwd=tree, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        return 124, out + f"\n(timed out after {TIMEOUT} s)", shown
    return ran.returncode, ran.stdout, shown


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source-root", required=True)
    parser.add_argument("--build-root", required=True)
    parser.add_argument("--cc", default=os.environ.get("CC", "cc"), help="the C compiler command")
    parser.add_argument("--python", default=sys.executable, help="the python for ```python blocks")
    args = parser.parse_args()
    source_root = os.path.abspath(args.source_root)
    build_root = os.path.abspath(args.build_root)
    files = []
    for pattern in FILES:
        for path in sorted(glob.glob(os.path.join(source_root, pattern))):
            name = os.path.relpath(path, source_root)
            if name not in NOT_RUN and name not in files:
                files.append(name)

    failures, ran, skipped = [], 0, 0
    with tempfile.TemporaryDirectory() as tmp:
        tree = make_tree(source_root, build_root, tmp)
        env = clean_environment(tmp)
        readme_blocks = blocks(os.path.join(source_root, "README.md"))
        first_c = next((code for _, language, code, *_ in readme_blocks if language == "c"), None)
        if first_c is not None:
            with open(os.path.join(tree, "prog.c"), "w") as f:
                f.write("\n".join(first_c) + "\n")
        for name in files:
            found = blocks(os.path.join(source_root, name))
            for index, (line, language, code, marker, end, _) in enumerate(found):
                if language not in RUN:
                    continue
                where = f"{name}:{line}: the ```{language} block"
                exports = ""
                if marker and marker[0] == "skip":
                    print(f"SKIP {where}: {marker[1] or '(no reason given)'}")
                    skipped += 1
                    continue
                unsafe = UNSAFE.search("\n".join(code)) if language == "sh" else None
                if unsafe:
                    failures.append(f"{where}: not run, it would run `{unsafe.group(0)}` on this machine: "
                                    "mark it <!-- doc-test: skip (REASON) -->")
                    print(f"FAIL {failures[-1]}")
                    continue
                if marker and marker[0] == "env":
                    try:
                        exports = env_exports(marker[1])
                    except ValueError as e:
                        failures.append(f"{where}: bad doc-test env marker: {e}")
                        print(f"FAIL {failures[-1]}")
                        continue
                missing = missing_module(code, args.python) if language == "python" else None
                if missing:
                    print(f"SKIP {where}: {args.python} has no module {missing}")
                    skipped += 1
                    continue
                status, output, shown = run_block(language, code, exports, tree, env, args)
                ran += 1
                expected = expected_output(found, index)
                if status != 0:
                    failures.append(f"{where}: exits with status {status} ({shown}):\n{output.rstrip()}")
                elif expected is not None and not matches(expected, output):
                    failures.append(f"{where}: prints\n{output.rstrip()}\n"
                                    f"not the ```text block at line {found[index + 1][0]}:\n"
                                    + "\n".join(expected).rstrip())
                else:
                    checked = f", output as at line {found[index + 1][0]}" if expected is not None else ""
                    print(f"ok   {where}{checked}" + (f" (with {marker[1]})" if marker else ""))
                    continue
                print(f"FAIL {failures[-1]}")
    print(f"{ran} blocks run, {skipped} skipped, {len(failures)} failed ({', '.join(files)})")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
