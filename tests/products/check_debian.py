#!/usr/bin/env python3
"""The Debian packaging against the build (test 'debian', suite products).

- debian/changelog's newest version is meson.build's project version (a
  native package: the same string), and so are the Python package's
  versions (pyproject.toml, hdt.__version__);
- debian/libhdt0.symbols lists exactly the symbols the built libhdt.so.0
  exports, each with its version node (lib/hdt.map) and the version 0.N.0
  of its node HDT_0.N, none later than this one;
- include/hdt.h's HDT_VERSION_MAJOR/MINOR/PATCH say the same version.

dpkg-gensymbols -c4 (debian/rules) makes the same symbol check in a package
build; this one tells at once, in the plain test suite, that a new function
also needs a line in debian/libhdt0.symbols.

Usage: check_debian.py SOURCE_ROOT LIBRARY NM VERSION
"""

import re
import subprocess
import sys
from pathlib import Path


def version_key(text):
    return tuple(int(part) for part in re.findall(r"\d+", text))


def main():
    root, library, nm, version = Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
    errors = []

    first = (root / "debian" / "changelog").read_text(encoding="utf-8").splitlines()[0]
    match = re.match(r"^libhdt \(([^)]+)\) ", first)
    if not match:
        errors.append(f"debian/changelog: cannot read the version in {first!r}")
    elif match.group(1) != version:
        errors.append(f"debian/changelog says {match.group(1)}, meson.build says {version}")

    pyproject = (root / "bindings" / "python" / "pyproject.toml").read_text(encoding="utf-8")
    init = (root / "bindings" / "python" / "hdt" / "__init__.py").read_text(encoding="utf-8")
    for name, text, pattern in (("bindings/python/pyproject.toml", pyproject, r'(?m)^version = "([^"]+)"'),
                                ("bindings/python/hdt/__init__.py", init, r'(?m)^__version__ = "([^"]+)"')):
        found = re.search(pattern, text)
        if not found or found.group(1) != version:
            errors.append(f"{name} says {found.group(1) if found else 'no version'}, meson.build says {version}")

    # "0000000000012340 T hdt_systole@@HDT_0.1", "0000000000000000 A HDT_0.2"
    listing = subprocess.run([nm, "-D", "--defined-only", library], check=True,
                             capture_output=True, text=True).stdout
    exported = set()
    for line in listing.splitlines():
        name = line.split()[-1]
        symbol, _, node = name.replace("@@", "@").partition("@")
        exported.add(f"{symbol}@{node or symbol}")

    listed = {}
    for line in (root / "debian" / "libhdt0.symbols").read_text(encoding="utf-8").splitlines():
        if line.startswith(" "):
            symbol, introduced = line.split()[:2]
            listed[symbol] = introduced
    for symbol in sorted(exported - listed.keys()):
        errors.append(f"exported but not in debian/libhdt0.symbols: {symbol} (add it with its node's version)")
    for symbol in sorted(listed.keys() - exported):
        errors.append(f"in debian/libhdt0.symbols but not exported: {symbol}")
    for symbol, introduced in sorted(listed.items()):
        if version_key(introduced) > version_key(version):
            errors.append(f"debian/libhdt0.symbols: {symbol} from {introduced}, later than {version}")
        node = re.fullmatch(r".*@HDT_0\.(\d+)", symbol)
        if node and introduced != f"0.{node.group(1)}.0":
            errors.append(f"debian/libhdt0.symbols: {symbol} from {introduced}: node HDT_0.N comes with 0.N.0")

    # hdt.h's version macros: compile-time tests for later symbol nodes.
    header = (root / "include" / "hdt.h").read_text(encoding="utf-8")
    parts = [re.search(rf"(?m)^#define HDT_VERSION_{name} (\d+)$", header) for name in ("MAJOR", "MINOR", "PATCH")]
    said = ".".join(p.group(1) if p else "?" for p in parts)
    if said != version:
        errors.append(f"include/hdt.h's HDT_VERSION_MAJOR/MINOR/PATCH say {said}, meson.build says {version}")

    for error in errors:
        print(error, file=sys.stderr)
    if not errors:
        print(f"debian/: version {version}, {len(listed)} symbols as exported")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
