"""Analytic and kinematic references the simulated bodies are checked against.

Modules here never import ``bodies/`` or ``controllers/``: a reference must not share code with
what it checks.  ``slithering``: Hu et al. (2009) resistive-friction model of lateral
undulation.  ``miller_images``: Miller's (1988) Images 1 to 4 as measurable checks.
"""
