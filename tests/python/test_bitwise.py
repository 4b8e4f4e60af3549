"""The Python module gives the C++ runtime's values to the last bit, on both paths."""
import math
from fractions import Fraction

import numpy as np
import pytest

import wavecontact as wc

X = np.linspace(-4.5, 4.5, 257)


def same_bits(reference, key, got):
    """got equals the C++ value of key (or of key[0], key[1], ... for an array), bit for bit."""
    if np.ndim(got) == 0:
        expected = reference[key]
        assert float(got).hex() == expected.hex(), f"{key}: Python {float(got)!r}, C++ {expected!r}"
        return
    for i, value in enumerate(np.asarray(got)):
        expected = reference[f"{key}[{i}]"]
        assert float(value).hex() == expected.hex(), f"{key}[{i}]: Python {value!r}, C++ {expected!r}"


@pytest.mark.parametrize("m", [0, 2, 10])
def test_wave_curve(reference, m):
    w = wc.WavinessParams(H1=1, b1=10, m=m, E=1)
    tag = f"m{m}"
    same_bits(reference, f"{tag}.pressure_array", wc.pressure(w, 4.0, X))
    same_bits(reference, f"{tag}.pressure_paper", wc.pressure(w, 4.0, X, form=wc.Form.paper))
    same_bits(reference, f"{tag}.pressure_scalar", wc.pressure(w, 4.0, 1.25))
    same_bits(reference, f"{tag}.pressure_beyond", wc.pressure(w, 6.0, 5.5))
    same_bits(reference, f"{tag}.load", wc.load(w, 4.0))
    same_bits(reference, f"{tag}.load_slope", wc.load_slope(w, 4.0))
    same_bits(reference, f"{tag}.pa_over_pstar", wc.pa_over_pstar(w, 4.0))
    same_bits(reference, f"{tag}.half_width", wc.single_asperity_half_width(w, 1.5))
    same_bits(reference, f"{tag}.wave_curve", wc.wave_curve(w, 3.3))
    same_bits(reference, f"{tag}.maximum_load", wc.LoadCurve(w).maximum_load)


@pytest.mark.parametrize("m", [0, 2, 10])
def test_zone_gives_the_free_functions_values(m):
    w = wc.WavinessParams(H1=1, b1=10, m=m, E=1)
    zone = wc.WavinessZone(w, 4.0)
    assert zone.pressure(X).tobytes() == wc.pressure(w, 4.0, X).tobytes()
    for x in X[::8]:
        assert zone.pressure(float(x)).hex() == wc.pressure(w, 4.0, float(x)).hex(), x
    paper = wc.WavinessZone(w, 4.0, wc.Form.paper)
    assert paper.pressure(X).tobytes() == wc.pressure(w, 4.0, X, form=wc.Form.paper).tobytes()


@pytest.mark.parametrize("m", [0, 2, 10])
def test_zone_with_atoms_per_call_beyond_half_gives_the_free_functions_values(m):
    w = wc.WavinessParams(H1=1, b1=10, m=m, E=1)
    zone = wc.WavinessZone(w, 6.0, tables=wc.AtomTables.per_call)
    assert zone.tables == wc.AtomTables.per_call
    assert zone.pressure(X).tobytes() == wc.pressure(w, 6.0, X).tobytes()
    for x in X[::8]:
        assert zone.pressure(float(x)).hex() == wc.pressure(w, 6.0, float(x)).hex(), x


@pytest.mark.parametrize("m", [0, 2, 10])
def test_zone_beyond_half_is_a_function_of_x_near_the_free_functions(m):
    # Beyond b1/2 the zone reads the Cauchy atoms from tables it builds as points ask: a point
    # gives the array's bits, and both lie within the atoms' rounding of the free functions.
    w = wc.WavinessParams(H1=1, b1=10, m=m, E=1)
    points_first, array_first = wc.WavinessZone(w, 6.0), wc.WavinessZone(w, 6.0)
    points = [points_first.pressure(float(x)) for x in X]
    array = array_first.pressure(X)
    assert np.array(points).tobytes() == array.tobytes()
    scale = np.abs(array).max()
    eps = np.finfo(float).eps
    assert np.abs(array - wc.pressure(w, 6.0, X)).max() <= 16 * eps * scale
    free_points = np.array([wc.pressure(w, 6.0, float(x)) for x in X])
    assert np.abs(array - free_points).max() <= 16 * eps * scale


def test_two_scale(reference):
    params = wc.TwoScaleParams(wc.WavinessParams(H1=1, b1=10, m=0, E=1), wc.RoughnessParams(H2=0.001, n=64))
    c = wc.TwoScaleContact(params, 0.9)
    same_bits(reference, "two_scale.pressure_array", c.pressure(np.linspace(-0.9, 0.9, 101)))
    same_bits(reference, "two_scale.roughness_scalar", c.roughness_pressure(0.3))
    same_bits(reference, "two_scale.load", c.load)


def test_profile_and_shape(reference):
    profile = wc.Profile("two_harmonic", b1=10, E=1, H1=1, H3=-0.05)
    same_bits(reference, "profile.pressure", profile.pressure(3.0, 1.7))
    same_bits(reference, "profile.load", profile.load(3.0))
    same_bits(reference, "uniformity.max_over_mean", wc.pressure_uniformity(2.0, 0.3).max_over_mean)


def test_contact(reference):
    surface = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=10, E=1))
    c = wc.solve_contact(surface, 1.9 * math.pi)
    same_bits(reference, "contact.p0", c.pressure(0.0))
    same_bits(reference, "contact.fraction", c.contact_fraction)
    same_bits(reference, "contact.x_end", c.zones[0].x_end)
    same_bits(reference, "contact.gap", c.gap(5.5))
    same_bits(reference, "contact.pressure_array", c.pressure(X))
    rough = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=0, E=1), [wc.Harmonic(H=0.15, n=8)])
    sweep = wc.solve_contact(rough, [0.3, 0.6, 0.9])
    same_bits(reference, "sweep.p0", [s.pressure(0.0) for s in sweep])
    same_bits(reference, "full_contact_load", wc.full_contact_load(surface))


def test_kcoef_is_exact():
    # eq. 18: k_j = (-1)^(n-j) C(n-1+j, n-j) 2^(2j-1)/n, independently of the runtime; docs/mathematics.md's n = 8.
    assert wc.kcoef(8) == [-2, 84, -1008, 5280, -14080, 19968, -14336, 4096]
    n = 128
    expected = [Fraction((-1) ** (n - j) * math.comb(n - 1 + j, n - j) * 2 ** (2 * j - 1), n) for j in range(1, n + 1)]
    assert wc.kcoef(n) == expected
    assert sum(wc.kcoef(n)) == 2
