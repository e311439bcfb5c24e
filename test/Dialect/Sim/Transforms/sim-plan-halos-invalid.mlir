// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-schedule --sim-substep-legality --sim-plan-memory --sim-plan-halos

// A gather in evaluate: its item may lie on any rank.
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
    // expected-error @+1 {{reads @X in evaluate through a gather, which a distributed run cannot serve: the item may lie on any rank; index it as the item plus a constant offset (a window), or compile without --sim-distributed}}
    %x = sim.read @X[%j] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Decay, @Pick]
  sim.observe [@Y]
}

// -----

// A gather in a total is refused the same way.
sim.simulation @total_gather range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.total @First : f64 {
  ^bb0(%i: index):
    %c0 = arith.constant 0 : index
    // expected-error @+1 {{reads @X in a total through a gather}}
    %x = sim.read @X[%c0] : f32
    %e = arith.extf %x : f32 to f64
    sim.yield %e : f64
  }
  sim.schedule [@Decay]
  sim.observe [@X]
}
