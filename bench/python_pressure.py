#!/usr/bin/python3
"""The Python module's call path, beside the C++ figures of the same inputs (m = 2, a = 4,
b1 = 10; bench/bench_inputs.hpp): the waviness pressure on 1e6 points (ns a point, as
BM_waviness_pressure_generated/1000000), one point (ns a call: the free function and a
WavinessZone, as BM_point_free_function/0 and BM_point_zone/0) and ten points as an array
(ns a call, as BM_ten_points_zone). Each figure is the best of `repeats` timeit runs' means,
as a latency is quoted; one line each, `name value`.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_pressure.py [repeats]
"""
import sys
import timeit

import numpy as np

import wavecontact as wc

params = wc.WavinessParams(H1=1, b1=10, m=2, E=1)
a = 4.0
zone = wc.WavinessZone(params, a)
wc.set_array_kernel_threads(1)  # as the C++ figures
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5


def best_mean(call, number):
    call()
    return min(timeit.repeat(call, number=number, repeat=repeats)) / number


many = np.linspace(-0.999 * a, 0.999 * a, 1_000_000)
ten = np.linspace(-0.999 * a, 0.999 * a, 10)
out = np.empty(10)
figures = {
    "python_pressure_ns_per_point": best_mean(lambda: wc.pressure(params, a, many), 4) / many.size,
    "python_point_free_function_ns": best_mean(lambda: wc.pressure(params, a, 1.25), 100_000),
    "python_point_zone_ns": best_mean(lambda: zone.pressure(1.25), 100_000),
    "python_ten_points_free_function_ns": best_mean(lambda: wc.pressure(params, a, ten), 100_000),
    "python_ten_points_zone_ns": best_mean(lambda: zone.pressure(ten), 100_000),
}
for name, seconds in figures.items():
    print(f"{name} {seconds * 1e9:.4f}")
