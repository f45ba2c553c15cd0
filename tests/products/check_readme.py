#!/usr/bin/env python3
"""The documentation, checked against the repository and the built library.

    check_readme.py --source-root DIR --library PATH/libhdt.so.0 [--cc "cc ..."]

1. Every relative link (and image) of README.md, CONTRIBUTING.md and
   docs/*.md points to a file or directory of the repository, and a
   "#fragment" to a heading of the Markdown file it names.
2. Every repository path those files write in backquotes (`.ci/run`,
   `tests/abi/README.md`, `lib/group/`, ...) exists.
3. Neither they nor bindings/python/README.md and the manual page link to or
   mention the team's notes outside the repository.
4. The README's first ```c block compiles against the built library (the
   compiler of --cc, or $CC, or cc; -std=c99 -Wall -Wextra -Werror) and runs
   with exit status 0.
5. The README's first ```python block runs with the built library
   (HDT_LIBRARY, PYTHONPATH=bindings/python, as the python test does), in a
   temporary directory.

Every failure names the file, the line and, for the examples, the block.
Standard library only.
"""
import argparse
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile

FAILURES = []

# Where Markdown links are checked.
LINKED = ["README.md", "CONTRIBUTING.md", "docs/*.md"]
# Where the notes outside the repository must not appear.
CLEAN = LINKED + ["bindings/python/README.md", "bindings/cli/hdt-triangulate.1"]
# Names of the team's notes, which live outside the repository (spelled in
# pieces so that this file does not mention them either).
FORBIDDEN = [re.compile(re.escape("../" + "shared")), re.compile(r"\b" + "DESIGN" + r"\.md\b")]
# Top-level folders of the repository: a backquoted path starting with one of
# them names a file of the repository. (lib/ alone is left out: install paths
# such as lib/x86_64-linux-gnu/ start with it too; lib/LAYER/ is checked.)
REPOSITORY_DIRS = (".ci/", "bench/", "bindings/", "docs/", "examples/", "include/", "tests/")
LIB_LAYERS = ("exact", "group", "surface", "predicates", "triangulation", "capi", "picture")


def fail(where, message):
    FAILURES.append(f"{where}: {message}")
    print(f"FAIL {where}: {message}")


def read_lines(path):
    with open(path, encoding="utf-8") as f:
        return f.read().split("\n")


def markdown_files(root, patterns):
    found = []
    for pattern in patterns:
        matches = sorted(glob.glob(os.path.join(root, pattern)))
        if not matches and not glob.has_magic(pattern):
            fail(pattern, "missing")
        found += matches
    return found


def strip_code(lines):
    """The lines with fenced blocks blanked (links are not looked for in code);
    inline code spans are kept for the path check."""
    out, fenced = [], False
    for line in lines:
        if line.lstrip().startswith("```"):
            fenced = not fenced
            out.append("")
            continue
        out.append("" if fenced else line)
    return out


def slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"`", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    result = set()
    fenced = False
    for line in read_lines(path):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6} ", line):
            result.add(slug(line.lstrip("#")))
    return result


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE_SPAN = re.compile(r"`([^`\n]+)`")


def check_links(root, path):
    name = os.path.relpath(path, root)
    lines = strip_code(read_lines(path))
    for number, line in enumerate(lines, 1):
        for target in LINK.findall(re.sub(CODE_SPAN, "", line)):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            file_part, _, fragment = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
            if not resolved.startswith(os.path.normpath(root) + os.sep):
                fail(f"{name}:{number}", f"the link ({target}) leaves the repository")
                continue
            if not os.path.exists(resolved):
                fail(f"{name}:{number}", f"the link ({target}) points to {os.path.relpath(resolved, root)}, "
                                         "which does not exist")
                continue
            if fragment and resolved.endswith(".md") and fragment not in anchors(resolved):
                fail(f"{name}:{number}", f"the link ({target}): {os.path.relpath(resolved, root)} has no "
                                         f"heading with the anchor #{fragment}")


def check_paths(root, path):
    """Backquoted repository paths, in text and code blocks alike."""
    name = os.path.relpath(path, root)
    for number, line in enumerate(read_lines(path), 1):
        for span in CODE_SPAN.findall(line):
            for word in span.split():
                word = word.strip("'\",;:()")
                is_layer = re.match(r"lib/(%s)(/|$)" % "|".join(LIB_LAYERS), word)
                if not (word.startswith(REPOSITORY_DIRS) or is_layer or word == "lib/hdt.map"):
                    continue
                if any(re.fullmatch(r"[A-Z][A-Z_]+", part) for part in word.split("/")) or re.search(r"[*?]", word):
                    continue  # a placeholder (tests/fuzz/crashes/FILE) or a pattern
                if not os.path.exists(os.path.join(root, word)):
                    fail(f"{name}:{number}", f"`{word}` is not a file of the repository")


def check_clean(root, path):
    name = os.path.relpath(path, root)
    for number, line in enumerate(read_lines(path), 1):
        for pattern in FORBIDDEN:
            if pattern.search(line):
                fail(f"{name}:{number}", "mentions the team's notes outside the repository "
                                         f"({pattern.search(line).group(0)}); say it in the project's own docs")


def first_block(lines, language):
    """(first line number of the code, code lines) of the first ```language
    block, or (None, None)."""
    for i, line in enumerate(lines):
        if line.strip() == "```" + language:
            for j in range(i + 1, len(lines)):
                if lines[j].strip().startswith("```"):
                    return i + 2, lines[i + 1:j]
            return i + 2, lines[i + 1:]
    return None, None


def remap(output, filename, readme, start):
    """Compiler and interpreter messages about FILENAME, with its line numbers
    turned into README.md's."""
    def c_line(m):
        return f"{readme}:{int(m.group(1)) + start - 1}:"

    def py_line(m):
        return f'File "{readme}", line {int(m.group(1)) + start - 1}'
    output = re.sub(re.escape(filename) + r":(\d+):", c_line, output)
    return re.sub(r'File "[^"]*' + re.escape(filename) + r'", line (\d+)', py_line, output)


def check_c_example(root, library, cc, tmp):
    lines = read_lines(os.path.join(root, "README.md"))
    start, code = first_block(lines, "c")
    if code is None:
        fail("README.md", "no ```c block")
        return
    block = f"README.md:{start}: the first ```c block (lines {start}-{start + len(code) - 1})"
    source = os.path.join(tmp, "readme_example.c")
    with open(source, "w") as f:
        f.write("\n".join(code) + "\n")
    program = os.path.join(tmp, "readme_example")
    libdir = os.path.dirname(os.path.abspath(library))
    command = shlex.split(cc) + ["-std=c99", "-Wall", "-Wextra", "-Werror", "-o", program, source,
                                 "-I" + os.path.join(root, "include"), os.path.abspath(library),
                                 "-Wl,-rpath," + libdir]
    compiled = subprocess.run(command, capture_output=True, text=True)
    if compiled.returncode != 0:
        fail(block, "does not compile against the built library:\n"
             + remap(compiled.stdout + compiled.stderr, source, "README.md", start).rstrip()
             + "\n(" + shlex.join(command) + ")")
        return
    ran = subprocess.run([program], capture_output=True, text=True, cwd=tmp, timeout=120,
                         env=dict(os.environ, LD_LIBRARY_PATH=libdir))
    if ran.returncode != 0:
        fail(block, f"exits with status {ran.returncode}:\n{ran.stdout}{ran.stderr}".rstrip())
        return
    print(f"ok   {block} compiles and runs: {ran.stdout.strip()}")


def check_python_example(root, library, tmp):
    lines = read_lines(os.path.join(root, "README.md"))
    start, code = first_block(lines, "python")
    if code is None:
        fail("README.md", "no ```python block")
        return
    block = f"README.md:{start}: the first ```python block (lines {start}-{start + len(code) - 1})"
    script = os.path.join(tmp, "readme_example.py")
    with open(script, "w") as f:
        f.write("\n".join(code) + "\n")
    workdir = os.path.join(tmp, "python")
    os.mkdir(workdir)
    env = dict(os.environ, HDT_LIBRARY=os.path.abspath(library),
               PYTHONPATH=os.path.join(root, "bindings", "python"), PYTHONDONTWRITEBYTECODE="1")
    ran = subprocess.run([sys.executable, script], capture_output=True, text=True, cwd=workdir, env=env,
                         timeout=300)
    if ran.returncode != 0:
        fail(block, f"exits with status {ran.returncode} (python {sys.executable}, "
             f"HDT_LIBRARY={library}):\n" + remap(ran.stdout + ran.stderr, script, "README.md", start).rstrip())
        return
    print(f"ok   {block} runs: {ran.stdout.strip()}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source-root", required=True)
    parser.add_argument("--library", required=True, help="the built libhdt.so.0")
    parser.add_argument("--cc", default=os.environ.get("CC", "cc"), help="the C compiler command")
    args = parser.parse_args()
    root = os.path.abspath(args.source_root)

    linked = markdown_files(root, LINKED)
    for path in linked:
        check_links(root, path)
        check_paths(root, path)
    for path in markdown_files(root, CLEAN):
        check_clean(root, path)
    if not FAILURES:
        print(f"ok   links and paths of {', '.join(os.path.relpath(p, root) for p in linked)}")
    with tempfile.TemporaryDirectory() as tmp:
        check_c_example(root, args.library, args.cc, tmp)
        check_python_example(root, args.library, tmp)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
