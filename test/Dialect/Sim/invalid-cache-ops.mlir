// RUN: sim-opt %s --split-input-file --verify-diagnostics

sim.simulation @outside range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.fill_cache' op must be at the top of a component's evaluate body}}
    sim.fill_cache @U window(-1, 1) {
    ^bb0(%k: index):
      %v = sim.load source @U[%k] : f32
      sim.yield %v : f32
    }
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.load local @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@U]
}

// -----

sim.simulation @narrow range(8) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.component @C writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.fill_cache' op expects a window of more than one offset, but got 2, 2}}
    sim.fill_cache @U window(2, 2) {
    ^bb0(%k: index):
      %v = sim.load source @U[%k] : f32
      sim.yield %v : f32
    }
    %u = sim.load cache @U[%i] : f32
    sim.yield %u : f32
  }
  sim.component @D writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.load local @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@V]
}

// -----

sim.simulation @wide range(8) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.component @C writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.fill_cache' op expects a window of at most 1048576 offsets, but got -1048577, 1}}
    sim.fill_cache @U window(-1048577, 1) {
    ^bb0(%k: index):
      %v = sim.load source @U[%k] : f32
      sim.yield %v : f32
    }
    %u = sim.load cache @U[%i] : f32
    sim.yield %u : f32
  }
  sim.component @D writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.load local @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@V]
}

// -----

sim.simulation @mistyped range(8) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.component @C writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.fill_cache' op must yield one 'f32', the element of @U}}
    sim.fill_cache @U window(-1, 1) {
    ^bb0(%k: index):
      %v = arith.constant 1.0 : f64
      sim.yield %v : f64
    }
    %u = sim.load cache @U[%i] : f32
    sim.yield %u : f32
  }
  sim.component @D writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.load local @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@V]
}

// -----

sim.simulation @unfilled range(8) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.component @C writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.load' op loads the cache of @U, but the body fills no cache of it (sim.fill_cache)}}
    %u = sim.load cache @U[%i] : f32
    sim.yield %u : f32
  }
  sim.component @D writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.load local @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@V]
}

// -----

sim.simulation @window_without_cache range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.load' op is marked in_window, but loads the local copy; only a cache load has a fill window}}
    %u = sim.load local @U[%i] in_window : f32
    sim.yield %u : f32
  }
  sim.observe [@U]
}
