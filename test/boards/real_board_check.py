#!/usr/bin/env python3
"""A board as a builder has one: firmware-sim --real-board (no boot
arguments, running before any host connects, hosts coming and going on its
pty), then host-send -p against it with no boot arguments at all.

  real_board_check.py SIM BOARD ELF HOST_SEND MINRT SCENE WORK [--idle S]
  real_board_check.py --probe-only SIM BOARD ELF HOST_SEND

--probe-only: just step 4, host-send --probe against the board's firmware.

1. The board runs from reset and waits S seconds (default 10) for a host;
   firmware-sim reports the wait, checked to be at least S seconds.
2. Three renders in a row without reset, each with other options (size,
   P3/P6, protocol), each byte-equal to minrt --precision float --shims
   portable.
3. host-send killed while it uploads (a whitespace-padded scene, the
   simulated UART paced so the upload takes seconds), then a fourth render
   that succeeds on the same board.
4. host-send --probe names the board.
5. A "board" that answers the greeting with garbage (a baud mismatch) and one
   that never answers each give their one clear line and status 1.
"""
import os
import pty
import re
import select
import signal
import subprocess
import sys
import time


def fail(msg):
    print(f"real_board_check: FAIL: {msg}", file=sys.stderr)
    sys.exit(1)


class Board:
    """firmware-sim --real-board on a pty, its stderr collected."""

    def __init__(self, sim, board, elf, extra):
        self.proc = subprocess.Popen([sim, "--board", board, "--real-board", "--pty"] + extra + [elf],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        self.err = b""
        self.pty = None
        deadline = time.time() + 20
        while self.pty is None:
            self.read_err(deadline - time.time())
            m = re.search(rb"uart on (/dev/pts/\d+)", self.err)
            if m:
                self.pty = m.group(1).decode()
            elif time.time() > deadline or self.proc.poll() is not None:
                fail(f"firmware-sim announced no pty: {self.err.decode(errors='replace')}")

    def read_err(self, timeout):
        r, _, _ = select.select([self.proc.stderr], [], [], max(timeout, 0))
        if r:
            chunk = os.read(self.proc.stderr.fileno(), 65536)
            self.err += chunk

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.read_err(0)


def reference(minrt, scene, size, fmt, out):
    with open(out, "wb") as f:
        r = subprocess.run([minrt, "--precision", "float", "--shims", "portable", "--size", size, "--format", fmt, scene],
                           stdout=f)
    if r.returncode != 0:
        fail(f"minrt failed on {scene} at {size}")


def render(board, hs, minrt, scene, work, name, args, size, fmt):
    got = os.path.join(work, f"{name}.ppm")
    ref = os.path.join(work, f"{name}-ref.ppm")
    if os.path.exists(got):
        os.remove(got)
    r = subprocess.run([hs, "-q", "-p", board.pty] + args + ["--size", size, "--format", fmt, scene, "-o", got],
                       capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        fail(f"{name}: host-send {' '.join(args)} --size {size} --format {fmt}: status {r.returncode}: {r.stderr.strip()}")
    reference(minrt, scene, size, fmt, ref)
    if open(got, "rb").read() != open(ref, "rb").read():
        fail(f"{name}: {got} differs from minrt's {ref}")
    print(f"{name}: {' '.join(args) or 'raw'} {size} {fmt}: same bytes as minrt")


def fake_board(answer):
    """A pty whose "board" answers every byte with `answer` (None: silence)."""
    master, slave = pty.openpty()
    name = os.ttyname(slave)
    pid = os.fork()
    if pid == 0:
        os.close(slave)
        end = time.time() + 30
        while time.time() < end:
            r, _, _ = select.select([master], [], [], 0.1)
            if r:
                try:
                    data = os.read(master, 4096)
                except OSError:
                    data = b""
                if answer is not None and data:
                    os.write(master, answer)
        os._exit(0)
    return pid, master, slave, name


def expect_error(hs, name, pattern, label):
    r = subprocess.run([hs, "--probe", "-p", name], capture_output=True, text=True, timeout=60)
    line = r.stderr.strip()
    if r.returncode != 1 or not re.search(pattern, line) or "\n" in line:
        fail(f"{label}: expected one line matching {pattern!r} and status 1, got {r.returncode}: {line!r}")
    print(f"{label}: {line}")


def main():
    args = sys.argv[1:]
    if args[:1] == ["--probe-only"] and len(args) == 5:
        sim, board_file, elf, hs = args[1:]
        board_name = re.search(r"^name\s*=\s*(\S+)", open(board_file).read(), re.M).group(1)
        board = Board(sim, board_file, elf, [])
        try:
            r = subprocess.run([hs, "--probe", "-p", board.pty, "--board", board_file], capture_output=True, text=True,
                               timeout=60)
        finally:
            board.stop()
        if r.returncode != 0 or f"board: {board_name} " not in r.stdout:
            fail(f"--probe: status {r.returncode}: {r.stdout}{r.stderr}")
        print(r.stdout, end="")
        return 0
    idle = 10.0
    if "--idle" in args:
        i = args.index("--idle")
        idle = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 7:
        print(__doc__.strip().splitlines()[4].strip(), file=sys.stderr)
        print(__doc__.strip().splitlines()[5].strip(), file=sys.stderr)
        return 2
    sim, board_file, elf, hs, minrt, scene, work = args
    os.makedirs(work, exist_ok=True)
    board_name = re.search(r"^name\s*=\s*(\S+)", open(board_file).read(), re.M).group(1)

    # A paced UART (simulated 921600 baud), so an upload of a padded scene
    # takes seconds of real time and host-send can be killed inside it.
    board = Board(sim, board_file, elf, ["--baud", "921600"])
    try:
        time.sleep(idle)
        render(board, hs, minrt, scene, work, "first", [], "8x8", "p3")
        board.read_err(0.2)
        m = re.search(rb"the board waited ([0-9.]+) s for the host \(([0-9]+) cycles at ([0-9]+) Hz\)", board.err)
        if not m or float(m.group(1)) < idle - 0.5:
            fail(f"firmware-sim did not report a wait of {idle} s: {board.err.decode(errors='replace')}")
        print(f"idle: the board waited {m.group(1).decode()} s ({m.group(2).decode()} cycles at {m.group(3).decode()} Hz)")
        render(board, hs, minrt, scene, work, "second", [], "6x4", "p6")
        render(board, hs, minrt, scene, work, "third", ["--protocol", "framed"], "4x4", "p6")

        # The padded scene: the same scene with 400 KB of blanks inside.
        text = open(scene).read()
        cut = text.index("\n") + 1
        padded = os.path.join(work, "padded.sld")
        with open(padded, "w") as f:
            f.write(text[:cut] + (" " * 1023 + "\n") * 400 + text[cut:])
        killed = subprocess.Popen([hs, "--progress", "-p", board.pty, "--size", "8x8", padded, "-o",
                                   os.path.join(work, "killed.ppm")], stderr=subprocess.PIPE)
        seen = b""
        deadline = time.time() + 60
        while b"sending the scene" not in seen:
            r, _, _ = select.select([killed.stderr], [], [], 1)
            if r:
                seen += os.read(killed.stderr.fileno(), 4096)
            if time.time() > deadline or killed.poll() is not None:
                fail(f"host-send never showed the upload: {seen.decode(errors='replace')}")
        time.sleep(0.5)
        if killed.poll() is not None:
            fail("host-send ended before it could be killed mid-upload")
        killed.kill()
        killed.wait()
        print("killed: host-send killed while it sent the scene")
        render(board, hs, minrt, scene, work, "fourth", ["--protocol", "course"], "5x3", "p3")

        r = subprocess.run([hs, "--probe", "-p", board.pty], capture_output=True, text=True, timeout=60)
        if r.returncode != 0 or f"board: {board_name} " not in r.stdout:
            fail(f"--probe: status {r.returncode}: {r.stdout}{r.stderr}")
        print("probe: " + r.stdout.strip().replace("\n", " | "))
        if board.proc.poll() is not None:
            fail(f"the board stopped: {board.err.decode(errors='replace')}")
    finally:
        board.stop()

    if board_name != "qemu-virt":
        print("real_board_check: ok")
        return 0
    # What a wrong baud rate looks like: bytes that are no identity line
    # (host-send's side only: checked once, with the reference board's run).
    pid, master, slave, name = fake_board(bytes([0xf8, 0x80, 0x00, 0xe0, 0x1c, 0xfe]) * 8)
    try:
        expect_error(hs, name, r"^host-send: error: garbled answer from the board on .*baud", "wrong baud")
    finally:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        os.close(master)
        os.close(slave)
    pid, master, slave, name = fake_board(None)
    try:
        expect_error(hs, name, r"^host-send: error: no answer from the board on .*reset.*baud", "silent board")
    finally:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        os.close(master)
        os.close(slave)
    print("real_board_check: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
