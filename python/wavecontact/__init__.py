"""wavecontact: elastic contact of regular rough surfaces (Tsukanov), from Python.

The closed forms derived by wavecontact-derive and the contact at any load, on floats and
NumPy arrays, from the C++ runtime library. Invalid input raises ValueError naming the
function, the parameter, its value and the valid range.
"""
from ._wavecontact import *  # noqa: F401,F403
from ._wavecontact import __version__  # noqa: F401
from ._maps import MapResult, map  # noqa: F401,A001
