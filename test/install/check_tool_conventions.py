#!/usr/bin/env python3
"""Checks the command-line conventions of every tool:

- `--help` exits 0, prints the usage on standard output and nothing on
  standard error;
- `--version` exits 0 and prints "TOOL VERSION" with the project's version;
- a bad option exits 2 with exactly one line "TOOL: error: ..." on standard
  error and nothing on standard output;
- tool-specific cases: host-send's short options (-p PORT, -b BAUD), output
  paths checked before any work, with the reason (strerror).

Usage: check_tool_conventions.py --bin DIR --version V [--shared DIR] [--tool PATH]... [--script PATH]...
Every executable in DIR is checked, and every --tool; each --script's --help
must answer at once, without setting up or building.
"""
import argparse
import os
import subprocess
import sys

failures = []


def run(cmd, timeout=60):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)


def expect(ok, what):
    if not ok:
        failures.append(what)


def one_error_line(r, tool, status, containing, what):
    lines = r.stderr.splitlines()
    expect(r.returncode == status, f"{what}: status {r.returncode}, expected {status}")
    expect(len(lines) == 1, f"{what}: {len(lines)} lines on stderr, expected 1: {r.stderr!r}")
    expect(r.stderr.startswith(f"{tool}: error: "), f"{what}: stderr does not start with '{tool}: error: ': {r.stderr!r}")
    for text in containing:
        expect(text in r.stderr, f"{what}: stderr lacks {text!r}: {r.stderr!r}")


def check_common(path, version):
    tool = os.path.basename(path)
    r = run([path, "--help"])
    expect(r.returncode == 0, f"{tool} --help: status {r.returncode}")
    expect(r.stdout.lower().startswith(f"usage: {tool}".lower()), f"{tool} --help: stdout does not start with the usage: {r.stdout[:80]!r}")
    expect(r.stderr == "", f"{tool} --help: wrote to stderr: {r.stderr!r}")
    expect("--version" in r.stdout, f"{tool} --help: does not list --version")
    r = run([path, "--version"])
    expect(r.returncode == 0, f"{tool} --version: status {r.returncode}")
    expect(r.stdout == f"{tool} {version}\n", f"{tool} --version: printed {r.stdout!r}, expected '{tool} {version}'")
    r = run([path, "--no-such-option"])
    if tool == "miniRT":
        # minrt under the 42 subject's name keeps the subject's form: "Error",
        # then one line, status 1.
        expect(r.returncode == 1, f"{tool} --no-such-option: status {r.returncode}, expected 1")
        lines = r.stderr.splitlines()
        expect(len(lines) == 2 and lines[0] == "Error" and "--no-such-option" in lines[1],
               f"{tool} --no-such-option: expected 'Error' and one line: {r.stderr!r}")
    else:
        one_error_line(r, tool, 2, ["--no-such-option"], f"{tool} --no-such-option")
    expect(r.stdout == "", f"{tool} --no-such-option: wrote to stdout: {r.stdout!r}")


def check_specific(tools, shared, scratch):
    scene = os.path.join(shared, "scenes", "ball.sld")
    missing = "/nonexistent-minrt-dir"
    if "host-send" in tools:
        hs = tools["host-send"]
        r = run([hs, "-b", "fast", scene])
        one_error_line(r, "host-send", 2, ["bad --baud 'fast'"], "host-send -b fast")
        r = run([hs, "-p", missing + "/tty", "-b", "9600", scene, "-o", os.path.join(scratch, "x.ppm")])
        one_error_line(r, "host-send", 1, [missing + "/tty", "No such file or directory"], "host-send -p MISSING")
        r = run([hs, "--sim", scene, "-o", missing + "/x.ppm"])
        one_error_line(r, "host-send", 2, [missing, "No such file or directory"], "host-send -o MISSING/x.ppm")
    if "minrt" in tools:
        r = run([tools["minrt"], "-o", missing + "/x.ppm", scene])
        one_error_line(r, "minrt", 2, [missing, "No such file or directory"], "minrt -o MISSING/x.ppm")
        r = run([tools["minrt"], "--size"])
        one_error_line(r, "minrt", 2, ["--size needs a value"], "minrt --size")
    if "image-compare" in tools:
        r = run([tools["image-compare"], "--sheet", missing + "/s.png", scene, scene])
        one_error_line(r, "image-compare", 2, [missing, "No such file or directory"], "image-compare --sheet MISSING")
    if "accuracy-report" in tools:
        ar = tools["accuracy-report"]
        # Checked before the six renders, once, with the reason.
        r = run([ar, "--out", missing, scene])
        one_error_line(r, "accuracy-report", 2, [missing, "No such file or directory"], "accuracy-report --out MISSING")
        plain = os.path.join(scratch, "a-file")
        open(plain, "w").close()
        r = run([ar, "--out", plain, scene])
        one_error_line(r, "accuracy-report", 2, ["Not a directory"], "accuracy-report --out FILE")
        r = run([ar, "--size", "0x3", scene])
        one_error_line(r, "accuracy-report", 2, ["bad --size '0x3'"], "accuracy-report --size 0x3")
        r = run([ar, "--out", scratch, missing + "/s.sld"])
        one_error_line(r, "accuracy-report", 2, ["No such file or directory"], "accuracy-report MISSING.sld")
    if "fault-relay" in tools:
        r = run([tools["fault-relay"], "--drop", "2", "/dev/null"])
        one_error_line(r, "fault-relay", 2, ["bad --drop '2'"], "fault-relay --drop 2")
        r = run([tools["fault-relay"], missing + "/tty"])
        one_error_line(r, "fault-relay", 1, ["No such file or directory"], "fault-relay MISSING")
    if "shim-ulp-table" in tools:
        r = run([tools["shim-ulp-table"], "--only", "tan"])
        one_error_line(r, "shim-ulp-table", 2, ["bad --only 'tan'"], "shim-ulp-table --only tan")


def check_script(path):
    """A script's --help answers at once (no set-up, no build) on standard output."""
    name = os.path.basename(path)
    try:
        r = run([path, "--help"], timeout=20)
    except subprocess.TimeoutExpired:
        failures.append(f"{name} --help: still running after 20 s (it must not set up or build)")
        return
    expect(r.returncode == 0, f"{name} --help: status {r.returncode}")
    expect(r.stdout.strip() != "", f"{name} --help: printed nothing on stdout")
    expect(r.stderr == "", f"{name} --help: wrote to stderr: {r.stderr[:200]!r}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--version", required=True)
    ap.add_argument("--shared", default="../shared")
    ap.add_argument("--tool", action="append", default=[])
    ap.add_argument("--script", action="append", default=[], help="a script whose --help is checked")
    args = ap.parse_args()
    paths = sorted(os.path.join(args.bin, n) for n in os.listdir(args.bin)
                   if os.access(os.path.join(args.bin, n), os.X_OK))
    paths += args.tool
    if len(paths) < 4:
        print(f"check_tool_conventions: only {len(paths)} tools found in {args.bin}", file=sys.stderr)
        return 1
    tools = {os.path.basename(p): p for p in paths}
    for p in paths:
        check_common(p, args.version)
    scratch = os.path.join(os.path.dirname(os.path.abspath(args.bin)), "conventions-scratch")
    os.makedirs(scratch, exist_ok=True)
    check_specific(tools, args.shared, scratch)
    for s in args.script:
        check_script(s)
    for f in failures:
        print("FAIL " + f)
    print(f"check_tool_conventions: {len(paths)} tools ({', '.join(sorted(tools))}), {len(args.script)} scripts, "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
