"""Invalid input is a ValueError naming the function and the parameter; nothing crashes."""
import math

import numpy as np
import pytest

import wavecontact as wc

W = wc.WavinessParams(H1=1, b1=10, m=2, E=1)
SURFACE = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=0, E=1), [wc.Harmonic(H=0.15, n=8)])


@pytest.mark.parametrize("call, message", [
    (lambda: wc.WavinessParams(H1=-1, b1=10, m=2, E=1), "H1"),
    (lambda: wc.WavinessParams(H1=1, b1=10, m=-2, E=1), "m"),
    (lambda: wc.WavinessParams(H1=1, b1=math.nan, m=2, E=1), "b1"),
    (lambda: wc.RoughnessParams(H2=0.1, n=7), "n"),
    (lambda: wc.pressure(W, -1.0, 0.0), "a = -1"),
    (lambda: wc.pressure(W, 4.0, math.inf), "x = inf"),
    (lambda: wc.pressure(W, 4.0, np.array([0.0, np.nan])), "x = nan"),
    (lambda: wc.pressure(W, 4.0, "abc"), "x must be a number or an array of numbers"),
    (lambda: wc.pressure(W, 4.0, [1.0, "a"]), "x must be a number or an array of numbers"),
    (lambda: wc.pressure(W, 4.0, [[1.0, 2.0], [3.0]]), "x must be a number or an array of numbers"),
    (lambda: wc.pressure(W, 4.0, None), "x must be a number or an array of numbers"),
    (lambda: wc.load(W, 11.0), "a = 11"),
    (lambda: wc.WavinessZone(W, 10.0), "wavecontact::WavinessZone: a = 10"),
    (lambda: wc.WavinessZone(W, 4.0).pressure(np.array([0.0, np.nan])), "WavinessZone::pressure: x = nan"),
    (lambda: wc.WavinessZone(W, 4.0).pressure("abc"), "x must be a number or an array of numbers"),
    (lambda: wc.contact_half_width(W, 1e9), "P"),
    (lambda: wc.kcoef(3), "n = 3"),
    (lambda: wc.kcoef(5000), "n = 5000"),
    (lambda: wc.Profile("no_such_profile", b1=10, E=1), "no_such_profile"),
    (lambda: wc.Profile("two_harmonic", b1=10, E=1, H1=1), "H3"),
    (lambda: wc.Profile("two_harmonic", b1=10, E=1, H1=1, H3=0.1, H7=2), "H7"),
    (lambda: wc.Profile("parametric_wave_curve", b1=10, E=1, H1=1, m=0.5).full_contact_pressure(-1.0, 0.0),
     "P = -1"),
    (lambda: wc.solve_contact(SURFACE, -1.0), "P = -1"),
    (lambda: wc.solve_contact(SURFACE, [0.3, math.nan]), "P = nan"),
    (lambda: wc.solve_contact(SURFACE, 0.3, tolerance=0.5), "tolerance"),
    (lambda: wc.solve_contact(SURFACE, 0.3, nodes_per_zone=2), "nodes_per_zone"),
    (lambda: wc.solve_contact(SURFACE, "heavy"), "P must be a number or an array of numbers"),
    (lambda: wc.single_zone_check(SURFACE, 20.0), "a = 20"),
    (lambda: wc.Surface(W, [wc.Harmonic(H=0.1, n=0)]), "n = 0"),
])
def test_value_error(call, message):
    with pytest.raises(ValueError, match=None) as error:
        call()
    assert message in str(error.value), f"message {str(error.value)!r} does not name {message!r}"


def test_a_zone_that_is_not_the_contact_is_refused():
    # The seed's Fig. 7 parameters: at a = 0.5 the neighbouring asperity penetrates (docs/mathematics.md fact 10).
    c = wc.TwoScaleContact(
        wc.TwoScaleParams(wc.WavinessParams(H1=1, b1=10, m=0, E=1), wc.RoughnessParams(H2=0.15, n=8)), 0.5)
    assert not c.admissible and c.lowest_gap < -0.03
    with pytest.raises(ValueError, match="not admissible|penetrat"):
        c.pressure(0.0)
    with pytest.raises(ValueError):
        c.pressure(np.zeros(3))


def test_wrong_types_are_type_errors_not_crashes():
    with pytest.raises(TypeError):
        wc.pressure("params", 4.0, 0.0)
    with pytest.raises(TypeError):
        wc.Surface(42)
    with pytest.raises(TypeError):
        wc.kcoef(4.5)


# Issue 28, item 9: what was taken silently or raised the wrong exception.
@pytest.mark.parametrize("call, message", [
    (lambda: wc.Form(5), "5 is not a value of this enum"),
    (lambda: wc.Isa(-1), "-1 is not a value of this enum"),
    (lambda: wc.AtomTables(2), "2 is not a value of this enum"),
    (lambda: wc.pressure(W, 4.0, np.array([1 + 2j])), "not an array of dtype complex128"),
    (lambda: wc.pressure(W, 4.0, 1j), "not complex"),
    (lambda: wc.pressure(W, 4.0, 10**400), "beyond the range of a double"),
    (lambda: wc.solve_contact(SURFACE, 10**400), "beyond the range of a double"),
    (lambda: wc.set_array_kernel_threads(10**6), "threads = 1e+06 is invalid"),
    (lambda: wc.WavinessParams(H1=1e-310, b1=10, m=2, E=1), "H1 = 1e-310 is invalid"),
    (lambda: wc.pressure(wc.WavinessParams(H1=1, b1=10, m=2, E=1), 1e-170, 0.0), "a = 1e-170 is invalid"),
])
def test_edge_inputs_are_value_errors(call, message):
    with pytest.raises(ValueError) as error:
        call()
    assert message in str(error.value), f"message {str(error.value)!r} does not name {message!r}"


def test_enum_values_still_construct():
    assert wc.Form(1) == wc.Form.paper and wc.Form(0) == wc.Form.exact
    assert wc.AtomTables(1) == wc.AtomTables.per_call and wc.AtomTables(0) == wc.AtomTables.kept


def test_gap_of_any_x_is_reduced_exactly():
    c = wc.solve_contact(wc.Surface(W), 0.3)
    far = 1e308  # = 16 + a multiple of the period 20
    assert c.gap(far) == c.gap(-4.0) and c.gap(far) > 0


def test_a_solve_beyond_its_work_budget_raises_beyond_reach():
    # Two harmonics far apart in scale: about 0.2 s of work, against a budget of a millisecond.
    rough = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=0, E=1), [wc.Harmonic(H=0.15, n=6), wc.Harmonic(H=0.01, n=64)])
    with pytest.raises(wc.BeyondReach, match=r"work budget of 0\.001 s \(max_seconds\) is spent"):
        wc.solve_contact(rough, 5.3, max_seconds=0.001)
    assert issubclass(wc.BeyondReach, RuntimeError)


def test_ctrl_c_interrupts_a_solve_within_a_second(tmp_path):
    # A child solving in a loop gets SIGINT: KeyboardInterrupt must reach it within a second
    # (the solver's checkpoint runs about every tenth of a second), not when the solve ends.
    import subprocess
    import sys
    import time
    script = tmp_path / "solve_forever.py"
    script.write_text(
        "import sys, time\n"
        "sys.path[:0] = " + repr(sys.path) + "\n"
        "import wavecontact as wc\n"
        "s = wc.Surface(wc.WavinessParams(H1=1, b1=10, m=0, E=1), [wc.Harmonic(H=0.001, n=128)])\n"
        "print('ready', flush=True)\n"
        "try:\n"
        "    while True:\n"
        "        wc.solve_contact(s, 3.14159, max_seconds=30)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', time.monotonic(), flush=True)\n")
    child = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(2)
    out, _ = child.communicate(timeout=30)
    word, when = out.split()
    assert word == "interrupted"
    assert float(when) - sent < 1.0, f"KeyboardInterrupt {float(when) - sent:.2f} s after SIGINT"
