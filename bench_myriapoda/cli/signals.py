"""SIGTERM ends a command as Ctrl-C does (``KeyboardInterrupt``): workers stopped, what was stored kept."""
from __future__ import annotations

import os
import signal


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
        return self

    def _raise(self, signum, frame):
        if os.getpid() != self.pid:  # a forked child inherited the handler: end as SIGTERM ends it
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            os.kill(os.getpid(), signal.SIGTERM)
            return
        self.received = True
        raise KeyboardInterrupt

    def __exit__(self, *exc):
        if self.saved is not None:
            signal.signal(signal.SIGTERM, self.saved)
        return False
