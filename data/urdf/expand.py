#!/usr/bin/env python3
"""Expands the fixtures' xacro sources into the URDF files beside this script.

ROS's own `xacro` needs a ROS workspace to resolve `$(find PKG)`; this script runs the
same expander, the `xacro` package from PyPI (2.1.1 was used), with `$(find PKG)` read
as `sources/FIXTURE/PKG`, the copies of the package files the fixture needs. It checks
each source against the git blob id in fixtures.toml first, so an edited copy is never
expanded as the repository's. The output is xacro's, behind a comment naming the
source; nothing else is changed (meshes stay `package://` names that nothing reads).

    python3 -m venv /tmp/xacro && /tmp/xacro/bin/pip install xacro==2.1.1
    /tmp/xacro/bin/python data/urdf/expand.py           # writes data/urdf/NAME.urdf
    /tmp/xacro/bin/python data/urdf/expand.py --check   # fails if any differs
"""

import hashlib
import os
import sys
import tomllib

import xacro
import xacro.substitution_args

HERE = os.path.dirname(os.path.abspath(__file__))


def git_blob(data: bytes) -> str:
    """The id `git hash-object` gives these bytes."""
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def expand(fixture: dict) -> str:
    """The URDF text of one fixture, its sources checked first."""
    root = os.path.join(HERE, "sources", fixture["name"])
    for f in fixture["files"]:
        with open(os.path.join(root, f["path"]), "rb") as fh:
            got = git_blob(fh.read())
        if got != f["git_blob"]:
            sys.exit(f"{fixture['name']}: {f['path']} is blob {got}, not {f['git_blob']}")
    # `$(find PKG)`: the fixture's copy of the package.
    xacro.substitution_args._eval_find = lambda pkg: os.path.join(root, pkg)
    doc = xacro.process_file(os.path.join(root, fixture["entry"]))
    body = doc.documentElement.toprettyxml(indent="  ")
    header = (
        '<?xml version="1.0"?>\n'
        f"<!-- {fixture['title']}: expanded by data/urdf/expand.py (xacro {xacro_version()})"
        f" from {fixture['repo']}, {fixture['entry']}, commit {fixture['commit']}"
        " (data/urdf/README.md). -->\n"
    )
    return header + body


def xacro_version() -> str:
    from importlib.metadata import version

    return version("xacro")


def main() -> None:
    check = "--check" in sys.argv[1:]
    with open(os.path.join(HERE, "fixtures.toml"), "rb") as fh:
        fixtures = tomllib.load(fh)["fixture"]
    stale = []
    for fixture in fixtures:
        text = expand(fixture)
        path = os.path.join(HERE, fixture["name"] + ".urdf")
        if check:
            with open(path, encoding="utf-8") as fh:
                if fh.read() != text:
                    stale.append(path)
        else:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text)
            print(f"wrote {os.path.relpath(path)} ({len(text.encode())} bytes)")
    if stale:
        sys.exit("differs from its expansion: " + ", ".join(stale))


if __name__ == "__main__":
    main()
