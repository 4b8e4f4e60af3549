"""The module's surface: the stubs name exactly what it holds, everything is documented, the
version is the CMake project's."""
import ast
import inspect
import math
import os

import pytest

import wavecontact as wc


def public(obj):
    return {n for n in dir(obj) if not n.startswith("_")}


def stub_tree(source_dir):
    with open(os.path.join(source_dir, "python", "wavecontact", "__init__.pyi")) as f:
        return ast.parse(f.read())


def stub_names(body):
    names = set()
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return {n for n in names if not n.startswith("_")}


def test_version():
    assert wc.__version__ == os.environ["WAVECONTACT_VERSION"]


def test_stubs_name_exactly_the_module(source_dir):
    tree = stub_tree(source_dir)
    module_names = public(wc)
    assert stub_names(tree.body) == module_names
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(wc, node.name)
        if hasattr(cls, "__members__"):  # a pybind11 enum: its values, name and value
            members = set(cls.__members__) | {"name", "value"}
        elif issubclass(cls, BaseException):  # an exception: what it adds to BaseException
            members = public(cls) - public(BaseException)
        else:
            members = public(cls)
        assert stub_names(node.body) == members, node.name


def test_everything_is_documented():
    undocumented = [name for name in public(wc) if not (inspect.getdoc(getattr(wc, name)) or "").strip()]
    for name in public(wc):
        cls = getattr(wc, name)
        if not inspect.isclass(cls) or hasattr(cls, "__members__"):
            continue
        for member in public(cls):
            if callable(inspect.getattr_static(cls, member)) and not (inspect.getdoc(getattr(cls, member)) or "").strip():
                undocumented.append(f"{name}.{member}")
    assert not undocumented, f"no docstring: {undocumented}"
    assert "an array of any shape" in wc.pressure.__doc__


def test_profile_full_contact():
    """Full contact of H1 cos x + H3 cos 3x: P/(2 b1) + (E/2)(pi/b1)(H1 cos x + 3 H3 cos 3x)."""
    profile = wc.Profile("two_harmonic", b1=10, E=2, H1=1, H3=0.1)
    c = math.pi * 2.5 / 10
    expected = 0.4 / 20 + math.pi / 10 * (math.cos(c) + 0.3 * math.cos(3 * c))
    assert profile.full_contact_pressure(0.4, 2.5) == pytest.approx(expected, rel=1e-14)


def fields_repr(obj, fields):
    return type(obj).__name__ + "(" + ", ".join(f"{f}={getattr(obj, f)!r}" for f in fields) + ")"


def test_value_types_read_back_from_their_reprs():
    w = wc.WavinessParams(H1=1, b1=10, m=0.2, E=3.5)
    for value in (w, wc.Harmonic(H=0.15, n=8), wc.RoughnessParams(H2=0.01, n=64),
                  wc.TwoScaleParams(w, wc.RoughnessParams(H2=0.01, n=64))):
        again = eval(repr(value), vars(wc))
        assert repr(again) == repr(value)
    assert repr(wc.Harmonic(H=0.1, n=4)) == "Harmonic(H=0.1, n=4)"


def test_results_show_their_fields():
    w = wc.WavinessParams(H1=1, b1=10, m=10, E=1)
    rough = wc.Surface(w, [wc.Harmonic(H=0.15, n=8)])
    contact = wc.solve_contact(rough, 0.3 * math.pi)
    assert repr(contact) == fields_repr(contact, ["load", "zones_per_period", "full_contact", "contact_fraction",
                                                  "max_pressure", "error_estimate"])
    zone = contact.zones[0]
    assert repr(zone) == fields_repr(zone, ["x_start", "x_end", "load", "max_pressure", "x_of_max_pressure"])
    check = wc.single_zone_check(rough, 2.0)
    assert repr(check) == fields_repr(check, ["solution", "penetrates", "lowest_gap", "x_of_lowest_gap",
                                              "lowest_pressure", "x_of_lowest_pressure"])
    admissible = wc.admissibility(w, 4.0)
    assert repr(admissible) == fields_repr(admissible, ["admissible", "most_negative_x", "most_negative_pressure",
                                                        "lowest_gap", "x_of_lowest_gap"])
    curve = wc.LoadCurve(w)
    unstable = curve.unstable_ranges[0]
    assert repr(unstable) == fields_repr(unstable, ["begin", "end"])
    equilibrium = curve.equilibria(4.0)[0]
    assert repr(equilibrium) == fields_repr(equilibrium, ["a", "stable", "admissible"])
    shape = wc.most_uniform_shape(0.3)
    assert repr(shape) == fields_repr(shape, ["m", "a_over_b1", "max_over_mean", "x_of_max_over_a"])
