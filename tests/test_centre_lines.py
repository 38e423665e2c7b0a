"""The guard's compiled bend (``centre_lines.ground_bend``) is the metrics' ``ground_curvature`` times a scale: the
shape tracker's waveform test and the run's shape metrics read the same curvature.  Not to the bit: numpy's arctan2
over an array may take a SIMD implementation (AVX-512 here) that differs from libm's by an ulp (measured: 3 of 48
points, relative 1.4e-16), so the comparison is at 1e-13 relative."""
import numpy as np

from bench_myriapoda.kinematics.centre_lines import ground_bend, ground_curvature


def test_the_compiled_bend_equals_the_numpy_curvature_times_the_scale():
    rng = np.random.default_rng(3)
    for n in (3, 7, 50):
        line = np.cumsum(rng.normal(size=(n, 3)), axis=0)
        line[n // 2] = line[n // 2 - 1]  # a zero-length chord: curvature 0 there, as in the numpy version
        out = np.full(n - 2, np.nan)
        ground_bend(line, 0.37, out)
        expected = 0.37 * ground_curvature(line[None])[0][0]
        np.testing.assert_allclose(out, expected, rtol=1e-13, atol=1e-15)
        # a straight line does not bend; a left turn seen from above is positive
    left = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, -1.0]])
    out = np.zeros(1)
    ground_bend(left, 1.0, out)
    assert out[0] > 0
