#!/usr/bin/env python3
"""Checks that #include "..." lines point down the layers (docs/architecture.md).

Usage: check_layers.py ROOT
Reads every C/C++/assembly file under ROOT's layer folders and fails (exit 1)
listing each include that crosses a forbidden boundary. Includes are
repository-root-relative for the freestanding layers ("core/base/arena.hpp"),
so the layer of the included file is the first part of its path; a bare name
("port.hpp") is a file of the includer's own folder and always allowed.
"""
import os
import re
import sys

# layer -> layers it may include (itself is always allowed). include/ (the
# <minrt/...> headers) is reached with angle brackets and allowed everywhere.
ALLOWED = {
    "core": set(),
    "formats": {"core"},
    "render": {"core", "formats"},
    "protocol": {"core/base"},
    "runtime": {"core", "formats", "render", "protocol"},
    "firmware_sim": {"posix"},
    # the Verilator harness: firmware-sim's board model and lock-step checker
    "rtl": {"firmware_sim", "posix"},
    "host": {"core", "formats", "render", "protocol", "posix"},
    # OS helpers every host tool shares (output files); nothing of the project.
    "posix": set(),
}
# Folders no layer below the hosts may name, whatever the include style.
FORBIDDEN_ANYWHERE = {
    "runtime": ("host/", "firmware_sim/"),
    "firmware_sim": ("runtime/",),
    "core": ("host/", "runtime/", "firmware_sim/"),
    "formats": ("host/", "runtime/", "firmware_sim/"),
    "render": ("host/", "runtime/", "firmware_sim/"),
    "protocol": ("host/", "runtime/", "firmware_sim/"),
    "posix": ("host/", "runtime/", "firmware_sim/"),
}
SOURCE = re.compile(r"\.(c|cc|cpp|h|hpp|S|ld)$")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
LAYERED = ("core", "formats", "render", "protocol", "posix")


def layer_of(path):
    """The layer an included path names, or None for a same-folder name."""
    first = path.split("/", 1)[0]
    if first not in LAYERED or "/" not in path:
        return None
    if first == "core":
        parts = path.split("/")
        return "core/" + parts[1] if len(parts) > 2 else "core"
    return first


def allowed(src_layer, target):
    if target is None or target.split("/")[0] == src_layer:
        return True
    for a in ALLOWED[src_layer]:
        if target == a or target.startswith(a + "/"):
            return True
    return False


def check(root):
    errors = []
    for top in ALLOWED:
        base = os.path.join(root, top)
        for dirpath, _, names in os.walk(base):
            for name in sorted(names):
                if not SOURCE.search(name):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                with open(path, encoding="utf-8", errors="replace") as f:
                    for lineno, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        inc = m.group(1)
                        bad = any(inc.startswith(p) or ("/" + p) in inc
                                  for p in FORBIDDEN_ANYWHERE.get(top, ()))
                        if bad or not allowed(top, layer_of(inc)):
                            errors.append(f"{rel}:{lineno}: error: {top}/ must not include \"{inc}\"")
    return errors


def main():
    if len(sys.argv) != 2:
        print("usage: check_layers.py ROOT", file=sys.stderr)
        return 2
    errors = check(sys.argv[1])
    for e in errors:
        print(e)
    if errors:
        print(f"check_layers: error: {len(errors)} forbidden include(s)", file=sys.stderr)
        return 1
    print("check_layers: every include points down the layers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
