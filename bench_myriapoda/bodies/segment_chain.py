"""The layout shared by bodies of rigid segments joined by deformable links.

The hybrid body (FEM links) and the legged mass-spring body (spring-cube links)
lay a creature out the same way: ``n_rigid`` boxes along -x from the head, one
link between each pair of neighbours.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SegmentChainLayout:
    """Resolved sizes [m] of a chain of rigid segments and links.

    ``cells``: how a link is discretized -- (nx, ny, nz) cells for an FEM link,
    or the number of spring cubes along a spring link.
    """

    n_rigid: int
    rigid_length: float
    rigid_width: float
    rigid_height: float
    link_length: float
    link_width: float
    link_height: float
    cells: tuple | int

    @property
    def pitch(self) -> float:
        """Distance between consecutive rigid centres [m]."""
        return self.rigid_length + self.link_length

    @property
    def body_length(self) -> float:
        """Head front face to tail back face [m]."""
        return self.n_rigid * self.rigid_length + (self.n_rigid - 1) * self.link_length
