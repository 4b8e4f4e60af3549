#!/usr/bin/python3
"""The Python module's overhead: the waviness pressure on 1e6 points from Python (timeit),
the same inputs as the C++ benchmark BM_waviness_pressure_generated/1000000 (m = 2, a = 4,
b1 = 10, points evenly spaced over 0.999 of the zone). Prints ns per point, the mean over the
calls after a warm-up one, as Google Benchmark reports it.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_pressure.py [repeats]
"""
import sys
import timeit

import numpy as np

import wavecontact as wc

params = wc.WavinessParams(H1=1, b1=10, m=2, E=1)
a = 4.0
wc.set_array_kernel_threads(1)  # as the C++ figure
x = np.linspace(-0.999 * a, 0.999 * a, 1_000_000)
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 20
wc.pressure(params, a, x)
mean = timeit.timeit(lambda: wc.pressure(params, a, x), number=repeats) / repeats
print(f"python_pressure_ns_per_point {mean / x.size * 1e9:.4f}")
