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


class AccumulatedContact:
    """The two contact figures every body reports (``core.protocols.Body``), read from the accumulators its step
    kernel fills (``self.acc``, N_ACC values in the layout above): a mixin, so a body model need not write them
    again (``tests/test_fourth_body.py``'s body takes them from here)."""

    def contact_fraction_mean(self) -> float:
        """Mean share of the body's contact points touching the ground over the steps run [-]."""
        return float(self.acc[ACC_CONTACT_SUM] / max(self.acc[ACC_STEPS], 1.0))

    def max_penetration(self) -> float:
        """Deepest penetration of a contact point into the terrain [m]."""
        return float(self.acc[ACC_MAX_PEN])
