// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=lts 2>/dev/null | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=hip 2>/dev/null | FileCheck %s

// A read whose index the analysis proves to be the body's own item, though
// it is another value (a round trip through i64, `%i + 0`), loads at `%i`
// itself. Under lts a local load at any other index reads another item's
// time levels, which an interp(none) buffer (and a #sim.hermite one)
// cannot give: the CPU lowering crashed on the first scene, and failed with
// "does not dominate" on the second. A window read (`%l`) keeps its index.

// CHECK-LABEL: sim.simulation @round_trip
// CHECK: sim.component @M
// CHECK: evaluate {
// CHECK-NEXT: ^bb0(%[[I:.*]]: index, %{{.*}}: i64, %{{.*}}: i32, %{{.*}}: f64):
// CHECK: %[[L:.*]] = arith.index_cast %{{.*}} : i64 to index
// CHECK-DAG: sim.load local @P[%[[I]]] : f64
// CHECK-DAG: sim.load local @P[%[[L]]] : f64
// CHECK-DAG: sim.load local @R[%[[I]]] : f64
sim.simulation @round_trip range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    sim.yield %x : f64
  }
  sim.buffer @R : f64 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @M writes(@P, @R) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %l64 = arith.subi %i64, %c1 : i64
    %l = arith.index_cast %l64 : i64 to index
    %me = arith.index_cast %i64 : i64 to index
    %p = sim.read @P[%me] : f64
    %pl = sim.read @P[%l] : f64
    %r = sim.read @R[%me] : f64
    %d = arith.subf %pl, %p : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %p1 = math.fma %h, %d, %p : f64
    %r1 = arith.addf %r, %h : f64
    sim.yield %p1, %r1 : f64, f64
  }
  sim.observe [@P, @R]
}

// -----

// CHECK-LABEL: sim.simulation @plus_zero
// CHECK: sim.component @M
// CHECK: evaluate {
// CHECK-NEXT: ^bb0(%[[I:.*]]: index, %{{.*}}: i64, %{{.*}}: i32, %{{.*}}: f64):
// CHECK-DAG: sim.load local @Q[%[[I]]] : f64
// CHECK-DAG: sim.load local @P[%[[I]]] : f64
sim.simulation @plus_zero range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    sim.yield %x : f64
  }
  sim.buffer @Q : f64 interp(#sim.hermite<@P>) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @M writes(@P, @Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %me = arith.addi %c0, %i : index
    %l = arith.subi %i, %c1 : index
    %p = sim.read @P[%i] : f64
    %pl = sim.read @P[%l] : f64
    %q = sim.read @Q[%me] : f64
    %d = arith.subf %pl, %p : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %p1 = math.fma %h, %d, %p : f64
    %q1 = arith.addf %q, %h : f64
    sim.yield %p1, %q1 : f64, f64
  }
  sim.observe [@P, @Q]
}
