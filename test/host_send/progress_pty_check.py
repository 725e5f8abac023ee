#!/usr/bin/env python3
"""The progress lines on a terminal (a pseudo-terminal here), and none elsewhere.

Usage: progress_pty_check.py MINRT HOST_SEND STANDIN SHARED_DIR WORK_DIR

- minrt, a render of a few seconds on a terminal: "minrt: rendering [bar] N%
  DONE/TOTAL rows ETA m:ss" redrawn in place, percentages rising, the times
  left near the real end once half is done, the line cleared at the end,
  the image the same as without a terminal; with -q, or with stderr not a
  terminal, no line at all.
- host-send against the stand-in board, paced: the wait for the first byte
  with its timeout, then "receiving [bar] N% rows ... ETA", and the
  summary; with stderr not a terminal only the summary.
Exits 1 with the reason on the first failed check.
"""
import os
import pty
import re
import select
import shutil
import subprocess
import sys
import time


def fail(msg):
    print("progress_pty_check: " + msg, file=sys.stderr)
    sys.exit(1)


def run_on_pty(argv, cwd):
    """Runs argv with stdin, stdout and stderr on a new pty; returns
    (status, [(seconds, chunk)])."""
    pid, fd = pty.fork()
    if pid == 0:
        os.chdir(cwd)
        os.execv(argv[0], argv)
    t0 = time.monotonic()
    chunks = []
    while True:
        ready, _, _ = select.select([fd], [], [], 120)
        if not ready:
            os.kill(pid, 9)
            fail("no output for 120 s from " + " ".join(argv))
        try:
            data = os.read(fd, 65536)
        except OSError:  # EIO: the other side closed
            break
        if not data:
            break
        chunks.append((time.monotonic() - t0, data.decode("utf-8", "replace")))
    _, status = os.waitpid(pid, 0)
    os.close(fd)
    return os.waitstatus_to_exitcode(status), chunks, time.monotonic() - t0


def redraws(chunks):
    """Each line drawn in place ("\\r\\033[K" TEXT) with the time it arrived."""
    out = []
    for t, text in chunks:
        for part in text.split("\r\x1b[K")[1:]:
            part = part.split("\r")[0].split("\n")[0]
            if part:
                out.append((t, part))
    return out


def eta_seconds(text):
    m = re.search(r"ETA (?:(\d+):)?(\d+):(\d\d)$", text)
    if not m:
        return None
    h = int(m.group(1) or 0)
    return h * 3600 + int(m.group(2)) * 60 + int(m.group(3))


def check_minrt(minrt, shared, work):
    scene = os.path.join(shared, "scenes", "contest.sld")
    args = [minrt, "--size", "1024x1024", "--threads", "1", "-o"]
    status, chunks, total = run_on_pty(args + ["tty.ppm", scene], work)
    if status != 0:
        fail("minrt on a terminal: status %d" % status)
    lines = [(t, s) for t, s in redraws(chunks) if s.startswith("minrt: rendering ")]
    if total > 3 and len(lines) < 3:
        fail("minrt took %.1f s on a terminal but drew %d progress lines" % (total, len(lines)))
    pattern = re.compile(r"^minrt: rendering \[[#.]{20}\] +(\d+)%  (\d+)/1024 rows  ETA (\?|[\d:]+)$")
    last_pct = -1
    for t, s in lines:
        m = pattern.match(s)
        if not m:
            fail("minrt: unexpected progress line %r" % s)
        pct = int(m.group(1))
        if pct < last_pct or pct != int(m.group(2)) * 100 // 1024:
            fail("minrt: percentage %d after %d, or not its rows: %r" % (pct, last_pct, s))
        last_pct = pct
        eta = eta_seconds(s)
        # Once half is done the time left is the rest of the run, give or
        # take half of the run and the line's own rounding.
        if pct >= 50 and eta is not None and abs(t + eta - total) > 2 + 0.5 * total:
            fail("minrt: at %.1f s of %.1f the line said %r" % (t, total, s))
    all_text = "".join(c for _, c in chunks)
    if lines and not all_text.endswith("\r\x1b[K"):
        fail("minrt: the progress line is not cleared at the end: %r" % all_text[-80:])
    # The same image on two threads (the bytes are the same for any count).
    fast = [minrt, "--size", "1024x1024", "--threads", "2", "-o"]
    plain = subprocess.run(fast + ["plain.ppm", scene], cwd=work, stderr=subprocess.PIPE)
    if plain.returncode != 0 or plain.stderr:
        fail("minrt without a terminal: status %d, stderr %r" % (plain.returncode, plain.stderr[:200]))
    with open(os.path.join(work, "tty.ppm"), "rb") as a, open(os.path.join(work, "plain.ppm"), "rb") as b:
        if a.read() != b.read():
            fail("minrt: the image differs with and without a terminal")
    status, chunks, _ = run_on_pty(fast + ["quiet.ppm", "-q", scene], work)
    if status != 0 or "".join(c for _, c in chunks):
        fail("minrt -q on a terminal: status %d, output %r" % (status, "".join(c for _, c in chunks)[:200]))
    return len(lines)


def check_host_send(host_send, standin, shared, work):
    scene = os.path.join(shared, "scenes", "ball.sld")
    # 128x128 P6 at 115200 baud: about 4 s on the line.
    args = [host_send, "--sim-binary", standin, "--sim", standin, "--baud", "115200", "--size", "128x128",
            "--format", "p6", scene, "-o"]
    status, chunks, total = run_on_pty(args + ["tty.ppm"], work)
    if status != 0:
        fail("host-send on a terminal: status %d: %r" % (status, "".join(c for _, c in chunks)[-300:]))
    lines = [s for _, s in redraws(chunks)]
    if not any(s.startswith("scene sent; waiting for the board's first byte, 120 s max (") for s in lines):
        fail("host-send: no line for the wait for the first byte: %r" % lines[:5])
    receiving = [s for s in lines if s.startswith("receiving [")]
    pattern = re.compile(r"^receiving \[[#.]{20}\] +(\d+)%  (\d+)/128 rows  [\d.]+ kB/s  ETA (\?|[\d:]+)$")
    if len(receiving) < 3:
        fail("host-send: %d receiving lines in %.1f s: %r" % (len(receiving), total, lines))
    for s in receiving:
        m = pattern.match(s)
        if not m or int(m.group(1)) != int(m.group(2)) * 100 // 128:
            fail("host-send: unexpected progress line %r" % s)
    size = os.path.getsize(os.path.join(work, "tty.ppm"))
    if "host-send: tty.ppm: %d bytes; received " % size not in "".join(c for _, c in chunks):
        fail("host-send: no summary with the file's size %d" % size)
    plain = subprocess.run(args + ["plain.ppm"], cwd=work, stderr=subprocess.PIPE, text=True)
    if plain.returncode != 0 or "\r" in plain.stderr or "\x1b" in plain.stderr or plain.stderr.count("\n") != 2:
        fail("host-send without a terminal: status %d, stderr %r" % (plain.returncode, plain.stderr))
    return len(receiving)


def main():
    if len(sys.argv) != 6:
        fail(__doc__.splitlines()[2])
    minrt, host_send, standin, shared, work = sys.argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    n = check_minrt(minrt, shared, work)
    m = check_host_send(host_send, standin, shared, work)
    shutil.rmtree(work, ignore_errors=True)
    print("progress lines: minrt %d, host-send %d" % (n, m))


main()
