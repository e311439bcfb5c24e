"""simscene: build `sim` dialect scenes from Python.

The package writes MLIR text for `sim-opt` and the other sim tools; it needs
only the Python standard library (the Debian MLIR package has no Python
bindings).

* `simscene.builder`: the scene structure (`Simulation`, `Param`, `Buffer`,
  `Component`) and `Body`, one block of ops with SSA-name generation.
* `simscene.emitters`: the building blocks of the paper's benchmark scenes
  (the step-count hash, the 9-neighbour gather, the L-round 4x4 matrix
  load, the relaxation) and Python references of the hash and initial values.
* `simscene.scenes`: the gravity-like (Section 5.1) and PBD-like (Section 5.2)
  scenes.

    from simscene import gravity_like
    open("g.mlir", "w").write(gravity_like(rounds=64, dist=2).render())
"""

from .builder import Body, Buffer, Component, Namer, Param, Simulation
from .emitters import init_value, step_count, step_key
from .scenes import ComponentSpec, build_scene, gravity_like, pbd_like

__all__ = [
    "Body",
    "Buffer",
    "Component",
    "ComponentSpec",
    "Namer",
    "Param",
    "Simulation",
    "build_scene",
    "gravity_like",
    "init_value",
    "pbd_like",
    "step_count",
    "step_key",
]
