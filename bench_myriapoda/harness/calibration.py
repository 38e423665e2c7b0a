"""What a controller learns of its body beyond ``core.protocols.body_info``: the body's measured gains.

A gait that commands a body shape (``gait.curvature_amplitude``) needs the body's strain per unit
of curvature x body length.  The body measures it itself (``bodies.curvature_calibration``, cached
on disk); this module, which may know both bodies and gaits, decides when a controller needs it
and hands the calibration the catalog's factory and the run's world.
"""
from __future__ import annotations

import dataclasses
from typing import Any

from ..bodies.curvature_calibration import lateral_gain, operating_plant, plant_response
from ..core import registry
from ..core.protocols import MUSCLES, body_info


def needs_curvature_gain(case) -> bool:
    """True when ``case``'s gait commands a curvature (and so needs the body's gain): its configuration
    class says so (``GaitConfig.commands_curvature``), so this module names no gait."""
    return case.gait.commands_curvature()


def calibrated_body_info(body, case, world) -> dict[str, Any]:
    """``body_info`` plus ``strain_per_curvature`` [-] and the body's ``shape_gain_p`` and
    ``shape_harmonic_gain_per_cycle`` [-] (``BodySpec``) when the gait commands a curvature.

    ``world``: the run's (``world.world.World``); a calibration measures its body in that world less its
    ground (``World.without_ground``, in ``bodies.curvature_calibration``), so it builds no world of its own."""
    info = body_info(body, case.dt)
    if needs_curvature_gain(case) and MUSCLES in body.capabilities:
        registry.load_all()
        spec = registry.BODIES[case.body.name]
        # the gain is a static property of the body: measure it at a step the body is stable at, so a
        # case run at a deliberately unstable dt (stable-dt searches, blow-up tests) still gets its gain
        # and blows up in its own run, where that is recorded as ``unstable``
        cal_case = dataclasses.replace(case, dt=min(case.dt, spec.default_dt(case.body)))
        info["strain_per_curvature"] = lateral_gain(spec.factory, cal_case, world)
        info["shape_gain_p"] = float(spec.shape_gain_p)
        info["shape_harmonic_gain_per_cycle"] = float(spec.shape_harmonic_gain_per_cycle)
        if identifies_the_plant(case):
            info["plant_response"] = (identified_plant(spec, case, info, world) if uses_the_plant(case)
                                      else {"status": f"not identified: the run ({case.duration:g} s) is shorter "
                                                      f"than half a gait period ({case.gait.period_s:g} s)"})
            if derives_the_integral_gain(case):
                info["operating_plant"] = identified_operating_plant(spec, case, info, world,
                                                                     info["plant_response"])
    return info


def uses_the_plant(case) -> bool:
    """True when the closed loop's run may use the identified plant: half a gait period or longer, or any run whose
    integral gain derives from it (``derives_the_integral_gain``: the gain acts from the first tick).

    The plant is the guard's (``LoopGuard.set_open_loop_harmonics``: its waveform test, which first checks once a
    whole period of the bend is in its ring) and the metrics' (``PlantMargin``).  Its identification drives the body
    for the ramp and two periods (``bodies.curvature_calibration.measure_plant_response``): 0.9, 2.1 and 5.1 CPU s
    for the default snake on the lattice, fem and hybrid bodies, where a smoke run of 0.02 s costs a few
    hundredths.  A run shorter than a period never reaches the guard's first waveform check (the ring holds a whole
    period of control ticks first); half a period keeps clear of a last tick's rounding.  So leaving the plant out
    of a shorter run changes nothing of its motion (``tests/test_shape_tracking_guard.py`` checks it bit for bit);
    it only reports no plant metrics."""
    return derives_the_integral_gain(case) or case.duration >= 0.5 * case.gait.period_s


def closes_the_shape_loop(case) -> bool:
    """True when ``case``'s gait tracks its lateral shape in closed loop (``controllers.shape_tracking``)."""
    g = case.gait
    return (getattr(g, "shape_control", "open_loop") == "closed_loop" and getattr(g, "curvature_amplitude", 0.0) > 0.0
            and not case.scenario.passive)


def identifies_the_plant(case) -> bool:
    """True when the closed loop schedules its gains from the body's measured plant (``gait.shape_guard``)."""
    return closes_the_shape_loop(case) and bool(getattr(case.gait, "shape_guard", False))


def derives_the_integral_gain(case) -> bool:
    """True when the loop's fundamental integral gain comes from the measured plant at the loop's operating
    amplitude (``gait.shape_gain_i_per_cycle`` < 0; ``controllers.shape_tracking.integral_gain_from_plant``)."""
    return float(getattr(case.gait, "shape_gain_i_per_cycle", 0.0)) < 0.0


def _open_loop(case, info):
    """The calibrated open-loop controller of ``case``'s gait, reset for its body, and the wave it drives."""
    open_case = dataclasses.replace(case, gait=dataclasses.replace(case.gait, shape_control="open_loop"))
    ctrl = registry.GAITS[case.gait.name].controller(open_case)
    ctrl.reset(open_case, info)
    return ctrl, ctrl.plant_wave(open_case)


def identified_plant(spec, case, info, world) -> dict[str, Any]:
    """The open loop's measured response on the case's own ground (``bodies.curvature_calibration.plant_response``,
    cached): the calibrated open-loop controller of the same gait drives a body of the same case, in the
    run's ``world``."""
    ctrl, wave = _open_loop(case, info)
    return plant_response(lambda c: spec.factory(c, world), case, ctrl.fill, wave)


def identified_operating_plant(spec, case, info, world, base) -> dict[str, Any]:
    """The plant at the loop's operating amplitude (``bodies.curvature_calibration.operating_plant``, cached), from
    ``base``, the feed-forward's identification (``identified_plant``)."""
    ctrl, wave = _open_loop(case, info)
    return operating_plant(lambda c: spec.factory(c, world), case, ctrl.fill, wave, base)


