#!/usr/bin/env python3
"""Finds a top-level X11 window by a part of its title and acts on it like a
user, through libX11 and libXtst (ctypes: no Python X library needed).

Usage: x11_window.py [--pid PID] ACTION TITLE ...
       x11_window.py wait TITLE [TIMEOUT [SINCE]]  prints the seconds until the window is
                                                    viewable, counted from SINCE (seconds
                                                    since the epoch; default: now)
       x11_window.py key TITLE [TIMEOUT]            presses and releases ESC in it (XTest)
       x11_window.py close TITLE [TIMEOUT]          clicks its close button (WM_DELETE_WINDOW)
       x11_window.py measure TITLE -- COMMAND...    starts COMMAND once connected, presses ESC
                                                    when its window is viewable, waits for it
                                                    to end; prints the seconds to viewable, the
                                                    seconds from ESC to the end, and its status
key and close print the time of the event, in seconds since the epoch.
--pid: only a window of that process (_NET_WM_PID) counts. A window of a
process that has just ended can stay viewable for a moment, until the X server
has handled the closed connection; without --pid it could be taken for the
next process's window. measure always matches its own child.
Exits 1 when no such window appears within TIMEOUT (default 5 s).
"""
import ctypes
import ctypes.util
import subprocess
import sys
import time

x11 = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
xtst = ctypes.CDLL(ctypes.util.find_library("Xtst") or "libXtst.so.6")

Window = ctypes.c_ulong
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
x11.XDefaultRootWindow.restype = Window
x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
x11.XQueryTree.argtypes = [ctypes.c_void_p, Window, ctypes.POINTER(Window), ctypes.POINTER(Window),
                           ctypes.POINTER(ctypes.POINTER(Window)), ctypes.POINTER(ctypes.c_uint)]
x11.XFetchName.argtypes = [ctypes.c_void_p, Window, ctypes.POINTER(ctypes.c_char_p)]
x11.XFree.argtypes = [ctypes.c_void_p]
x11.XInternAtom.restype = ctypes.c_ulong
x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
x11.XKeysymToKeycode.restype = ctypes.c_ubyte
x11.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
x11.XSetInputFocus.argtypes = [ctypes.c_void_p, Window, ctypes.c_int, ctypes.c_ulong]
x11.XFlush.argtypes = [ctypes.c_void_p]
x11.XSync.argtypes = [ctypes.c_void_p, ctypes.c_int]
x11.XGetWindowProperty.argtypes = [ctypes.c_void_p, Window, ctypes.c_ulong, ctypes.c_long, ctypes.c_long,
                                   ctypes.c_int, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                                   ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_ulong),
                                   ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.c_void_p)]
x11.XSendEvent.argtypes = [ctypes.c_void_p, Window, ctypes.c_int, ctypes.c_long, ctypes.c_void_p]
xtst.XTestFakeKeyEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]


# Windows come and go while the tree is walked; Xlib's default handler would
# end this script on the first BadWindow. Errors are counted instead, and an
# action whose own request failed says so.
class XErrorEvent(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("display", ctypes.c_void_p), ("resourceid", ctypes.c_ulong),
                ("serial", ctypes.c_ulong), ("error_code", ctypes.c_ubyte), ("request_code", ctypes.c_ubyte),
                ("minor_code", ctypes.c_ubyte)]


x_errors = []
ErrorHandler = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.POINTER(XErrorEvent))


@ErrorHandler
def note_x_error(display, event):
    e = event.contents
    x_errors.append((e.error_code, e.request_code, e.resourceid))
    return 0


x11.XSetErrorHandler.argtypes = [ErrorHandler]
x11.XSetErrorHandler.restype = ctypes.c_void_p


class XWindowAttributes(ctypes.Structure):
    _fields_ = [("x", ctypes.c_int), ("y", ctypes.c_int), ("width", ctypes.c_int), ("height", ctypes.c_int),
                ("border_width", ctypes.c_int), ("depth", ctypes.c_int), ("visual", ctypes.c_void_p),
                ("root", Window), ("class_", ctypes.c_int), ("bit_gravity", ctypes.c_int),
                ("win_gravity", ctypes.c_int), ("backing_store", ctypes.c_int),
                ("backing_planes", ctypes.c_ulong), ("backing_pixel", ctypes.c_ulong),
                ("save_under", ctypes.c_int), ("colormap", ctypes.c_ulong), ("map_installed", ctypes.c_int),
                ("map_state", ctypes.c_int), ("all_event_masks", ctypes.c_long),
                ("your_event_mask", ctypes.c_long), ("do_not_propagate_mask", ctypes.c_long),
                ("override_redirect", ctypes.c_int), ("screen", ctypes.c_void_p)]


x11.XGetWindowAttributes.argtypes = [ctypes.c_void_p, Window, ctypes.POINTER(XWindowAttributes)]
IS_VIEWABLE = 2


class ClientMessage(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("window", Window), ("message_type", ctypes.c_ulong),
                ("format", ctypes.c_int), ("data", ctypes.c_long * 5), ("pad", ctypes.c_long * 12)]


def window_pid(display, w):
    """The _NET_WM_PID of window w, or None."""
    atom = x11.XInternAtom(display, b"_NET_WM_PID", 1)
    if not atom:
        return None
    kind, fmt = ctypes.c_ulong(), ctypes.c_int()
    count, after = ctypes.c_ulong(), ctypes.c_ulong()
    data = ctypes.c_void_p()
    XA_CARDINAL = 6
    if x11.XGetWindowProperty(display, w, atom, 0, 1, 0, XA_CARDINAL, ctypes.byref(kind), ctypes.byref(fmt),
                              ctypes.byref(count), ctypes.byref(after), ctypes.byref(data)) != 0:
        return None
    pid = None
    if data.value:
        if fmt.value == 32 and count.value == 1:
            pid = ctypes.cast(data, ctypes.POINTER(ctypes.c_ulong))[0]
        x11.XFree(data)
    return pid


def find(display, title, pid=None):
    """The first viewable window (depth first) whose name contains title, and
    which belongs to process pid when one is given, or 0."""
    stack = [x11.XDefaultRootWindow(display)]
    while stack:
        w = stack.pop()
        name = ctypes.c_char_p()
        if x11.XFetchName(display, w, ctypes.byref(name)) and name.value is not None:
            found = title.encode() in name.value
            x11.XFree(name)
            attrs = XWindowAttributes()
            if found and x11.XGetWindowAttributes(display, w, ctypes.byref(attrs)) and \
                    attrs.map_state == IS_VIEWABLE and (pid is None or window_pid(display, w) == pid):
                return w
        root, parent = Window(), Window()
        children = ctypes.POINTER(Window)()
        count = ctypes.c_uint()
        if x11.XQueryTree(display, w, ctypes.byref(root), ctypes.byref(parent), ctypes.byref(children),
                          ctypes.byref(count)):
            stack.extend(children[i] for i in range(count.value))
            if children:
                x11.XFree(children)
    return 0


def wait_for(display, title, timeout, since, pid=None):
    start = time.monotonic()
    while time.monotonic() - start < timeout:
        w = find(display, title, pid)
        if w:
            return w, time.time() - since
        time.sleep(0.005)
    sys.exit(f"no viewable window titled '{title}' within {timeout} s")


def press_escape(display, w):
    x11.XSetInputFocus(display, w, 1, 0)  # RevertToPointerRoot, CurrentTime
    x11.XSync(display, 0)
    code = x11.XKeysymToKeycode(display, 0xff1b)  # XK_Escape
    xtst.XTestFakeKeyEvent(display, code, 1, 0)
    xtst.XTestFakeKeyEvent(display, code, 0, 0)
    x11.XFlush(display)


def main():
    pid = None
    if len(sys.argv) > 2 and sys.argv[1] == "--pid":
        pid = int(sys.argv[2])
        del sys.argv[1:3]
    if len(sys.argv) < 3 or sys.argv[1] not in ("wait", "key", "close", "measure"):
        sys.exit(__doc__)
    display = x11.XOpenDisplay(None)
    if not display:
        sys.exit("cannot open the display")
    x11.XSetErrorHandler(note_x_error)
    action, title = sys.argv[1], sys.argv[2]
    if action == "measure":
        if len(sys.argv) < 5 or sys.argv[3] != "--":
            sys.exit(__doc__)
        start = time.time()
        child = subprocess.Popen(sys.argv[4:])
        w, opened = wait_for(display, title, 30.0, start, child.pid)
        press_escape(display, w)
        pressed = time.time()
        status = child.wait(timeout=60)
        print(f"{opened:.3f} {time.time() - pressed:.3f} {status}")
        return
    timeout = float(sys.argv[3]) if len(sys.argv) > 3 else 5.0
    since = float(sys.argv[4]) if len(sys.argv) > 4 else time.time()
    w, seconds = wait_for(display, title, timeout, since, pid)
    if action == "wait":
        print(f"{seconds:.3f}")
    elif action == "key":
        press_escape(display, w)
        print(f"{time.time():.6f}")
    else:
        msg = ClientMessage()
        msg.type = 33  # ClientMessage
        msg.window = w
        msg.message_type = x11.XInternAtom(display, b"WM_PROTOCOLS", 0)
        msg.format = 32
        msg.data[0] = x11.XInternAtom(display, b"WM_DELETE_WINDOW", 0)
        x_errors.clear()
        x11.XSendEvent(display, w, 0, 0, ctypes.byref(msg))
        x11.XSync(display, 0)
        if x_errors:
            sys.exit(f"the close event for window {w:#x} failed: X error {x_errors[0]}")
        print(f"{time.time():.6f}")


if __name__ == "__main__":
    main()
