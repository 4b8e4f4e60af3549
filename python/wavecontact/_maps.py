"""Maps of shape and scale (docs/maps.md): the contact over a grid of the wave curve's shape m,
the roughness (a harmonic's height H2 and wavelength ratio n, or a list of whole roughnesses)
and the load, on this machine's cores or on a Dask cluster."""
import numpy as np

from . import _wavecontact

_STATUS = np.array(["solved", "above_tolerance", "beyond_reach"])
_LONG_NAMES = {"status": "status", "zones": "zones per period", "contact_fraction": "contact fraction",
               "p0": "pressure p(0)", "max_p": "largest pressure", "error_estimate": "error estimate",
               "message": "why beyond reach"}


class MapResult:
    """The contacts of a map, as NumPy arrays over the grid.

    Every column is an array of shape ``dims``: (len(m), len(H2), len(n), len(loads)) (H2 and
    n of length 1, holding 0, without roughness), or with ``harmonics`` (len(m),
    len(harmonics), len(loads)) and H2 and n None. The columns: ``status`` ("solved",
    "above_tolerance", "beyond_reach"), ``zones`` (per period), ``contact_fraction``, ``p0``,
    ``max_p``, ``error_estimate`` (NaN beyond reach) and ``message`` (why, beyond reach). The
    axes are ``m``, ``H2`` and ``n`` or ``harmonics`` (a list of lists of (H, n)), and the load
    as ``P`` and ``pa_over_pstar``; ``parameters`` holds H1, b1, E, tolerance and max_seconds.
    ``result["p0"]`` is ``result.p0``; ``result.to_xarray()`` is the same as an xarray Dataset.
    """

    columns = ("status", "zones", "contact_fraction", "p0", "max_p", "error_estimate", "message")
    __slots__ = ("m", "H2", "n", "harmonics", "P", "pa_over_pstar", "dims", "parameters") + columns

    def __init__(self, axes, columns, parameters):
        self.parameters = parameters
        self.m, self.H2, self.n, self.harmonics, self.P, self.pa_over_pstar = axes
        if self.harmonics is None:
            self.dims = ("m", "H2", "n", "load")
            shape = (len(self.m), len(self.H2), len(self.n), len(self.P))
        else:
            self.dims = ("m", "harmonics", "load")
            shape = (len(self.m), len(self.harmonics), len(self.P))
        status, zones, fraction, p0, max_p, estimate, messages = columns
        self.status = _STATUS[np.asarray(status)].reshape(shape)
        self.zones = np.asarray(zones).reshape(shape)
        self.contact_fraction = np.asarray(fraction).reshape(shape)
        self.p0 = np.asarray(p0).reshape(shape)
        self.max_p = np.asarray(max_p).reshape(shape)
        self.error_estimate = np.asarray(estimate).reshape(shape)
        self.message = np.asarray(messages, dtype=object).reshape(shape)

    def __getitem__(self, column):
        """The column of that name (``columns``)."""
        if column not in self.columns:
            raise KeyError(f"wavecontact.MapResult: no column {column!r} (columns: {', '.join(self.columns)})")
        return getattr(self, column)

    def to_xarray(self):
        """The map as an ``xarray.Dataset``: a variable a column on ``dims``, the axes as
        coordinates (``harmonics`` as strings ``"H:n+H:n"``, the syntax of the CLI's
        --harmonics) and the load dimension's two coordinates ``P`` and ``pa_over_pstar``
        (``ds.swap_dims(load="pa_over_pstar")`` indexes by the latter). Needs xarray (Debian:
        python3-xarray)."""
        try:
            import xarray
        except ImportError:
            raise ImportError("wavecontact.MapResult.to_xarray: needs xarray (Debian: apt install python3-xarray)") from None
        coords = {"m": ("m", self.m, {"long_name": "shape m of the wave curve"})}
        if self.harmonics is None:
            coords["H2"] = ("H2", self.H2, {"long_name": "roughness height H2 (0: none)"})
            coords["n"] = ("n", self.n, {"long_name": "wavelength ratio n = b1/b2 (0: none)"})
        else:
            names = ["+".join(f"{H!r}:{n}" for H, n in roughness) for roughness in self.harmonics]
            coords["harmonics"] = ("harmonics", names, {"long_name": "roughness, H:n of each harmonic"})
        coords["P"] = ("load", self.P, {"long_name": "load per unit length P"})
        coords["pa_over_pstar"] = ("load", self.pa_over_pstar, {"long_name": "pa/p*"})
        return xarray.Dataset(
            {column: (self.dims, self[column], {"long_name": _LONG_NAMES[column]}) for column in self.columns},
            coords=coords, attrs=dict(self.parameters))

    def __repr__(self):
        solved = int((self.status == "solved").sum())
        return f"MapResult({self.status.size} points, {solved} solved, axes {' x '.join(self.dims)} = {self.status.shape})"


def _axis(name, values, kind=float):
    array = np.atleast_1d(np.asarray(values, dtype=kind))
    if array.ndim != 1 or array.size == 0:
        raise ValueError(f"wavecontact.map: {name} must be a number or a non-empty 1-d sequence")
    return array


def _solve_line(grid, line):
    # A Dask task: one load line, in a worker process (module level, so that it pickles).
    return _wavecontact._solve_map_line(**grid, line=line)


def _roughnesses(harmonics):
    try:
        return [[(float(H), int(n)) for H, n in roughness] for roughness in harmonics]
    except (TypeError, ValueError) as e:
        raise ValueError(f"wavecontact.map: harmonics must be a list of lists of (H, n) pairs ({e})") from None


def map(H1, b1, E, *, m=0.0, H2=None, n=None, harmonics=None, pa_over_pstar=None, P=None, tolerance=1e-10,
        max_seconds=60.0, threads=0, client=None):
    """The contact at every point of the grid m x H2 x n x load (or m x harmonics x load), as a
    MapResult.

    ``harmonics``, instead of ``H2`` and ``n``, lists whole roughnesses, each a list of (H, n)
    pairs: ``[[(0.15, 6), (0.01, 64)], [(0.0375, 32)]]``. The loads (``pa_over_pstar`` or
    ``P``, ascending) of one (m, roughness) are a load line,
    solved by one continuation; without ``client`` the lines run on ``threads`` threads (0:
    one a core), with a ``dask.distributed.Client`` they are its tasks, one a line. Either way
    every point holds the same bits as ``solve_contact`` on its line's loads. ``H2`` and ``n``
    go together; without them, the wave curve alone. Invalid input raises ValueError naming
    the parameter.
    """
    if (H2 is None) != (n is None):
        raise ValueError("wavecontact.map: H2 and n go together (neither: the wave curve alone)")
    if harmonics is not None and H2 is not None:
        raise ValueError("wavecontact.map: give either H2 and n or harmonics")
    roughnesses = _roughnesses(harmonics) if harmonics is not None else []
    if harmonics is not None and not roughnesses:
        raise ValueError("wavecontact.map: harmonics must hold at least one roughness")
    if (pa_over_pstar is None) == (P is None):
        raise ValueError("wavecontact.map: give exactly one of pa_over_pstar, P")
    shapes = _axis("m", m)
    heights = _axis("H2", H2) if H2 is not None else np.zeros(0)
    ratios = _axis("n", n, np.int64) if n is not None else np.zeros(0, dtype=np.int64)
    loads = _axis("pa_over_pstar" if P is None else "P", pa_over_pstar if P is None else P)
    grid = dict(H1=float(H1), b1=float(b1), E=float(E), m=shapes.tolist(), H2=heights.tolist(), n=ratios.tolist(),
                harmonics=roughnesses, loads=loads.tolist(), ratios=P is None, tolerance=float(tolerance),
                max_seconds=float(max_seconds))
    parameters = {key: grid[key] for key in ("H1", "b1", "E", "tolerance", "max_seconds")}
    pstar_load = np.pi * float(E) * float(H1)
    load_axes = (loads * pstar_load if P is None else loads, loads if P is None else loads / pstar_load)
    if roughnesses:
        axes = (shapes, None, None, roughnesses) + load_axes
    else:
        axes = (shapes, heights if heights.size else np.zeros(1),
                ratios if ratios.size else np.zeros(1, dtype=np.int64), None) + load_axes
    if client is None:
        return MapResult(axes, _wavecontact._map_contacts(**grid, threads=int(threads)), parameters)
    # The grid checked here, before any task (the same ValueError as the local run); the lines
    # submitted the costliest first, as the local map takes them (Client.map ranks its tasks
    # in the order given), and their parts put back in the order of the lines.
    order = _wavecontact._map_lines_costliest_first(**grid)
    futures = client.map(_solve_line, [grid] * len(order), order, pure=False)
    parts = [None] * len(order)
    for line, part in zip(order, client.gather(futures)):
        parts[line] = part
    columns = [np.concatenate([np.asarray(part[c]) for part in parts]) for c in range(6)]
    columns.append([message for part in parts for message in part[6]])
    return MapResult(axes, columns, parameters)
