"""Hybrid body backend (myriapod paper Sec. 3): rigid box segments joined by FEM links."""
