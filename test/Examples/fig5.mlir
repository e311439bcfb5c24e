// The hand-written scene of the paper's Fig. 5 parses, verifies and prints
// identically after a round trip, in the custom and in the generic form.
//
// RUN: sim-opt %examples/paper/fig5.mlir > %t.1
// RUN: sim-opt %t.1 > %t.2
// RUN: diff %t.1 %t.2
// RUN: sim-opt %examples/paper/fig5.mlir --mlir-print-op-generic > %t.g
// RUN: sim-opt %t.g > %t.3
// RUN: diff %t.1 %t.3
// RUN: FileCheck %s --implicit-check-not=sim.read < %t.1

// Every read of the scene is listed here (--implicit-check-not): they are
// the edges of Fig. 5, plus the output B4 that C4 writes.

// CHECK-LABEL: sim.simulation @fig5 range(1024) dt(1.000000e-03 : f32) max_steps(3)
// CHECK: sim.buffer @B0 : f32 interp(#sim.linear) init
// CHECK: sim.buffer @B1 : f32 interp(#sim.linear) init
// CHECK: sim.buffer @B2 : f32 interp(#sim.linear) init
// CHECK: sim.buffer @B3 : f32 interp(#sim.linear) init
// CHECK: sim.buffer @B4 : f32 interp(#sim.linear) init

// CHECK-LABEL: sim.component @C0 writes(@B0) num_steps
// CHECK: evaluate
// CHECK: sim.read @B0[%i] : f32
// CHECK: sim.read @B3[%i] : f32

// CHECK-LABEL: sim.component @C1 writes(@B1) num_steps
// CHECK: sim.read @B0[%i] : f32

// CHECK-LABEL: sim.component @C2 writes(@B2) num_steps
// CHECK: scf.for %[[K:[^ ]+]] = %c-1 to %c2 step %c1
// CHECK-NEXT: %[[J:[^ ]+]] = arith.addi %i, %[[K]] : index
// CHECK-NEXT: sim.read @B1[%[[J]]] : f32

// CHECK-LABEL: sim.component @C3 writes(@B3) num_steps
// CHECK: sim.read @B2[%i] : f32

// CHECK-LABEL: sim.component @C4 writes(@B4) num_steps
// CHECK: sim.read @B3[%i] : f32

// CHECK: sim.schedule [@C0]
// CHECK-NEXT: sim.observe [@B4]
