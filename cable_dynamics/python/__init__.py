"""cable_dynamics from Python: the n-link umbilical simulator (the compiled module _bindings, pybind11).

The package also holds what dynamic_reconfigure generates for the node's live tuning (cable_dynamics.cfg);
the build puts this file in place of the empty one it writes, so that `import cable_dynamics` gives both.
"""
from cable_dynamics._bindings import *  # noqa: F401,F403
from cable_dynamics._bindings import __doc__ as _bindings_doc  # noqa: F401
