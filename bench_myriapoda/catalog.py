"""The explicit table of body models and gaits, by the names used on the command line and in files.

Adding a body backend or a gait is one entry here (README, "Extending"): nothing registers itself
as a side effect of being imported, so importing a body never imports a controller, and neither
imports this table.
"""
from __future__ import annotations

from .bodies.fem.body import FEMConfig, default_dt as fem_default_dt, make_fem
from .bodies.hybrid.body import HybridConfig, default_dt as hybrid_default_dt, make_hybrid
from .bodies.massspring.body import MassSpringConfig, default_dt as massspring_default_dt, make_massspring
from .controllers.muscle_waves import GAIT_DESCRIPTIONS, MuscleWaveController, PassiveController
from .controllers.myriapod.controller import MyriapodController
from .core.protocols import LEGS, MUSCLES, SEGMENTS
from .core.specs import BodySpec, GaitSpec

FRICTION_ALL = frozenset({"friction:miller", "friction:coulomb", "friction:stick"})

BODIES: dict[str, BodySpec] = {
    "massspring": BodySpec(
        name="massspring",
        description="Miller 1988: cube lattice of point masses, edge and face-diagonal springs, directional friction",
        config_cls=MassSpringConfig, factory=make_massspring, default_dt=massspring_default_dt,
        capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_ALL),
    "fem": BodySpec(
        name="fem",
        description="Fang et al. 2013 App. A: every segment a fixed-corotational tetrahedral FEM block; "
                    "muscles as active strain",
        config_cls=FEMConfig, factory=make_fem, default_dt=fem_default_dt,
        capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_ALL),
    "hybrid": BodySpec(
        name="hybrid",
        description="Fang et al. 2013 Sec. 3: rigid box segments joined by fixed-corotational FEM links, staggered "
                    "coupling; muscles as active strain of the links",
        config_cls=HybridConfig, factory=make_hybrid, default_dt=hybrid_default_dt,
        capabilities=frozenset({MUSCLES, SEGMENTS, LEGS}) | FRICTION_ALL),
}

GAITS: dict[str, GaitSpec] = {
    **{name: GaitSpec(name=name, description=desc, requires=frozenset({MUSCLES}), controller=MuscleWaveController)
       for name, desc in GAIT_DESCRIPTIONS.items()},
    "passive": GaitSpec(name="passive", description="no actuation: the body only falls, hangs and collides",
                        requires=frozenset(), controller=PassiveController),
    "leg-wave": GaitSpec(name="leg-wave", description="myriapod legs: decentralized Switchers and Targeters whose "
                         "leg wave emerges from local rules (Fang et al. 2013, Sec. 4)",
                         requires=frozenset({LEGS, SEGMENTS}), controller=MyriapodController),
}
