// The generated gravity-like scene (Section 5.1, Fig. 9) parses, verifies and
// prints identically after a round trip, in the custom and in the generic
// form, and reads exactly the buffers of Fig. 9.
//
// RUN: sim-opt %examples/paper/gravity_like.mlir > %t.1
// RUN: sim-opt %t.1 > %t.2
// RUN: diff %t.1 %t.2
// RUN: sim-opt %examples/paper/gravity_like.mlir --mlir-print-op-generic > %t.g
// RUN: sim-opt %t.g > %t.3
// RUN: diff %t.1 %t.3
// RUN: FileCheck %s --implicit-check-not=sim.read < %t.1

// Every read of the scene is listed here (--implicit-check-not). Reads at
// item i other than the own buffer are rows of the per-item load.

// CHECK-LABEL: sim.simulation @gravity_like range(65536) dt(1.000000e-03 : f32) max_steps(3)
// CHECK-NEXT: sim.param @L = 8 : i32
// CHECK-NEXT: sim.param @dist = 0 : i32
// CHECK-NEXT: sim.param @group = 32 : i32
// CHECK: sim.buffer @B0 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B1 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B2 : vector<4xf32> interp(#sim.linear) init

// C0: own B0 at i, B2 at i (the back edge).
// CHECK-LABEL: sim.component @C0 writes(@B0) num_steps
// CHECK: sim.get_param @dist : i32
// CHECK: arith.remui
// CHECK: evaluate
// CHECK: sim.read @B0[%i] : vector<4xf32>
// CHECK: sim.read @B2[%i] : vector<4xf32>
// CHECK: sim.get_param @L : i32
// CHECK: math.tanh

// C1: B0 in the window i-4..i+4.
// CHECK-LABEL: sim.component @C1 writes(@B1) num_steps
// CHECK: evaluate
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B0[%[[J]]] : vector<4xf32>
// CHECK: sim.read @B0[%i] : vector<4xf32>
// CHECK: %[[L:[^ ]+]] = arith.addi %i, %c-1 : index
// CHECK-NEXT: sim.read @B0[%[[L]]] : vector<4xf32>
// CHECK: %[[R:[^ ]+]] = arith.addi %i, %c1 : index
// CHECK-NEXT: sim.read @B0[%[[R]]] : vector<4xf32>

// C2: own B2 at i, B0 and B1 in the window i-4..i+4.
// CHECK-LABEL: sim.component @C2 writes(@B2) num_steps
// CHECK: evaluate
// CHECK: sim.read @B2[%i] : vector<4xf32>
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B0[%[[J]]] : vector<4xf32>
// CHECK: sim.read @B1[%[[J]]] : vector<4xf32>
// CHECK: sim.read @B0[%i] : vector<4xf32>
// CHECK: sim.read @B1[%i] : vector<4xf32>

// CHECK: sim.schedule [@C0]
// CHECK-NEXT: sim.observe [@B2]
