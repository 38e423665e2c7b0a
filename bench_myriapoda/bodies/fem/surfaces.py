"""The FEM body's kinds of triangle surface in its scene (``bodies.scene.Scene``) and how the animations draw
them (``BodySpec.surface_kinds``): a tet mesh's boundary, and the legged chain's stiff segment blocks."""
from __future__ import annotations

from ...core.specs import SurfaceStyle

FEM_SURFACE = "fem-surface"              # the boundary of an FEM tet mesh (fem body, hybrid links)
FEM_BLOCK_SURFACE = "fem-block-surface"  # legged FEM chain: boundary faces of the stiff segment blocks

# kind -> style; both keep the dark triangle edges that show the mesh, the blocks in the rigid boxes' colour
SURFACE_KINDS = {FEM_SURFACE: SurfaceStyle("#7fb3d5"), FEM_BLOCK_SURFACE: SurfaceStyle("#b08850")}
