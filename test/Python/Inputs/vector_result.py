"""A vector result of the wrong length points at the body's `return`
(sim-vector-result.test).

A body that returns a tuple for a vector buffer builds the vector from it;
when the tuple's length is not the vector's, the TraceError names the line
of the `return`, not the line that traced the scene (`s.mlir()`). This
file is also the FileCheck file.
"""

import sim
from sim import f32, vector

from trace_cases import case, run


@case
def init_constants():
    s = sim.Scene("vectors", range=4, dt=1e-3)

    @s.buffer(vector(2, f32))
    def V(i):
        # CHECK: init_constants: vector_result.py:[[@LINE+1]]:{{[0-9]+}}: sim.vector(2, sim.f32) takes one value or 2 lanes, not 3
        return (1.0, 2.0, 3.0)
    s.component(writes=V, name="C")(lambda i: V[i])
    s.mlir()


@case
def evaluate_traced_lanes():
    s = sim.Scene("vectors", range=4, dt=1e-3)
    V = s.buffer(vector(3, f32), name="V")(lambda i: 0.0)

    @s.component(writes=V)
    def C(i):
        x = V[i]
        # CHECK-NEXT: evaluate_traced_lanes: vector_result.py:[[@LINE+1]]:{{[0-9]+}}: sim.vector(3, sim.f32) takes one value or 3 lanes, not 2
        return [x[0], x[1]]
    s.mlir()


@case
def lane_of_wrong_type():
    s = sim.Scene("vectors", range=4, dt=1e-3)

    @s.buffer(vector(2, f32))
    def V(i):
        # CHECK-NEXT: lane_of_wrong_type: vector_result.py:[[@LINE+1]]:{{[0-9]+}}: the constant [1.0, 'x'] is not a valid vector(2, f32)
        return (1.0, "x")
    s.component(writes=V, name="C")(lambda i: V[i])
    s.mlir()


run()
# CHECK-NOT: no error
