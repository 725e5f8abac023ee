#!/usr/bin/env python3
"""Checks that the commands written in README.md and docs/*.md run as written
from the repository root, after the README's two commands (set-up and build).

Usage: check_doc_commands.py --root REPO --build BUILD --shared SHARED [--no-run] [FILE.md...]

Commands are the lines of fenced blocks marked sh, bash, shell or console,
and the lines of unmarked fenced blocks and indented code blocks that start
with a command (a path under build/, scripts/, bench/ or tools/, or a program
such as cmake, ctest or python3); other lines of those blocks are output. An
unmarked block with a placeholder in one line is a usage synopsis.
A line ending in a backslash goes on with the next. For every command:

- no retired build folder (build-fw, build-sim, build/firmware, ...): the
  build is build/release;
- no bare tool name (host-send ...) where the tool is not installed: the
  path in build/release is written instead, so the command runs as written;
- every repository path it names exists (an output path's folder exists),
  and so does every such path in the documents' inline code;
- unless it is a synopsis (placeholders such as [OPTIONS], SCENE, p3|p6) or
  listed in SKIP with the reason, it runs and exits 0, or with the status its
  comment states ("# exit status 1: ...").

The commands run in a scratch copy of the root (the files they write stay out
of the checkout): symbolic links to REPO's tracked entries (not files earlier
commands left in the root), a copy of docs/,
build/release pointing to BUILD, and ../shared pointing to SHARED.
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
import time

FENCE_LANGS_SHELL = {"sh", "bash", "shell", "console"}
PROGRAMS = {"cmake", "ctest", "python3", "sh", "bash", "git", "man", "gdb-multiarch", "valgrind",
            "qemu-system-riscv32", "qemu-riscv32", "env", "time", "perf", "make", "apt-get", "sudo",
            "mkdir", "for", "cd", "ls", "cat", "rm", "cp", "mv", "echo", "printf", "export", "grep",
            "sed", "head", "tail", "diff", "cmp", "sha256sum", "xvfb-run", "callgrind_annotate",
            "c++filt", "objdump", "llvm-objdump", "nm", "llvm-nm", "file"}
PATH_PREFIXES = ("build/", "scripts/", "bench/", "tools/", "./")
# Tools and where the build puts them: a command names them by that path.
TOOLS = {
    "minrt": "build/release/host/minrt",
    "host-send": "build/release/host/send/host-send",
    "firmware-sim": "build/release/firmware_sim/firmware-sim",
    "image-compare": "build/release/host/image-compare",
    "fault-relay": "build/release/tools/fault_relay/fault-relay",
    "accuracy-report": "build/release/tools/accuracy/accuracy-report",
    "shim-ulp-table": "build/release/tools/shim_ulp/shim-ulp-table",
}
RETIRED_BUILD = re.compile(r"\bbuild-(fw|shims|sim|acc|hs|rel|release|debug)\b|\bbuild/firmware\b")
REPO_PATH = re.compile(r"^(\.\./shared|build/release|sld|scripts|bench|tools|docs|firmware_sim|runtime|"
                       r"host|core|formats|render|protocol|include|test|cmake)/[^\s'\"`]*$")
# Paths in inline code that are checked too: the ones a reader types.
INLINE_PATH = re.compile(r"^(\.\./shared|build/release|sld|scripts|bench|tools)/\S*$")
# Folders a benchmark writes (they exist once it ran).
WRITTEN_LATER = {"build/release/bench-firmware/"}
OUTPUT_OPTIONS = {"-o", "--output", "--uart-out", "--profile-out", "--folded-out", "--out", "--sheet", ">"}
# Commands that are not run, with the reason. Their paths are still checked.
SKIP = [
    (r"^scripts/(render|test|setup)\.sh\b", "sets up and builds: the README's commands, run before this test"),
    (r"^scripts/fuzz\.sh\b", "fuzzing runs for minutes"),
    (r"^scripts/cs418_report\.sh\b", "regenerates docs/cs418 (minutes)"),
    (r"^cmake (--preset|--build|-S)\b", "configures or builds: the build is done before this test"),
    (r"^cmake --install\b", "installs outside the checkout (ctest install.tree_and_man_pages installs into the build)"),
    (r"^ctest\b", "runs the test suite this test belongs to"),
    (r"^bench/", "a benchmark (minutes; results are in docs/)"),
    (r"\bqemu-system-riscv32\b", "QEMU comparison, not part of the build"),
    (r"/dev/tty", "needs a board on a serial port"),
    (r"/dev/pts/", "names a pseudo-terminal another tool prints when it starts"),
    (r"--port usb:", "needs a board on a serial port"),
    (r"shim-ulp-table", "takes a minute or more per table"),
    (r"&\s*(#.*)?$", "starts a background job whose pseudo-terminal name differs every run"),
    (r"\bvalgrind\b", "profiling runs take minutes"),
    (r"^gdb-multiarch\b.*target remote", "connects to the stub the line before starts in the background "
     "(ctest's GDB test runs the same session)"),
    (r"#.*\bin a window\b", "opens a window and waits for the user to close it"),
]
PLACEHOLDER = re.compile(r"\[[^\]]*\]|(?<![\w$=/.-])[A-Z][A-Z0-9_]*[A-Z](?:/[A-Z0-9_]+)*(?![\w=])|\w\|\w")


class Command:
    def __init__(self, doc, line, text, block, shell):
        self.doc, self.line, self.text, self.block, self.shell = doc, line, text, block, shell

    def where(self):
        return f"{self.doc}:{self.line}"


# One leading "NAME=value": the value may be a $(command) or quoted, with spaces.
ASSIGNMENT = re.compile(r"""[A-Za-z_][A-Za-z0-9_]*=(?:\$\([^()]*\)|"[^"]*"|'[^']*'|[^\s'"]*)(?:\s+|$)""")


def strip_assignments(text):
    """The command after its leading variable assignments ("" for assignments only)."""
    rest = text.strip()
    while (m := ASSIGNMENT.match(rest)):
        rest = rest[m.end():]
    return rest


def first_word(text):
    words = strip_assignments(text).split()
    return words[0] if words else ""


def is_command(text):
    w = first_word(text)
    if not w and re.match(r"^[A-Za-z_][A-Za-z0-9_]*=", text.strip()):
        return True  # a variable assignment the next lines use
    return (w.startswith(PATH_PREFIXES) or w in PROGRAMS or w in TOOLS or w.startswith("$")
            or w.startswith("build/"))


def join_continuations(lines):
    """[(line number, text)] with backslash continuations joined."""
    out, pending, start = [], "", None
    for n, text in lines:
        if start is None:
            start = n
        if text.rstrip().endswith("\\"):
            pending += text.rstrip()[:-1] + " "
            continue
        out.append((start, pending + text))
        pending, start = "", None
    if pending:
        out.append((start, pending))
    return out


def extract(doc, text):
    """Commands of one Markdown document, and its inline code spans."""
    lines = text.split("\n")
    blocks = []  # (shell-tagged, [(line number, text)])
    i, prev_blank, in_list = 0, True, False
    while i < len(lines):
        line = lines[i]
        m = re.match(r"^(\s*)(```+|~~~+)\s*(\S*)", line)
        if m:
            fence, lang, body = m.group(2), m.group(3).lower(), []
            i += 1
            while i < len(lines) and not lines[i].strip().startswith(fence):
                body.append((i + 1, lines[i][len(m.group(1)):]))
                i += 1
            blocks.append((lang in FENCE_LANGS_SHELL, lang, body))
            i += 1
            prev_blank = False
            continue
        if re.match(r"^\s*([-*+]|\d+\.)\s", line):
            in_list = True
        elif line.strip() and not line.startswith(" "):
            in_list = False
        if line.startswith("    ") and prev_blank and not in_list:
            body = []
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                body.append((i + 1, lines[i][4:]))
                i += 1
            blocks.append((False, "", body))
            prev_blank = True
            continue
        prev_blank = not line.strip()
        i += 1
    commands = []
    for b, (shell, lang, body) in enumerate(blocks):
        if lang and not shell:
            continue  # python, text, ...: not commands
        for n, t in join_continuations(body):
            s = t.strip()
            if not s or s.startswith("#"):
                continue
            if s.startswith("$ "):
                s = s[2:]
            if shell or is_command(s):
                commands.append(Command(doc, n, s, b, shell))
    spans = []
    for n, line in enumerate(lines, 1):
        for span in re.findall(r"`([^`]+)`", line):
            spans.append((n, span))
    return commands, spans


def words_of(text):
    try:
        return shlex.split(text, comments=True)
    except ValueError:
        return text.split()


def is_synopsis(text):
    body = text.split(" #", 1)[0]
    return bool(PLACEHOLDER.search(body))


def check_paths(cmd, words, root, problems):
    out_next = False
    for w in words:
        if w in OUTPUT_OPTIONS:
            out_next = True
            continue
        w2 = w.split("=", 1)[1] if w.startswith("--") and "=" in w else w
        w2 = w2.rstrip(";")
        if REPO_PATH.match(w2) and not re.search(r"[$*?]", w2) and not PLACEHOLDER.search(w2):
            target = os.path.join(root, w2)
            if out_next:
                folder = os.path.dirname(target) or root
                if not os.path.isdir(folder):
                    problems.append(f"{cmd.where()}: output folder of {w2} does not exist: {cmd.text}")
            elif not os.path.exists(target):
                problems.append(f"{cmd.where()}: {w2} does not exist: {cmd.text}")
        out_next = False


def tracked_entries(root):
    """The root's entries that git tracks: files a user's earlier commands left
    there (the README's contest.ppm) stay out of the scratch copy. Every entry
    when the root is not a git checkout."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return set(os.listdir(root))
    return {p.split("/", 1)[0] for p in out.decode().split("\0") if p}


def make_scratch(root, build, shared):
    scratch = tempfile.mkdtemp(prefix="doc-commands-")
    top = os.path.join(scratch, "root")
    os.makedirs(os.path.join(top, "build"))
    tracked = tracked_entries(root)
    for name in os.listdir(root):
        if name in ("build", ".git") or name not in tracked:
            continue
        if name == "docs":  # a copy: commands that redraw a picture of docs/ leave the checkout alone
            shutil.copytree(os.path.join(root, name), os.path.join(top, name), symlinks=True)
        else:
            os.symlink(os.path.join(root, name), os.path.join(top, name))
    os.symlink(os.path.abspath(build), os.path.join(top, "build", "release"))
    os.symlink(os.path.abspath(shared), os.path.join(scratch, "shared"))
    return scratch, top


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--shared", required=True)
    ap.add_argument("--no-run", action="store_true", help="check names and paths only")
    ap.add_argument("--timeout", type=float, default=180)
    ap.add_argument("--verbose", action="store_true", help="say why each command not run is not run")
    ap.add_argument("docs", nargs="*")
    args = ap.parse_args()
    root = os.path.abspath(args.root)
    docs = args.docs or [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    scratch, top = make_scratch(root, args.build, args.shared)
    problems, ran, skipped, synopses = [], 0, 0, 0
    try:
        for doc in docs:
            rel = os.path.relpath(doc, root)
            text = open(doc, encoding="utf-8").read()
            for m in RETIRED_BUILD.finditer(text):
                n = text.count("\n", 0, m.start()) + 1
                problems.append(f"{rel}:{n}: '{m.group(0)}' is a build folder no script creates; "
                                "the build is build/release")
            commands, spans = extract(rel, text)
            for n, span in spans:
                for w in words_of(span):
                    w = w.rstrip(".,;:)")
                    if (INLINE_PATH.match(w) and not re.search(r"[*?<>$]", w) and not PLACEHOLDER.search(w)
                            and w not in WRITTEN_LATER and not os.path.exists(os.path.join(top, w))):
                        problems.append(f"{rel}:{n}: {w} (inline code) does not exist")
            assignments = {}
            # An unmarked block with a placeholder is a usage synopsis as a whole.
            synopsis_blocks = {c.block for c in commands if not c.shell and is_synopsis(c.text)}
            for cmd in commands:
                words = words_of(cmd.text)
                synopsis = is_synopsis(cmd.text) or cmd.block in synopsis_blocks
                tool = first_word(cmd.text)
                check_paths(cmd, words, top, problems)
                if tool in TOOLS and not synopsis:
                    problems.append(f"{cmd.where()}: '{tool}' is not on the PATH after the build; "
                                    f"write {TOOLS[tool]}: {cmd.text}")
                    continue
                if not first_word(cmd.text):
                    assignments.setdefault(cmd.block, []).append(cmd.text)
                    continue
                if synopsis:
                    synopses += 1
                    continue
                # "VAR=value bench/..." is skipped as "bench/..." is.
                bare = strip_assignments(cmd.text)
                reason = next((why for pattern, why in SKIP
                               if re.search(pattern, cmd.text) or re.search(pattern, bare)), None)
                if reason or args.no_run:
                    skipped += 1
                    if args.verbose:
                        print(f"not run {cmd.where()}: {reason or '--no-run'}: {cmd.text}")
                    continue
                script = "\n".join(assignments.get(cmd.block, []) + [cmd.text])
                stated = re.search(r"#.*\bexit status (\d+)", cmd.text)
                expected = int(stated.group(1)) if stated else 0
                t0 = time.time()
                try:
                    r = subprocess.run(["sh", "-c", script], cwd=top, capture_output=True, text=True,
                                       timeout=args.timeout, stdin=subprocess.DEVNULL)
                    status, err = r.returncode, r.stderr.strip().splitlines()[-3:]
                except subprocess.TimeoutExpired:
                    status, err = "timeout", []
                ran += 1
                print(f"ran {cmd.where()} in {time.time() - t0:.1f} s: status {status}: {cmd.text}")
                if status != expected:
                    problems.append(f"{cmd.where()}: exits {status}, not {expected}: {cmd.text}" +
                                    "".join("\n    " + e for e in err))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    for p in problems:
        print("FAIL " + p)
    print(f"check_doc_commands: {len(docs)} documents, {ran} commands run, {skipped} not run "
          f"(slow, hardware or build), {synopses} synopses, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
