"""Status codes and in-loop statistics shared by every body backend's step kernel.

A kernel never raises on a blow-up: it stops and returns one of these codes,
and the runner records the run as ``unstable`` with the time of failure.
"""
OK, NONFINITE, RUNAWAY_SPEED, DEEP_PENETRATION = 0, 1, 2, 3
STATUS_TEXT = {OK: "ok", NONFINITE: "non-finite position or velocity", RUNAWAY_SPEED: "runaway speed",
               DEEP_PENETRATION: "deep penetration"}

# accumulator layout (``acc``): statistics gathered inside the step loop
ACC_CONTACT_SUM, ACC_STEPS, ACC_MAX_PEN = range(3)  # sum of contact fractions, steps, max depth [m]
N_ACC = 4
