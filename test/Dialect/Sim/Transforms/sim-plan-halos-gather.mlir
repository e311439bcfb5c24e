// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-schedule --sim-substep-legality --sim-plan-memory --sim-plan-halos | FileCheck %s

// A gather may read an item of any rank: the buffer it reads is replicated
// (every rank holds all of it) instead of getting ghost items, with a
// remark at the read that says what it costs.

// CHECK-LABEL: sim.simulation @gather
// CHECK-SAME: distributed_halo = 0 : i64
// CHECK: sim.buffer @X : f32 attributes {replicated} init
// CHECK: sim.buffer @Y : f32 init
sim.simulation @gather range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.component @Pick writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c3 = arith.constant 3 : index
    %j = arith.muli %i, %c3 : index
    // expected-remark @+1 {{reads @X in evaluate through a gather: every rank holds all of it, and the blocks its writer computes travel to every rank after each write (an all-gather); a window (the item plus a constant offset) would need only the items next to each block}}
    %x = sim.read @X[%j] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Decay, @Pick]
  sim.observe [@Y]
}

// -----

// A gather in a total replicates the buffer too; a window read of the same
// buffer needs no ghosts then.

// CHECK-LABEL: sim.simulation @total_gather
// CHECK-SAME: distributed_halo = 0 : i64
// CHECK: sim.buffer @X : f32 attributes {replicated} init
sim.simulation @total_gather range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.component @Shift writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %x = sim.read @X[%j] : f32
    sim.yield %x : f32
  }
  sim.total @First : f64 {
  ^bb0(%i: index):
    %c0 = arith.constant 0 : index
    // expected-remark @+1 {{reads @X in a total through a gather}}
    %x = sim.read @X[%c0] : f32
    %e = arith.extf %x : f32 to f64
    sim.yield %e : f64
  }
  sim.schedule [@Decay, @Shift]
  sim.observe [@Y]
}
