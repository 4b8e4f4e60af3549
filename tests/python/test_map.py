"""wavecontact.map: every point is solve_contact's on its load line, bit for bit, on this
machine's threads (test_map_dask.py: on a Dask cluster); bad grids are refused before any
work."""
import os
import subprocess
import sys

import numpy as np
import pytest

import wavecontact as wc

GRID = dict(H1=1.0, b1=10.0, E=1.0, m=[0.0, 2.0, 10.0], H2=[0.02, 0.05], n=[8, 16], pa_over_pstar=[0.1, 0.4, 1.2])


def same(a, b):
    """Equal arrays, NaN equal to NaN (beyond reach), bit for bit."""
    return np.array_equal(np.asarray(a), np.asarray(b), equal_nan=a.dtype.kind == "f")


def assert_same_result(a, b):
    for column in wc.MapResult.columns:
        assert same(a[column], b[column]), column
    for axis in ("m", "H2", "n", "P", "pa_over_pstar"):
        assert same(getattr(a, axis), getattr(b, axis)), axis
    assert a.parameters == b.parameters


def test_points_are_solve_contact_on_their_line():
    r = wc.map(**GRID)
    assert r.status.shape == (3, 2, 2, 3)
    for i, m in enumerate(GRID["m"]):
        for j, H2 in enumerate(GRID["H2"]):
            for k, n in enumerate(GRID["n"]):
                surface = wc.Surface(wc.WavinessParams(1.0, 10.0, m, 1.0), [wc.Harmonic(H2, n)])
                contacts = wc.solve_contact(surface, np.array(GRID["pa_over_pstar"]) * np.pi)
                for l, c in enumerate(contacts):
                    where = (i, j, k, l)
                    assert r.status[where] == "solved", where
                    assert r.zones[where] == c.zones_per_period, where
                    assert r.contact_fraction[where] == c.contact_fraction, where
                    assert r.p0[where] == c.pressure(0.0), where
                    assert r.max_p[where] == c.max_pressure, where
                    assert r.error_estimate[where] == c.error_estimate, where
    assert np.all(r.P == np.array(GRID["pa_over_pstar"]) * np.pi)


def test_threads_change_nothing():
    assert_same_result(wc.map(**GRID, threads=1), wc.map(**GRID, threads=3))


def test_the_wave_curve_alone():
    r = wc.map(1.0, 10.0, 1.0, m=[0.5, 3.0], P=[0.5, 2.0])
    assert r.status.shape == (2, 1, 1, 2) and np.all(r.H2 == 0) and np.all(r.n == 0)
    c = wc.solve_contact(wc.Surface(wc.WavinessParams(1.0, 10.0, 3.0, 1.0)), [0.5, 2.0])
    assert [x.contact_fraction for x in c] == list(r.contact_fraction[1, 0, 0])


def test_a_list_of_roughnesses():
    sets = [[(0.15, 6), (0.01, 64)], [(0.0375, 32)]]
    r = wc.map(1.0, 10.0, 1.0, m=[0.0, 10.0], harmonics=sets, pa_over_pstar=[0.3, 1.0])
    assert r.dims == ("m", "harmonics", "load") and r.status.shape == (2, 2, 2)
    assert r.H2 is None and r.n is None and r.harmonics == sets
    for i, m in enumerate([0.0, 10.0]):
        for j, roughness in enumerate(sets):
            surface = wc.Surface(wc.WavinessParams(1.0, 10.0, m, 1.0), [wc.Harmonic(H, n) for H, n in roughness])
            contacts = wc.solve_contact(surface, np.array([0.3, 1.0]) * np.pi)
            assert [c.contact_fraction for c in contacts] == list(r.contact_fraction[i, j]), (m, roughness)
            assert [c.zones_per_period for c in contacts] == list(r.zones[i, j]), (m, roughness)


def test_as_an_xarray_dataset():
    r = wc.map(**dict(GRID, m=[0.0, 10.0]), tolerance=1e-8)
    ds = r.to_xarray()
    assert tuple(ds.dims) == r.dims and ds.attrs == dict(H1=1.0, b1=10.0, E=1.0, tolerance=1e-8, max_seconds=60.0)
    for column in wc.MapResult.columns:
        assert ds[column].dims == r.dims and same(ds[column].values, r[column]), column
    for axis in ("m", "H2", "n", "P", "pa_over_pstar"):
        assert same(ds[axis].values, getattr(r, axis)), axis
    assert list(ds.pa_over_pstar.values) == GRID["pa_over_pstar"]
    # Selection by the axes' values, the load by pa/p*.
    point = ds.swap_dims(load="pa_over_pstar").sel(m=10.0, H2=0.05, n=16, pa_over_pstar=1.2)
    assert point.contact_fraction.item() == r.contact_fraction[1, 1, 1, 2]
    assert point.status.item() == r.status[1, 1, 1, 2]


def test_roughness_lists_as_xarray_coordinates():
    sets = [[(0.15, 6), (0.01, 64)], [(0.0375, 32)]]
    r = wc.map(1.0, 10.0, 1.0, harmonics=sets, pa_over_pstar=[0.3], tolerance=1e-8)
    ds = r.to_xarray()
    assert list(ds.harmonics.values) == ["0.15:6+0.01:64", "0.0375:32"] and "H2" not in ds.coords
    assert ds.zones.sel(harmonics="0.0375:32").values.tolist() == r.zones[:, 1].tolist()


def test_the_cli_file_read_as_docs_maps_says(tmp_path):
    # docs/maps.md, *The file*: the CSV of `wavecontact map` into pandas and xarray; every
    # value the same as wavecontact.map's on the same grid (17 digits round-trip a double, and
    # pandas reads them back exactly with float_precision="round_trip"; its default parser
    # was 1 ulp off in 14 of these 24 contact fractions).
    import pandas  # Debian: python3-pandas, with python3-xarray
    out = tmp_path / "map.csv"
    subprocess.run([os.environ["WAVECONTACT_CLI"], "map", "--H1", "1", "--b1", "10", "--E", "1", "--m", "0,10",
                    "--H2", "0.02,0.05", "--n", "8,16", "--pa-over-pstar", "0.1,0.4,1.2", "--tolerance", "1e-8",
                    "--out", str(out)], check=True, capture_output=True)
    table = pandas.read_csv(out, skiprows=3, float_precision="round_trip")
    ds = table.set_index(["m", "H2", "n", "pa_over_pstar"]).to_xarray()
    r = wc.map(**dict(GRID, m=[0.0, 10.0]), tolerance=1e-8).to_xarray().swap_dims(load="pa_over_pstar")
    for column in ("zones", "contact_fraction", "p0", "max_p", "error_estimate", "P"):
        assert same(ds[column].values, r[column].broadcast_like(r.p0).values), column
    assert (ds.status.values == r.status.values).all()


def test_xarray_missing_is_named(monkeypatch):
    r = wc.map(1.0, 10.0, 1.0, P=[1.0])
    monkeypatch.setitem(sys.modules, "xarray", None)  # import xarray now raises ImportError
    with pytest.raises(ImportError, match="to_xarray: needs xarray.*python3-xarray"):
        r.to_xarray()


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(pa_over_pstar=[0.5, 0.1]), "ascending"),
        (dict(pa_over_pstar=[]), "non-empty"),
        (dict(n=[7]), "n = 7"),
        (dict(H2=None), "H2 and n go together"),
        (dict(P=[1.0]), "exactly one of pa_over_pstar, P"),
        (dict(m=[-1.0]), "m = -1"),
        (dict(H2=None, n=None, harmonics=[[(0.1, 0)]]), "n = 0"),
        (dict(H2=None, n=None, harmonics=[[]]), "at least one harmonic"),
        (dict(H2=None, n=None, harmonics=[]), "at least one roughness"),
        (dict(H2=None, n=None, harmonics=[[0.1]]), "pairs"),
        (dict(harmonics=[[(0.1, 8)]]), "either H2 and n or harmonics"),
    ],
)
def test_bad_grids_are_refused(change, message):
    with pytest.raises(ValueError, match=message):
        wc.map(**dict(GRID, **change))


