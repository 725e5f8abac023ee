#!/usr/bin/env python3
"""host-send against simulators and boards that lie (docs/reliability.md).

Usage: hostile_board_check.py HOST_SEND FIRMWARE_SIM SCENE WORKDIR

Each case runs host-send with a short deadline and asserts how it ends:
status, one error line, the time it took (a hang fails), and, for the
signals, that the serial port's settings are back as they were. The fake
boards are this script too (--fake MODE), started by host-send through a
small wrapper as its --sim-binary, or played here on a pty's master side.
"""
import os
import pty
import resource
import select
import signal
import subprocess
import sys
import termios
import time

EOT = 0x04


def fake_board(mode):
    """Plays a board on a new pty the way firmware-sim announces it."""
    if mode == "never-starts":
        time.sleep(60)  # says nothing, opens nothing
        return
    if mode == "floods-stderr":
        chunk = b"x" * 65536
        while True:
            os.write(2, chunk)  # never a newline, never the pty line
    master, slave = pty.openpty()
    tty = termios.tcgetattr(slave)
    tty[3] &= ~(termios.ECHO | termios.ICANON)  # the bytes as sent, no echo
    termios.tcsetattr(slave, termios.TCSANOW, tty)
    sys.stderr.write("fake-board: uart on %s\n" % os.ttyname(slave))
    sys.stderr.flush()
    # The upload: the scene and its end-of-input byte.
    while EOT not in os.read(master, 4096):
        pass
    if mode == "silent":
        while True:
            os.read(master, 4096)
    if mode == "drips":
        # A valid header, then one pixel byte well inside the idle timeout.
        os.write(master, b"P6\n16 16\n255\n")
        while True:
            os.write(master, b"\x80")
            time.sleep(0.2)
    if mode == "escapes":
        os.write(master, b"!minrt-error: 1:1: \x1b]0;owned\x07\x1b[2J\x1b[31mred\rhidden\x9b6n\n")
        time.sleep(5)


failures = []


def check(what, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + what + ("" if ok else ": " + detail))
    if not ok:
        failures.append(what)


def run(argv, timeout=30):
    t0 = time.monotonic()
    p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        p.kill()
        out, err = p.communicate()
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return p.returncode, err, time.monotonic() - t0, ru.ru_maxrss


def main():
    host_send, sim, scene, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    for f in os.listdir(work):
        os.unlink(os.path.join(work, f))
    elf = os.path.join(work, "fw.elf")
    open(elf, "wb").close()
    out = os.path.join(work, "out.ppm")

    def wrapper(mode):
        path = os.path.join(work, "board-" + mode)
        with open(path, "w") as f:
            f.write("#!/bin/sh\nexec %s %s --fake %s\n" % (sys.executable, os.path.abspath(__file__), mode))
        os.chmod(path, 0o755)
        return path

    base = [host_send, scene, "--size", "16x16", "--format", "p6", "--no-check", "--quiet", "-o", out]

    # A simulator that never announces its pty: the start-up deadline holds
    # (a blocking read after poll used to wait for good).
    st, err, secs, _ = run(base + ["--sim", elf, "--sim-binary", wrapper("never-starts"), "--sim-start-timeout", "1"])
    check("a never-starting simulator: status 1 within the start-up deadline",
          st == 1 and secs < 5 and b"did not announce its pty within" in err, "status %s, %.1f s, %r" % (st, secs, err))

    # One that floods its standard error at start-up: kept output capped.
    st, err, secs, rss = run(base + ["--sim", elf, "--sim-binary", wrapper("floods-stderr"),
                                     "--sim-start-timeout", "2"])
    check("a simulator flooding stderr at start-up: status 1 in time, memory bounded",
          st == 1 and secs < 6 and rss < 64 * 1024 and len(err) < 8192,
          "status %s, %.1f s, %d KiB, %d bytes of stderr" % (st, secs, rss, len(err)))

    # Started, then silent: the first-byte timeout.
    st, err, secs, _ = run(base + ["--sim", elf, "--sim-binary", wrapper("silent"), "--first-byte-timeout", "1"])
    check("a silent simulator: status 1 by the first-byte timeout",
          st == 1 and secs < 6 and b"first-byte timeout" in err, "status %s, %.1f s, %r" % (st, secs, err))

    # A board that drips one byte inside the idle timeout: the overall
    # reply deadline ends it.
    st, err, secs, _ = run(base + ["--sim", elf, "--sim-binary", wrapper("drips"), "--idle-timeout", "1",
                                   "--reply-timeout", "2"])
    check("a board that drips: status 1 by the reply deadline",
          st == 1 and secs < 6 and b"the reply did not end within 2 s" in err and not os.path.exists(out),
          "status %s, %.1f s, %r" % (st, secs, err))

    # A board whose error line carries escape sequences, \r and a C1 byte:
    # shown escaped, nothing raw reaches the terminal.
    st, err, secs, _ = run(base + ["--sim", elf, "--sim-binary", wrapper("escapes")])
    raw = [b for b in (b"\x1b", b"\x07", b"\r", b"\x9b") if b in err]
    check("a board's escape sequences are shown escaped",
          st == 3 and not raw and b"\\x1b]0;owned\\x07\\x1b[2J" in err and b"red\\x0dhidden" not in err
          and b"\\x9b6n" in err and err.count(b"\n") == 1, "status %s, %r" % (st, err))

    # Signals from outside during a transfer: the port's settings restored.
    # The port is a pty held here; its master plays a board that reads the
    # upload and stays silent.
    for sig in (signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2, signal.SIGALRM, signal.SIGSEGV):
        master, slave = pty.openpty()
        before = termios.tcgetattr(slave)
        p = subprocess.Popen([host_send, "--port", os.ttyname(slave), "--no-handshake", scene, "--size", "16x16", "--no-check",
                              "--quiet", "-o", out], stdin=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_CORE, (0, 0)))  # no core files
        got = b""
        deadline = time.monotonic() + 10
        while EOT not in got and time.monotonic() < deadline:
            if select.select([master], [], [], 0.1)[0]:
                got += os.read(master, 4096)
        during = termios.tcgetattr(slave)
        p.send_signal(sig)
        try:
            p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
        after = termios.tcgetattr(slave)
        name = signal.Signals(sig).name
        check("%s during a transfer: ended by it, the port's settings restored" % name,
              EOT in got and during != before and after == before and p.returncode == -sig
              and not os.path.exists(out),
              "upload seen %s, raw while sending %s, restored %s, status %s" %
              (EOT in got, during != before, after == before, p.returncode))
        os.close(master)
        os.close(slave)

    # Special files to every file option of host-send: refused at once with
    # one line (status 2 for host-send's own inputs; the simulator's --board
    # and ELF are firmware-sim's, which refuses them before starting).
    fifo = os.path.join(work, "fifo")
    os.mkfifo(fifo)
    big = os.path.join(work, "big.sld")
    with open(big, "wb") as f:
        f.truncate(1 << 30)  # sparse
    specials = {"/tmp": b"Is a directory", fifo: b"not a regular file (a FIFO)",
                "/dev/zero": b"not a regular file (a device)"}
    for path, reason in list(specials.items()) + [(big, b"larger than")]:
        st, err, secs, _ = run([host_send, path, "--sim", elf, "--sim-binary", wrapper("silent"), "-o", out])
        check("scene %s refused" % path, st == 2 and reason in err and secs < 5 and err.count(b"\n") == 1,
              "status %s, %r" % (st, err))
    for option in ("--verify", "--program"):
        for path, reason in specials.items():
            extra = ["--protocol", "course"] if option == "--program" else []
            st, err, secs, _ = run(base + extra + [option, path, "--sim", elf, "--sim-binary", wrapper("silent")])
            check("%s %s refused" % (option, path), st == 2 and reason in err and secs < 5,
                  "status %s, %r" % (st, err))
    # --sim takes the next argument as the firmware when it is named *.elf.
    as_elf = {}
    for path, reason in specials.items():
        link = os.path.join(work, os.path.basename(path) + ".elf")
        os.symlink(path, link)
        as_elf[link] = reason
    for option, paths in (("--board", specials), ("--sim", as_elf)):
        for path, reason in paths.items():
            args = [option, path] + (["--sim", elf] if option == "--board" else [])
            st, err, secs, _ = run(base + args + ["--sim-binary", sim])
            check("the simulator's %s %s refused" % (option, path),
                  st != 0 and reason in err and secs < 5 and err.count(b"\n") <= 2, "status %s, %r" % (st, err))

    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "--fake":
        fake_board(sys.argv[2])
        sys.exit(0)
    sys.exit(main())
