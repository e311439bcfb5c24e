// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory --sim-plan-halos | FileCheck %s

// Reads of other items through windows: each buffer records the items it is
// read at below and above the reading item, joined over every read
// (num_steps, evaluate and totals); a buffer read only at its own item
// records nothing. The simulation records the largest.

// CHECK-LABEL: sim.simulation @windows
// CHECK-SAME: distributed_halo = 3 : i64
// CHECK: sim.buffer @A : f32 attributes {halo = array<i64: 1, 3>} init
// CHECK: sim.buffer @B : f32 attributes {halo = array<i64: 2, 0>} init
// CHECK: sim.buffer @C : f32 init
// CHECK: sim.buffer @Own : f32 init
sim.simulation @windows range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    // Init bodies are recomputed at the item they read: no ghosts.
    %c5 = arith.constant 5 : index
    %j = arith.addi %i, %c5 : index
    %a = sim.read @A[%j] : f32
    sim.yield %a : f32
  }
  sim.buffer @Own : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@A, @B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %a = sim.read @A[%j] : f32
    %c2 = arith.constant 2 : index
    %k = arith.subi %i, %c2 : index
    %b = sim.read @B[%k] : f32
    sim.yield %a, %b : f32, f32
  }
  sim.component @Reader writes(@C, @Own) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c3 = arith.constant 3 : index
    %j = arith.addi %i, %c3 : index
    %a = sim.read @A[%j] : f32
    %o = sim.read @Own[%i] : f32
    sim.yield %a, %o : f32, f32
  }
  sim.total @Sum : f64 {
  ^bb0(%i: index):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %b = sim.read @B[%j] : f32
    %e = arith.extf %b : f32 to f64
    sim.yield %e : f64
  }
  sim.schedule [@Source, @Reader]
  sim.observe [@C, @Own]
}

// -----

// An interpolated read also reads the buffers of its interpolation: a
// Hermite derivative gets the halo of the buffer it belongs to.

// CHECK-LABEL: sim.simulation @hermite
// CHECK-SAME: distributed_halo = 1 : i64
// CHECK: sim.buffer @X : f32 interp(#sim.hermite<@dX>) attributes {halo = array<i64: 1, 1>} init
// CHECK: sim.buffer @dX : f32 attributes {halo = array<i64: 1, 1>} init
sim.simulation @hermite range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 interp(#sim.hermite<@dX>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @dX : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Move writes(@X, @dX) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %d = sim.read @dX[%i] : f32
    sim.yield %x, %d : f32, f32
  }
  sim.component @Probe writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %k = arith.subi %i, %c1 : index
    %a = sim.read @X[%j] : f32
    %b = sim.read @X[%k] : f32
    %s = arith.addf %a, %b : f32
    sim.yield %s : f32
  }
  sim.schedule [@Move, @Probe]
  sim.observe [@Y]
}

// -----

// Nothing read at other items: no buffer has a halo, and the ranks keep no
// ghost items.

// CHECK-LABEL: sim.simulation @local
// CHECK-SAME: distributed_halo = 0 : i64
// CHECK-NOT: halo = array
sim.simulation @local range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Decay]
  sim.observe [@X]
}

// -----

// The snapshot of a grid_sync component's buffer needs ghosts only where a
// later component interpolates it at other items: @U's (read at i+1 by
// @Watch) records snapshot_ghosts, @V's (read at its own item) does not.

// CHECK-LABEL: sim.simulation @snapshots
// CHECK: sim.buffer @U : f32 attributes {halo = array<i64: 1, 1>, snapshot, snapshot_ghosts} init
// CHECK: sim.buffer @V : f32 attributes {halo = array<i64: 1, 0>, snapshot} init
sim.simulation @snapshots range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    %vl = sim.read @V[%l] : f32
    sim.yield %vl, %ul : f32, f32
  }
  sim.component @Watch writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %u = sim.read @U[%r] : f32
    %v = sim.read @V[%i] : f32
    %s = arith.addf %u, %v : f32
    sim.yield %s : f32
  }
  sim.schedule [@Diffuse, @Watch]
  sim.observe [@W]
}
