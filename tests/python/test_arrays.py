"""The scalar-or-array convention: any shape in, the same shape out, the scalar path's values."""
import threading
import time

import numpy as np
import pytest

import wavecontact as wc

W = wc.WavinessParams(H1=1, b1=10, m=2, E=1)


def evaluators():
    two_scale = wc.TwoScaleContact(
        wc.TwoScaleParams(wc.WavinessParams(H1=1, b1=10, m=0, E=1), wc.RoughnessParams(H2=0.001, n=16)), 0.9)
    profile = wc.Profile("two_harmonic", b1=10, E=1, H1=1, H3=-0.05)
    surface = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=0, E=1), [wc.Harmonic(H=0.15, n=8)])
    contact = wc.solve_contact(surface, 0.3 * np.pi)
    return {
        "pressure": lambda x: wc.pressure(W, 4.0, x),
        "pressure beyond b1/2": lambda x: wc.pressure(W, 6.0, x),
        "wave_curve": lambda x: wc.wave_curve(W, x),
        "TwoScaleContact.pressure": two_scale.pressure,
        "TwoScaleContact.roughness_pressure": two_scale.roughness_pressure,
        "TwoScaleContact.waviness_pressure": two_scale.waviness_pressure,
        "Profile.pressure": lambda x: profile.pressure(3.0, x),
        "Surface.height": surface.height,
        "Contact.pressure": contact.pressure,
        "Contact.gap": contact.gap,
    }


@pytest.mark.parametrize("name", list(evaluators()))
def test_array_equals_scalar_path(name):
    f = evaluators()[name]
    x = np.linspace(-0.85, 0.85, 35).reshape(5, 7)
    got = f(x)
    assert isinstance(got, np.ndarray) and got.shape == (5, 7) and got.dtype == np.float64
    expected = np.array([[f(float(v)) for v in row] for row in x])
    assert isinstance(f(0.5), float)
    # The array kernels sum the same closed forms in another order: within a few ulp.
    np.testing.assert_allclose(got, expected, rtol=0, atol=8 * np.finfo(float).eps * np.abs(expected).max())


def test_inputs_numpy_reads_as_numbers():
    x = np.linspace(-3, 3, 13)
    base = wc.pressure(W, 4.0, x)
    assert np.array_equal(wc.pressure(W, 4.0, list(x)), base)
    assert np.array_equal(wc.pressure(W, 4.0, x.astype(np.float32).astype(np.float64)),
                          wc.pressure(W, 4.0, x.astype(np.float32)))
    assert np.array_equal(wc.pressure(W, 4.0, np.arange(-3, 4)), wc.pressure(W, 4.0, np.arange(-3.0, 4.0)))
    strided = np.linspace(-3, 3, 26)[::2]
    assert np.array_equal(wc.pressure(W, 4.0, strided), wc.pressure(W, 4.0, np.ascontiguousarray(strided)))
    assert wc.pressure(W, 4.0, np.float64(1.0)) == wc.pressure(W, 4.0, 1.0)
    assert isinstance(wc.pressure(W, 4.0, np.int64(1)), float)
    assert wc.pressure(W, 4.0, np.int64(1)) == wc.pressure(W, 4.0, 1.0)
    assert wc.pressure(W, 4.0, np.empty(0)).shape == (0,)
    assert wc.pressure(W, 4.0, np.array(1.0)).shape == ()


def test_array_kernel_releases_the_gil():
    # While one call evaluates 4e6 points (tens of milliseconds), another thread keeps running
    # Python; it could not if the kernel held the GIL (it would tick at most once, at the switch).
    x = np.linspace(-4, 4, 4_000_000)
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.0002)

    counter = threading.Thread(target=count)
    counter.start()
    time.sleep(0.01)
    start = time.perf_counter()
    wc.pressure(W, 4.0, x)
    end = time.perf_counter()
    done.set()
    counter.join()
    during = sum(start < t < end for t in ticks)
    assert during >= 3, f"the other thread ran {during} times in {end - start:.4f} s of kernel"


def test_one_load_or_many():
    surface = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=10, E=1))
    one = wc.solve_contact(surface, 6)
    assert isinstance(one, wc.Contact)
    assert isinstance(wc.solve_contact(surface, np.float64(6.0)), wc.Contact)
    assert isinstance(wc.solve_contact(surface, np.int64(6)), wc.Contact)
    many = wc.solve_contact(surface, np.array([6.0, 2.0]))
    assert [c.load for c in many] == [6.0, 2.0]
    # Another continuation path to the same contact: the same within the tolerance (1e-10).
    assert abs(many[0].pressure(0.0) - one.pressure(0.0)) <= 1e-10 * one.max_pressure
