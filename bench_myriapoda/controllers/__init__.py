"""Controllers: Miller's muscle waves (worm, snake, sidewinder, caterpillar)."""
from . import muscle_waves  # noqa: F401  (registers the gaits)
from . import myriapod  # noqa: F401,E402  (registers the leg-wave gait)
