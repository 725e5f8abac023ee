"""Writing the accuracy report's files as the C++ tools do (posix/output_file.hpp):
the bytes go to a unique temporary file in the target's folder, which is synced
and renamed over the target only when complete, and only onto a regular file
or a new name. SIGTERM and SIGHUP end the program through SystemExit (like
Ctrl-C through KeyboardInterrupt), so the temporary file is removed."""
import io
import os
import signal
import stat
import sys
import tempfile


class OutputError(Exception):
    pass


def _exit_on_signal(signum, _frame):
    sys.exit(128 + signum)


def install_signal_handlers():
    """SIGTERM and SIGHUP unwind like Ctrl-C, so no temporary file stays."""
    for sig in (signal.SIGTERM, signal.SIGHUP):
        if signal.getsignal(sig) == signal.SIG_DFL:
            signal.signal(sig, _exit_on_signal)


def write_atomically(path, data):
    """Writes `data` (bytes or str) to `path` whole or not at all; refuses a
    FIFO, device, socket or symbolic link (OutputError)."""
    if isinstance(data, str):
        data = data.encode()
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        mode = None
    if mode is not None and not stat.S_ISREG(mode):
        kind = ("a symbolic link" if stat.S_ISLNK(mode) else "a FIFO" if stat.S_ISFIFO(mode)
                else "a directory" if stat.S_ISDIR(mode) else "not a regular file")
        raise OutputError(f"refusing to replace {path}: it is {kind}")
    folder = os.path.dirname(path) or "."
    fd, temp = tempfile.mkstemp(prefix=os.path.basename(path) + ".partial.", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temp, 0o666 & ~umask)
        os.replace(temp, path)
    except BaseException:
        if os.path.exists(temp):
            os.unlink(temp)
        raise


def save_figure(fig, path, **options):
    """matplotlib's savefig through write_atomically (PNG)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", **options)
    write_atomically(path, buf.getvalue())
