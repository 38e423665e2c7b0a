"""The scalars of a body's step that come from the case alone: the contact's and the blow-up checks'.

Every body's kernel reads its scalars from a float64 vector ``phys`` at indices its own kernel module declares
(``fem.body_kernels``, ``massspring.kernels``, ``rigid_chain``, ``fem.myriapod``); ``contact_scalars`` writes
the ones every body has there, so the five bodies read them from the case the same way.
"""
from __future__ import annotations

import numpy as np


def contact_scalars(phys: np.ndarray, at: tuple[int, int, int, int], case) -> None:
    """Write into phys at the indices at = (R_N, R_T, MAX_SPEED, MAX_PEN): the collision's normal and tangential
    restitution (``case.collision``), the speed [m/s] and penetration [m] beyond which a step is a blow-up
    (``case.stability``).  Not the time step: every body's step takes dt as a plain argument (issue 42 item 2;
    tests/test_step_arguments.py fails if a body's parameter vector holds it again)."""
    i_rn, i_rt, i_speed, i_pen = at
    phys[i_rn] = case.collision.r_n
    phys[i_rt] = case.collision.r_t
    phys[i_speed] = case.stability.max_speed_m_s
    phys[i_pen] = case.stability.max_penetration_m
