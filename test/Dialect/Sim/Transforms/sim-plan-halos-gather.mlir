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

// -----

// An interpolated read at other items of a buffer with boundary(wrap)
// whose Hermite derivative has another rule: past an end of the range the
// derivative is read at the wrapped item, at the other end of the range,
// which no ghost item under its own rule holds, so it is replicated.

// CHECK-LABEL: sim.simulation @hermite_wrap
// CHECK: sim.buffer @V : f32 interp(none) boundary(zero) attributes {replicated} init
// CHECK: sim.buffer @X : f32 interp(#sim.hermite<@V>) boundary(wrap) attributes {halo = array<i64: 1, 0>} init
sim.simulation @hermite_wrap range(48) dt(5.0e-2 : f32) max_steps(4) {
  sim.buffer @V : f32 interp(none) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant -0.25 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.5 : f32
    sim.yield %c : f32
  }
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @Osc writes(@V, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %nx = arith.negf %x : f32
    %v1 = math.fma %h, %nx, %v : f32
    %x1 = math.fma %h, %v1, %x : f32
    sim.yield %v1, %x1 : f32, f32
  }
  sim.component @Probe writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %one = arith.constant 1 : i32
    sim.yield %one : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    // expected-remark @below {{reads @X in evaluate at other items; past an end of the range its derivative @V (boundary(zero)) is read at the item @X's boundary(wrap) gives, at the other end of the range, so every rank holds all of @V}}
    %x = sim.read @X[%j] : f32
    %p = sim.read @P[%i] : f32
    %s = arith.addf %p, %x : f32
    sim.yield %s : f32
  }
  sim.schedule [@Osc, @Probe]
  sim.observe [@P]
}

// -----

// An index wrapped around by hand is a gather too; the remark names the
// window that boundary(wrap) gives instead: (%i - 1 + 64) mod 64 is %i - 1,
// (%i + 63) mod 64 is %i - 1 too, and (%i + 2) mod range is %i + 2;
// (%i - 1) mod 64 is below zero at item 0, so it is no wrap.

// CHECK-LABEL: sim.simulation @wrapped_by_hand
// CHECK: sim.buffer @X : f32 attributes {replicated} init
// CHECK: sim.buffer @W : f32 boundary(wrap) attributes {replicated} init
sim.simulation @wrapped_by_hand range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@X, @W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x, %x : f32, f32
  }
  sim.component @Pick writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %c63 = arith.constant 63 : index
    %c64 = arith.constant 64 : index
    %left = arith.subi %i, %c1 : index
    %lifted = arith.addi %left, %c64 : index
    %j = arith.remsi %lifted, %c64 : index
    // expected-remark @+1 {{reads @X in evaluate through a gather: every rank holds all of it, and the blocks its writer computes travel to every rank after each write (an all-gather); a window (the item plus a constant offset) would need only the items next to each block; the index wraps %i - 1 around the range by hand: with boundary(wrap) on @X, @X[%i - 1] reads the same item (where the divisor is the range) as a window}}
    %a = sim.read @X[%j] : f32
    %far = arith.addi %c63, %i : index
    %k = arith.remui %far, %c64 : index
    // expected-remark @+1 {{the index wraps %i - 1 around the range by hand: with boundary(wrap) on @X, @X[%i - 1] reads}}
    %b = sim.read @X[%k] : f32
    %range = sim.get_param @range : i64
    %r = arith.index_cast %range : i64 to index
    %right = arith.addi %i, %c2 : index
    %m = arith.remui %right, %r : index
    // expected-remark @+1 {{the index wraps %i + 2 around the range by hand: @W is boundary(wrap), so @W[%i + 2] reads the same item (where the divisor is the range) as a window}}
    %w = sim.read @W[%m] : f32
    // Not lifted by the divisor, %i - 1 is below zero at item 0: no wrap.
    %z = arith.remsi %left, %c64 : index
    // expected-remark-re @+1 {{reads @X in evaluate through a gather: {{.*}} would need only the items next to each block{{$}}}}
    %y = sim.read @X[%z] : f32
    %ab = arith.addf %a, %b : f32
    %aby = arith.addf %ab, %y : f32
    %s = arith.addf %aby, %w : f32
    sim.yield %s : f32
  }
  sim.schedule [@Source, @Pick]
  sim.observe [@Y]
}
