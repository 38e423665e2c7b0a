"""The command's exit codes: 0 done, 1 a result that failed (a FAIL, a regression, an error row, a file not
written after the run), 2 bad input (one line, nothing written), and what a shell reports for a signal."""

EXIT_OK, EXIT_FAIL, EXIT_BAD_INPUT = 0, 1, 2
EXIT_CLOSED_PIPE = 128 + 13  # what a shell reports for a process ended by SIGPIPE
EXIT_INTERRUPTED = 128 + 2  # Ctrl-C (SIGINT), and SIGTERM inside ``signals.sigterm_as_interrupt``
