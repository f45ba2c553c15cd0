"""Ctrl-C during a long library call (private).

The library asks a progress callback (hdt_set_progress) at most every
INTERVAL seconds whether to go on. While a call runs, a SIGINT handler only
sets a flag; the callback, which runs Python code on the calling thread (so
that Python gets to run the handler), returns the flag and the library stops
with a valid triangulation holding the work done so far. KeyboardInterrupt is
raised once the call has returned. Off the main thread, where Python cannot
install a signal handler, the call runs as before (not interruptible).

Any signal handler may run inside the call that way, and use the
triangulation while the library is in the middle of its work: the
Triangulation marks itself busy around these calls (Triangulation._calling),
refuses every use from inside them and defers close() to their end.
"""

import contextlib
import ctypes
import signal
import threading

from ._lib import lib, progress_fn

#: Seconds between the library's questions: Ctrl-C takes effect within it.
INTERVAL = 0.05


@contextlib.contextmanager
def interruptible(handle, stop=None):
    """Makes the library calls on handle inside the block stop on SIGINT,
    and when stop() (if given) becomes true."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    interrupted = []

    def on_sigint(signum, frame):
        interrupted.append(signum)

    def ask(user, done, total):
        return 1 if interrupted or (stop is not None and stop()) else 0

    callback = progress_fn(ask)  # alive until the call has returned
    previous = signal.signal(signal.SIGINT, on_sigint)
    lib.hdt_set_progress(handle, callback, None, INTERVAL)
    try:
        yield
    finally:
        lib.hdt_set_progress(handle, progress_fn(), None, 0.0)
        signal.signal(signal.SIGINT, previous)
    if interrupted:
        raise KeyboardInterrupt
