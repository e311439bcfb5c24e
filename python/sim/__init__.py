"""sim: write simulations as Python functions, compile them, run them.

Import it from a checkout with one line (or PYTHONPATH=<repo>/python):

    import sys; sys.path.insert(0, "<repo>/python")
    import sim

A scene's buffers, components and totals are Python functions that the
package traces into the `sim` dialect (docs/Model.md), in the spirit of
`@wp.kernel`: operators and `sim.*` functions on traced values become
`arith`, `math`, `vector` and `scf` operations, each located at the Python
line that made it, so compiler diagnostics name that line.

    # Explicit Euler is stable for kappa * dt / h^2 <= 1/2 (here 0.33).
    rod = sim.Scene("rod", range=256, dt=5e-6, precision=sim.f64)
    kappa = rod.param("kappa", 1.0)

    @rod.buffer(boundary="zero")
    def T(i):
        return sim.sin(3.141592653589793 * (sim.f64(i) + 1.0) / 257.0)

    @rod.component(writes=T)
    def Diffuse(i, n, dt):
        h2 = (1.0 / 257.0) ** 2
        return T[i] + kappa * sim.f64(n) * dt / h2 * (T[i - 1] - 2.0 * T[i] + T[i + 1])

    rod.observe(T)
    bundle = sim.compile(rod)                     # sim-translate --sim-to-bundle
    session = bundle.session("hip", backend="cpu")
    out = session.run(1000, output_every=100)     # numpy arrays over time
    out.save("rod.npz")                           # python3 -m sim.plot rod.npz

docs/Tutorial.md walks through it; python/examples/ has the paper's and two
physics scenes written this way. Standard library + numpy (+ matplotlib for
sim.plot).
"""

from . import ops
from .compiler import compile, find_tool, run_sim_opt
from .errors import CompileError, NonFiniteWarning, SimError, TraceError
from .ops import (abs, acos, acosh, asin, asinh, atan, atan2, atanh, bitcast,
                  broadcast, cbrt, ceil, clamp, copysign, cos, cosh, div, dot,
                  erf, exp, exp2, expm1, floor, fma, fmod, log, log1p, log2,
                  log10, loop, max, min, pow, range, reduce, rem, round,
                  roundeven, rsqrt, select, sin, sinh, sqrt, sum, tan, tanh,
                  trunc, where)
from .scene import Buffer, Component, Param, Scene, Total, hermite
from .trace import Value
from .types import (DType, boolean, f32, f64, i32, i64, index, u32, u64,
                    vector)

# numpy is needed only to run bundles (sim.runtime); tracing and compiling
# need the standard library alone.
try:
    from .output import Output, error_norms
    from .runtime import Bundle, RunError, Session
except ImportError as _error:  # pragma: no cover - without numpy
    _runtime_error = _error

    def __getattr__(name):
        if name in ("Bundle", "Session", "RunError", "Output", "error_norms"):
            raise ImportError(f"sim.{name} needs numpy ({_runtime_error})")
        raise AttributeError(name)

__all__ = [
    "Scene", "Buffer", "Component", "Param", "Total", "hermite", "Value",
    "DType", "f32", "f64", "i32", "i64", "u32", "u64", "index", "boolean",
    "vector", "compile", "find_tool", "run_sim_opt", "Bundle", "Session",
    "Output", "error_norms", "RunError", "SimError", "TraceError",
    "CompileError", "NonFiniteWarning", "select", "where", "min", "max",
    "clamp", "fma", "abs", "sum", "dot", "reduce", "broadcast", "bitcast",
    "div", "rem", "fmod", "range", "loop", "atan2", "pow", "copysign",
    # The math functions of ops.UNARY_MATH:
    "exp", "exp2", "expm1", "log", "log2", "log10", "log1p", "sqrt", "rsqrt",
    "cbrt", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh",
    "tanh", "asinh", "acosh", "atanh", "erf", "floor", "ceil", "round",
    "roundeven", "trunc",
]
assert sorted(__all__[-len(ops.UNARY_MATH):]) == sorted(ops.UNARY_MATH)
