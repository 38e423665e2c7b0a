"""SIGTERM ends a command as Ctrl-C does (``KeyboardInterrupt``): workers stopped, what was stored kept."""
from __future__ import annotations

import os
import signal
import sys
import threading
import time


class sigterm_as_interrupt:
    """Inside the block SIGTERM raises KeyboardInterrupt (as SIGINT does), so that a terminated matrix
    stops its workers, keeps what it stored and prints "interrupted"; the old handler is restored after.
    ``main`` holds it around every command: a terminated ``run`` or matrix start-up ends with 130, as
    Ctrl-C does, not -15.  A process forked inside the block (the report's figure pool) dies of SIGTERM
    as it would without the handler.

    ``received`` tells the caller that SIGTERM ended the block even when the KeyboardInterrupt did not come out as
    one: raised inside an import of a C extension (numpy's, numba's), it is turned into that import's ImportError
    ("PyCapsule_Import could not import module ...") -- a terminated ``run`` whose SIGTERM arrived while numba
    was being imported ended with that traceback and exit 1, not 130."""

    received = False  # SIGTERM arrived inside the block (whatever exception it became on its way out)

    def __enter__(self):
        self.pid = os.getpid()
        try:
            self.saved = signal.signal(signal.SIGTERM, self._raise)
        except ValueError:  # not the main thread: leave SIGTERM as it is
            self.saved = None
        self.saved_hook = sys.unraisablehook
        sys.unraisablehook = self._unraisable
        self.resending: list[threading.Thread] = []  # signals sent again (``_unraisable``), not yet delivered
        return self

    def _unraisable(self, unraisable) -> None:
        """An interrupt that landed in a finalizer (a ``__del__``, a weakref callback) is delivered again.  Python
        prints and ignores an exception raised there, so the command went on as if no signal had come: a matrix
        terminated while ``zipfile.ZipFile.__del__`` ran finished its cases and ended with 0, not 130.  The signal is
        sent again from a thread a few milliseconds later (sent from here, its handler would raise inside this hook,
        which Python ignores as well), to land in the code the finalizer interrupted; should it land in a finalizer
        again, it comes back here."""
        if isinstance(unraisable.exc_value, KeyboardInterrupt) and os.getpid() == self.pid:
            sig = signal.SIGTERM if self.received else signal.SIGINT
            resend = threading.Thread(target=_send_later, args=(self.pid, sig), daemon=True)
            resend.start()
            self.resending.append(resend)
            return
        self.saved_hook(unraisable)

    def _raise(self, signum, frame):
        if os.getpid() != self.pid:  # a forked child inherited the handler: end as SIGTERM ends it
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            os.kill(os.getpid(), signal.SIGTERM)
            return
        self.received = True
        raise KeyboardInterrupt

    def __exit__(self, *exc):
        try:
            # a signal sent again lands here, inside the block, when the block ends before it comes (a command that
            # returns within the few milliseconds): after the handlers are restored it would kill the process (-15)
            for resend in self.resending:
                resend.join(timeout=1.0)
        finally:
            if self.saved is not None:
                signal.signal(signal.SIGTERM, self.saved)
            sys.unraisablehook = self.saved_hook
        return False


def _send_later(pid: int, sig: int, delay_s: float = 0.005) -> None:
    """Send ``sig`` to ``pid`` after ``delay_s`` [s] (``sigterm_as_interrupt._unraisable``)."""
    time.sleep(delay_s)
    os.kill(pid, sig)
