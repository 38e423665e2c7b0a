"""Controllers: Miller's muscle waves (worm, snake, sidewinder, caterpillar)."""
from . import muscle_waves  # noqa: F401  (registers the gaits)
