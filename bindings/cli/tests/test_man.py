#!/usr/bin/env python3
"""The manual page of hdt-triangulate against the tool.

    python3 test_man.py PATH/TO/hdt-triangulate PATH/TO/hdt-triangulate.1

Checks: every option of `--help` (long and short) has an entry under OPTIONS
in the manual and every entry there is in `--help`; every option the manual
mentions anywhere is one of them; `--help` ends by pointing at
hdt-triangulate(1); the version in the manual's .TH line is the tool's; and
the page renders without a warning, with `man -l` (or `groff -man -Tutf8`
when man is not installed; that check is skipped when neither is).
Standard library only.
"""
import os
import re
import shutil
import subprocess
import sys

LONG = re.compile(r"(?<![\w-])--[a-z][a-z-]*[a-z]")
SHORT = re.compile(r"(?<![\w-])-[a-zA-Z](?![\w-])")
FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("FAIL: " + message)


def man_text(path):
    """The page's source without comment lines, with roff's escaped minus
    signs as plain hyphens."""
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith(('.\\"', "'\\\""))]
    return "".join(lines).replace("\\-", "-")


def option_heads(text):
    """The options of the tagged paragraphs of the OPTIONS section: the line
    after each .TP."""
    section = re.search(r"^\.SH OPTIONS\n(.*?)^\.SH ", text, re.S | re.M)
    if not section:
        return None
    lines = section.group(1).splitlines()
    heads = [lines[i + 1] for i, line in enumerate(lines[:-1]) if line.startswith(".TP")]
    return heads


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    tool, page = sys.argv[1:]
    help_run = subprocess.run([tool, "--help"], capture_output=True, text=True)
    check(help_run.returncode == 0, f"--help exited {help_run.returncode}")
    help_text = help_run.stdout
    check(help_text.rstrip().endswith("See hdt-triangulate(1)."),
          "--help does not end with 'See hdt-triangulate(1).'")

    text = man_text(page)
    heads = option_heads(text)
    check(heads, f"{page}: no .SH OPTIONS section with .TP entries")
    heads = heads or []
    head_long = {o for h in heads for o in LONG.findall(h)}
    head_short = {o for h in heads for o in SHORT.findall(h)}

    # The option column of --help: the first 22 characters of the lines that
    # start with blanks and a '-'.
    help_lines = [line for line in help_text.splitlines() if re.match(r"\s+-", line)]
    help_long = set(LONG.findall(help_text))
    help_short = {o for line in help_lines for o in SHORT.findall(line[:22])}

    for option in sorted(help_long - head_long):
        check(False, f"{option} is in --help but has no entry under OPTIONS in {os.path.basename(page)}")
    for option in sorted(head_long - help_long):
        check(False, f"{option} has an entry under OPTIONS in {os.path.basename(page)} but is not in --help")
    for option in sorted(help_short - head_short):
        check(False, f"{option} is in --help but has no entry under OPTIONS in {os.path.basename(page)}")
    for option in sorted(head_short - help_short):
        check(False, f"{option} has an entry under OPTIONS in {os.path.basename(page)} but is not in --help")
    for option in sorted(set(LONG.findall(text)) - head_long):
        check(False, f"{os.path.basename(page)} mentions {option}, which is not one of its OPTIONS")

    # The version of the .TH line, "libhdt X.Y.Z", is the tool's.
    version_run = subprocess.run([tool, "--version"], capture_output=True, text=True)
    tool_version = re.search(r"hdt-triangulate (\S+)", version_run.stdout)
    th = re.search(r'^\.TH \S+ 1 \S+ "libhdt (\S+)"', text, re.M)
    check(th is not None, f"{page}: no '.TH HDT-TRIANGULATE 1 DATE \"libhdt VERSION\"' line")
    if th and tool_version:
        check(th.group(1) == tool_version.group(1),
              f"{os.path.basename(page)} says libhdt {th.group(1)}, the tool is {tool_version.group(1)}")

    # Rendering, warnings on.
    env = dict(os.environ, MANWIDTH="80", LC_ALL="C.UTF-8")
    if shutil.which("man"):
        command = ["man", "--warnings=w", "-l", page]
    elif shutil.which("groff"):
        command = ["groff", "-man", "-Tutf8", "-ww", "-z", page]
    else:
        print("neither man nor groff is installed: the rendering is not checked (skipped)")
        command = None
    if command:
        run = subprocess.run(command, capture_output=True, text=True, env=env)
        check(run.returncode == 0, f"{' '.join(command)} exited {run.returncode}: {run.stderr.strip()}")
        check(run.stderr.strip() == "", f"{' '.join(command)} warns:\n{run.stderr.rstrip()}")
        if command[0] == "man":
            check("OPTIONS" in run.stdout and "EXIT STATUS" in run.stdout,
                  "man -l renders no OPTIONS or EXIT STATUS section")

    if FAILURES:
        print(f"{len(FAILURES)} check(s) failed")
        return 1
    print(f"ok: {len(head_long)} long and {len(head_short)} short options documented alike; "
          + ("rendered by " + command[0] + " without warnings" if command else "rendering not checked"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
