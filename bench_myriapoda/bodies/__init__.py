"""Body model backends; importing this package registers them by name."""
from .fem import body as _fem  # noqa: F401
from .massspring import body as _massspring  # noqa: F401
from .hybrid import body as _hybrid  # noqa: F401
