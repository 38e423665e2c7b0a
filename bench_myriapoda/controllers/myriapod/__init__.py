"""The myriapod leg controller of Fang, Jiang & Terzopoulos (2013), Sec. 4:
a Targeter per rigid segment (``targeter``) and a Switcher per leg (``switcher``).
Leg kinematics and IK live in ``bench_myriapoda.bodies.legs``."""
from . import switcher, targeter  # noqa: F401

from ...core.registry import GaitSpec, register_gait  # noqa: E402

register_gait(GaitSpec(name="leg-wave", description="myriapod legs: decentralized Switchers and Targeters whose "
                       "leg wave emerges from local rules (Fang et al. 2013, Sec. 4)", requires=frozenset({"legs"})))
