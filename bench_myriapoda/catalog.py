"""The explicit table of body models and gaits, by the names used on the command line and in files.

Adding a body backend or a gait is one entry here (README, "Extending";
docs/development/body-backends.md): a body backend declares everything the suite asks of it in one
``core.specs.BodySpec`` in its own subpackage (``bodies/<name>/body.py``), and its row here
points at that record.  Nothing registers itself as a side effect of being imported, so importing a
body never imports a controller, and neither imports this table.

A researcher's own tables (a module with ``BODIES`` and/or ``GAITS`` of the same form) are named in
``BENCH_MYRIAPODA_PLUGINS`` and read after this one (``core.registry``).
"""
from __future__ import annotations

from .bodies.fem.body import BACKEND as FEM
from .bodies.hybrid.body import BACKEND as HYBRID
from .bodies.massspring.body import BACKEND as MASSSPRING
from .controllers.muscle_waves import GAIT_DESCRIPTIONS, MuscleWaveConfig, MuscleWaveController, PassiveController
from .controllers.myriapod.controller import MyriapodController
from .core.protocols import LEGS, MUSCLES, SEGMENTS
from .core.specs import BodySpec, GaitSpec

BODIES: dict[str, BodySpec] = {spec.name: spec for spec in (MASSSPRING, FEM, HYBRID)}

GAITS: dict[str, GaitSpec] = {
    **{name: GaitSpec(name=name, description=desc, requires=frozenset({MUSCLES}), controller=MuscleWaveController,
                     config_cls=MuscleWaveConfig)
       for name, desc in GAIT_DESCRIPTIONS.items()},
    "passive": GaitSpec(name="passive", description="no actuation: the body only falls, hangs and collides",
                        requires=frozenset(), controller=PassiveController),
    "leg-wave": GaitSpec(name="leg-wave", description="myriapod legs: decentralized Switchers and Targeters whose "
                         "leg wave emerges from local rules (Fang et al. 2013, Sec. 4)",
                         requires=frozenset({LEGS, SEGMENTS}), controller=MyriapodController, takes_world=True),
}

