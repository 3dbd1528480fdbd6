"""springlab: mass-spring simulation for teaching physically based animation.

The core of the command line and the app, for Python: scenes, the method table, simulations
whose state reads as numpy arrays, the stability analysis and the accuracy sweep.

    import springlab
    sim = springlab.Simulation("rope", method="rk4", steps=100)
    sim.run()
    print(sim.t, sim.energy().total, sim.positions[-1])
    print(sim.stability_limit().description)

Bad input raises springlab.InputError with the message the command line prints.
"""

import os as _os
from pathlib import Path as _Path

# Installed (cmake --install), the package carries the shipped scenes and tableaux in data/; in
# the build tree the module reads them from the source tree it was built from.
_data = _Path(__file__).with_name("data")
if (_data / "assets" / "scenes").is_dir():
    _os.environ.setdefault("SPRINGLAB_DATA", str(_data))



def _built_for():
    """The interpreter the compiled module was built for (_build.py, written by the build) and the
    module's own file, whose name carries its ABI (cpython-311-...)."""
    try:
        from ._build import PYTHON, PYTHON_VERSION
    except ImportError:
        PYTHON, PYTHON_VERSION = "an unknown Python", "?"
    modules = sorted(p.name for p in _Path(__file__).parent.glob("_springlab*.so"))
    return PYTHON, PYTHON_VERSION, modules[0] if modules else "no _springlab*.so"


def _wrong_interpreter(missing):
    """An ImportError naming this interpreter, the one the module was built for, what is missing
    and the fix, instead of an error later that seems to be the caller's."""
    import sys
    python, version, module = _built_for()
    this = f"{sys.executable} (Python {sys.version.split()[0]})"
    return ImportError(f"springlab: {missing} in this Python, {this}; springlab's compiled module ({module}) "
                       f"was built for {python} (Python {version}). Run that Python ({python} -c 'import springlab'), "
                       f"or build springlab for this one: {sys.executable} -m pip install --no-build-isolation "
                       f"SOURCE (docs/python.md)")


try:
    import numpy as _numpy  # noqa: E402,F401  (the state's arrays; the module's own import would fail later)
except ImportError:
    raise _wrong_interpreter("numpy is missing") from None
try:
    from ._springlab import *  # noqa: E402,F401,F403
    from ._springlab import __version__  # noqa: E402,F401
except ImportError as _error:
    if getattr(_error, "name", None) != __name__ + "._springlab":
        raise
    raise _wrong_interpreter("the compiled module cannot be loaded") from None
