// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory --sim-plan-halos --sim-plan-halos | FileCheck %s --check-prefix=HALOS

// The distributed decisions belong to --sim-plan-halos, which runs after
// the memory plan in a distributed compile only. Left over in a scene (a
// copy of a distributed compile's IR, or written by hand), they would plan
// a distributed run without its ghosts: the memory plan drops them, and
// --sim-plan-halos decides them afresh (twice gives the same).

// CHECK-LABEL: sim.simulation @leftovers
// CHECK-NOT: distributed_halo
// CHECK: sim.buffer @U : f64 init
// CHECK-NOT: halo
// CHECK-NOT: replicated
// CHECK-NOT: snapshot_ghosts
// CHECK: sim.observe

// HALOS-LABEL: sim.simulation @leftovers
// HALOS-SAME: distributed_halo = 1 : i64
// HALOS: sim.buffer @U : f64 attributes {halo = array<i64: 1, 1>} init
// HALOS-NOT: replicated
// HALOS: sim.observe
sim.simulation @leftovers range(64) dt(1.0e-3 : f64) max_steps(4) attributes {distributed_halo = 0 : i64} {
  sim.buffer @U : f64 attributes {halo = array<i64: 0, 0>, replicated, snapshot_ghosts} init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.component @Diffuse writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %ul = sim.read @U[%l] : f64
    %u = sim.read @U[%i] : f64
    %ur = sim.read @U[%r] : f64
    %s = arith.addf %ul, %ur : f64
    %h = arith.constant 0.25 : f64
    %d = arith.mulf %s, %h : f64
    %half = arith.constant 0.5 : f64
    %k = arith.mulf %u, %half : f64
    %v = arith.addf %k, %d : f64
    sim.yield %v : f64
  }
  sim.observe [@U]
}
