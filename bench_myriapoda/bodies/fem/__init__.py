"""Tetrahedral FEM body backend (myriapod paper, App. A): kernels, meshing, FEMSystem."""
from .mesh import box_grid, chain_grid, lame_parameters, tetrahedralize_surface
from .system import (
    DT_PAPER,
    E_PAPER,
    GAMMA_PAPER,
    NU_PAPER,
    RHO_PAPER,
    AdvanceResult,
    FEMSystem,
)

__all__ = [
    "AdvanceResult", "FEMSystem", "box_grid", "chain_grid", "lame_parameters",
    "tetrahedralize_surface", "DT_PAPER", "E_PAPER", "GAMMA_PAPER", "NU_PAPER", "RHO_PAPER",
]
