// sim.total round-trips, and its body's reads count as outputs for
// --sim-prune and become loads of the state at T in
// --sim-insert-interpolation.
//
// RUN: sim-opt %s | sim-opt | FileCheck %s --check-prefix=ROUNDTRIP
// RUN: sim-opt %s --sim-prune --verify-diagnostics | FileCheck %s --check-prefix=PRUNE
// RUN: sim-opt %s --sim-front-end=strategy=hip | FileCheck %s --check-prefix=LOADS
// RUN: sim-opt %s --sim-front-end=strategy=simple | FileCheck %s --check-prefix=LOADS

// ROUNDTRIP-LABEL: sim.simulation @drift
// ROUNDTRIP:       sim.total @Energy : f64 {
// ROUNDTRIP-NEXT:  ^bb0(%i: index):
// ROUNDTRIP-NEXT:    sim.read @V[%i] : f32
// ROUNDTRIP:         sim.yield %{{.*}} : f64
// ROUNDTRIP:       sim.total @Count : f32 {

// @V is observed by no buffer: only the total @Energy reads it, so
// --sim-prune keeps it and its writer. @Unused feeds nothing.
// PRUNE-LABEL: sim.simulation @drift
// PRUNE: sim.buffer @X
// PRUNE: sim.buffer @V
// PRUNE-NOT: sim.buffer @Unused
// PRUNE: sim.component @Move writes(@X)
// PRUNE: sim.component @Push writes(@V)
// PRUNE: sim.total @Energy
// PRUNE: sim.schedule [@Move, @Push]

// Every read of a total body loads the source copy, whatever the strategy.
// LOADS-LABEL: sim.total @Energy : f64
// LOADS:         sim.load source @V[%i] : f32
// LOADS-NOT:     sim.read
// LOADS:         sim.yield
sim.simulation @drift range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @Unused: no observed buffer depends on it}}
  sim.buffer @Unused : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Move writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.component @Push writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @V[%i] : f32
    sim.yield %v : f32
  }
  // expected-remark @+1 {{removed component @Stir: no observed buffer depends on it}}
  sim.component @Stir writes(@Unused) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @Unused[%i] : f32
    sim.yield %u : f32
  }
  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : f32
    %v2 = arith.mulf %v, %v : f32
    %e = arith.extf %v2 : f32 to f64
    sim.yield %e : f64
  }
  sim.total @Count : f32 {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.schedule [@Move, @Push]
  sim.observe [@X]
}
