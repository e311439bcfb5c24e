// The generated PBD-like scene (Section 5.2, Fig. 10) parses, verifies and
// prints identically after a round trip, in the custom and in the generic
// form, and reads exactly the buffers of Fig. 10.
//
// RUN: sim-opt %examples/paper/pbd_like.mlir > %t.1
// RUN: sim-opt %t.1 > %t.2
// RUN: diff %t.1 %t.2
// RUN: sim-opt %examples/paper/pbd_like.mlir --mlir-print-op-generic > %t.g
// RUN: sim-opt %t.g > %t.3
// RUN: diff %t.1 %t.3
// RUN: FileCheck %s --implicit-check-not=sim.read < %t.1

// Every read of the scene is listed here (--implicit-check-not). Reads at
// item i (and i-1, i+1) of a windowed buffer are rows of the per-item load.

// CHECK-LABEL: sim.simulation @pbd_like range(65536) dt(1.000000e-03 : f32) max_steps(3)
// CHECK: sim.buffer @B0 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B1 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B2 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B3 : vector<4xf32> interp(#sim.cubic) init
// CHECK: sim.buffer @B4 : vector<4xf32> interp(#sim.cubic) init
// CHECK: sim.buffer @B5 : vector<4xf32> interp(#sim.linear) init
// CHECK: sim.buffer @B6 : vector<4xf32> interp(#sim.linear) init

// C0: own B0 at i, B6 at i (the back edge).
// CHECK-LABEL: sim.component @C0 writes(@B0) num_steps
// CHECK: evaluate
// CHECK: sim.read @B0[%i] : vector<4xf32>
// CHECK: sim.read @B6[%i] : vector<4xf32>

// C1: B0 in the window.
// CHECK-LABEL: sim.component @C1 writes(@B1) num_steps
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B0[%[[J]]]
// CHECK: sim.read @B0[%i]
// CHECK: sim.read @B0[%{{[^]]+}}]
// CHECK: sim.read @B0[%{{[^]]+}}]

// C2: B1 in the window, B0 at i.
// CHECK-LABEL: sim.component @C2 writes(@B2) num_steps
// CHECK: sim.read @B0[%i]
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B1[%[[J]]]
// CHECK: sim.read @B1[%i]
// CHECK: sim.read @B1[%{{[^]]+}}]

// C3: B2 in the window.
// CHECK-LABEL: sim.component @C3 writes(@B3) num_steps
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B2[%[[J]]]
// CHECK: sim.read @B2[%i]
// CHECK: sim.read @B2[%{{[^]]+}}]
// CHECK: sim.read @B2[%{{[^]]+}}]

// C4: B3 in the window.
// CHECK-LABEL: sim.component @C4 writes(@B4) num_steps
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B3[%[[J]]]
// CHECK: sim.read @B3[%i]
// CHECK: sim.read @B3[%{{[^]]+}}]
// CHECK: sim.read @B3[%{{[^]]+}}]

// C5: B4 and B3 in the window.
// CHECK-LABEL: sim.component @C5 writes(@B5) num_steps
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B4[%[[J]]]
// CHECK: sim.read @B3[%[[J]]]
// CHECK: sim.read @B4[%i]
// CHECK: sim.read @B3[%i]

// C6: own B6 at i, B5 in the window.
// CHECK-LABEL: sim.component @C6 writes(@B6) num_steps
// CHECK: sim.read @B6[%i]
// CHECK: scf.for %[[K:[^ ]+]] = %c-4 to %c5 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B5[%[[J]]]
// CHECK: sim.read @B5[%i]
// CHECK: sim.read @B5[%{{[^]]+}}]

// CHECK: sim.schedule [@C0]
// CHECK-NEXT: sim.observe [@B6]
