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

from ._springlab import *  # noqa: E402,F401,F403
from ._springlab import __version__  # noqa: E402,F401
