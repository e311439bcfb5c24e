// --sim-set-params overrides the parameters of the generated gravity-like
// scene without editing it: the item range, the load L and the step-count
// distribution, as the benchmark sweeps do.
//
// RUN: sim-opt %examples/paper/gravity_like.mlir \
// RUN:   --sim-set-params="values=range=16384,L=4,dist=2" | FileCheck %s
// RUN: sim-opt %examples/paper/gravity_like.mlir \
// RUN:   --sim-set-params="values=dist=1,group=64,max_steps=2,dt=5.0e-4" \
// RUN:   | FileCheck %s --check-prefix=GROUP
// RUN: not sim-opt %examples/paper/gravity_like.mlir \
// RUN:   --sim-set-params="values=rounds=4" 2>&1 | FileCheck %s --check-prefix=ERR

// CHECK-LABEL: sim.simulation @gravity_like range(16384) dt(1.000000e-03 : f32) max_steps(3)
// CHECK-NEXT: sim.param @L = 4 : i32
// CHECK-NEXT: sim.param @dist = 2 : i32
// CHECK-NEXT: sim.param @group = 32 : i32
// The bodies still read the parameters (they are not folded into constants).
// CHECK: sim.get_param @dist : i32
// CHECK: sim.get_param @L : i32

// GROUP-LABEL: sim.simulation @gravity_like range(65536) dt(5.000000e-04 : f32) max_steps(2)
// GROUP-NEXT: sim.param @L = 8 : i32
// GROUP-NEXT: sim.param @dist = 1 : i32
// GROUP-NEXT: sim.param @group = 64 : i32

// ERR: gravity_like.mlir:{{[0-9]+}}:1: error: has no parameter named 'rounds'; it has range, dt, max_steps, L, dist, group
