#!/usr/bin/env python3
"""The format registry (formats/registry.hpp) is the only list of scene formats.

Outside it, code may name its own format (a format's own files use
FormatId::kX to look up their registry entry) but may not tell formats
apart itself. This reports, in the C and C++ sources under ROOT (tests
excluded):
  - a comparison or switch on a FormatId (`== FormatId::k..`, `case FormatId::k..`);
  - a string literal that is a format's name or extension ("cs418", ".rt", ...);
  - a wire tag constant other than SLD's (MINRT_SCENE_FORMAT_CS418 ...).
Usage: check_format_lists.py ROOT [REGISTRY]   (exit 1 and one line per finding;
REGISTRY defaults to ROOT/formats/registry.hpp)
"""
import pathlib
import re
import sys

REGISTRY = "formats/registry.hpp"
SOURCE_DIRS = ["core", "formats", "render", "host", "runtime", "protocol", "firmware_sim", "posix", "include", "tools"]
SUFFIXES = {".cpp", ".hpp", ".h", ".c"}


def registry_words(registry):
    """Format names and extensions, read from the registry itself."""
    text = registry.read_text()
    names = re.findall(r'\{FormatId::k\w+, "([a-z0-9]+)"', text)
    exts = re.findall(r'"(\.[a-z0-9]+)"', text)
    return set(names) | set(exts)


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    registry = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else root / REGISTRY
    words = registry_words(registry)
    if not words:
        print(f"{REGISTRY}: no format names found")
        return 1
    # Names as the registry spells them; extensions in any case (".SLD").
    literal = re.compile(r'"(' + "|".join(re.escape(w) if not w.startswith(".") else "(?i:" + re.escape(w) + ")"
                                         for w in sorted(words)) + r')"')
    compare = re.compile(r'(?:[=!]=\s*(?:\w+::)*FormatId::k\w+|(?:\w+::)*FormatId::k\w+\s*[=!]=|case\s+(?:\w+::)*FormatId::k)')
    tag = re.compile(r'MINRT_SCENE_FORMAT_(?!SLD\b|TAG_LIMIT\b)[A-Z0-9_]+')
    findings = []
    for d in SOURCE_DIRS:
        base = root / d
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            rel = path.relative_to(root).as_posix()
            if path.suffix not in SUFFIXES or rel == REGISTRY or "/fixture/" in rel:
                continue
            for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                code = line.split("//", 1)[0]
                for rx, what in ((compare, "tells formats apart by FormatId"), (literal, "names a format"),
                                 (tag, "uses a format's wire tag")):
                    m = rx.search(code)
                    if m:
                        findings.append(f"{rel}:{n}: {what} ({m.group(0).strip()}): use formats/registry.hpp")
    for f in findings:
        print(f)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
