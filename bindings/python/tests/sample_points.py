"""Points and conversions shared by the tests (not a test module)."""

import math
import random


def random_points(count, seed, radius=0.95):
    """Points uniform in the Euclidean disk of the given radius (many outside F_g)."""
    generator = random.Random(seed)
    points = []
    for _ in range(count):
        r, a = radius * math.sqrt(generator.random()), 2 * math.pi * generator.random()
        points.append((r * math.cos(a), r * math.sin(a)))
    return points


def square_points(count, seed, radius):
    """count points of the disk of the given radius, drawn in its square and
    kept when inside (radius 0.4: inside F_g for every genus)."""
    generator = random.Random(seed)
    found = []
    while len(found) < count:
        x, y = generator.uniform(-radius, radius), generator.uniform(-radius, radius)
        if math.hypot(x, y) < radius:
            found.append((x, y))
    return found


def as_list(value):
    """A NumPy array or a list of tuples as plain nested lists."""
    return value.tolist() if hasattr(value, "tolist") else [list(v) if isinstance(v, tuple) else v for v in value]
