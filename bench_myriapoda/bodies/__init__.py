"""Body model backends; importing this package registers them by name."""
from .massspring import body as _massspring  # noqa: F401
