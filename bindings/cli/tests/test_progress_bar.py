"""hdt-triangulate's progress bar: drawn on stderr when it is a terminal (a
pseudo-terminal here) and the insertion or refinement runs for more than a
second, ending at 100% with a newline; absent on a pipe and for a short run.

Usage: test_progress_bar.py PATH_TO_hdt-triangulate
"""

import os
import pty
import subprocess
import sys

TOOL = sys.argv[1]
MARK = b"hdt-triangulate: insert ["


def stderr_of(args, terminal):
    """The tool's stderr, from a pseudo-terminal or a pipe."""
    command = [TOOL, *args, "-o", "/dev/null"]
    if not terminal:
        done = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, check=True, timeout=300)
        return done.stderr
    main, sub = pty.openpty()
    process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=sub)
    os.close(sub)
    out = b""
    while True:
        try:
            chunk = os.read(main, 65536)
        except OSError:  # EIO: the tool closed its end
            break
        if not chunk:
            break
        out += chunk
    os.close(main)
    assert process.wait(timeout=300) == 0
    return out


def main():
    # 2 million points: more than a second to insert on any machine we run on.
    long_run = ["--genus", "2", "--random", "2000000", "--seed", "3"]
    shown = stderr_of(long_run, terminal=True)
    assert MARK in shown, shown[-300:]
    last = shown[shown.rindex(MARK):]
    assert last.startswith(MARK + b"#" * 30 + b"] 100% (2000000/2000000)\r\n"), last[:120]
    counts = [int(bar.split(b"(")[1].split(b"/")[0]) for bar in shown.split(b"\r") if bar.startswith(MARK)]
    assert counts == sorted(counts), counts

    assert b"\r" not in stderr_of(long_run, terminal=False)
    assert MARK not in stderr_of(["--genus", "2", "--random", "1000"], terminal=True)
    print(f"ok: {len(counts)} bars, none on a pipe or for a short run")


if __name__ == "__main__":
    main()
