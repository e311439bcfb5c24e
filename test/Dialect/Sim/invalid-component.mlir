// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of sim.component: the writes list, the num_steps and evaluate body
// signatures and yields, and the one-writer rule.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects to write at least one buffer}}
  sim.component @C writes() evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op lists buffer @B twice in writes}}
  sim.component @C writes(@B, @B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x, %x : f32, f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op writes @X, which is not a sim.buffer of this simulation}}
  sim.component @C writes(@B, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x, %x : f32, f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op writes @C, which is not a sim.buffer of this simulation}}
  sim.component @C writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op writes buffer @B, which component @C already writes; every buffer has exactly one writer}}
  sim.component @D writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the num_steps body to have arguments (index, i64), but it has ('index')}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index):
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the num_steps body to have arguments (index, i64), but it has ('index', 'i32')}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i32):
    sim.yield %t : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the num_steps body to end in 'sim.yield'}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the num_steps body to yield one 'i32', but it yields ('i64')}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    sim.yield %t : i64
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the num_steps body to yield one 'i32', but it yields ()}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    sim.yield
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op region #0 ('num_steps') failed to verify constraint: region with at most 1 blocks}}
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  ^bb1:
    %d = arith.constant 1 : i32
    sim.yield %d : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// The evaluate body's time step has the simulation's dt type.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to have arguments (index, i64, i32, f32), but it has ('index', 'i64', 'i32', 'f64')}}
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f64) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to have arguments (index, i64, i32, f64), but it has ('index', 'i64', 'i32')}}
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to have arguments (index, i64, i32, f32), but it has ()}}
  sim.component @C writes(@B) evaluate {
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to end in 'sim.yield'}}
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op region #1 ('evaluate') failed to verify constraint: region with 1 blocks}}
  sim.component @C writes(@B) evaluate {
  }
}

// -----

// An empty block in the generic form: must be diagnosed, not crash.
"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32, max_steps = 1 : i32}> ({
  // expected-error @+1 {{'sim.component' op expects the evaluate body to end in 'sim.yield'}}
  "sim.component"() <{sym_name = "C", writes = [@B]}> ({
  }, {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
  }) : () -> ()
}) : () -> ()

// -----

"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32, max_steps = 1 : i32}> ({
  // expected-error @+1 {{'sim.component' op expected 2 regions}}
  "sim.component"() <{sym_name = "C", writes = [@B]}> ({
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = "arith.constant"() <{value = 0.0 : f32}> : () -> f32
    "sim.yield"(%c) : (f32) -> ()
  }) : () -> ()
}) : () -> ()

// -----

"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32, max_steps = 1 : i32}> ({
  // expected-error @+1 {{'sim.component' op requires attribute 'writes'}}
  "sim.component"() <{sym_name = "C"}> ({
  }, {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    "sim.yield"() : () -> ()
  }) : () -> ()
}) : () -> ()

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to yield one value per written buffer (1), but it yields 2}}
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x, %x : f32, f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op expects the evaluate body to yield one value per written buffer (2), but it yields 0}}
  sim.component @C writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : vector<2xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  // Results follow the order of writes: result #1 is the value of @V.
  // expected-error @+1 {{'sim.component' op yields 'f32' for @V (result #1 of evaluate), but the buffer's element type is 'vector<2xf32>'}}
  sim.component @C writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x, %x : f32, f32
  }
}

// -----

// expected-error @+1 {{'sim.component' op expects parent op 'sim.simulation'}}
sim.component @C writes(@B) evaluate {
^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
  %c = arith.constant 0.0 : f32
  sim.yield %c : f32
}

// -----

// Caches recorded by --sim-plan-memory under hip-cache.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
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
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op caches @Nope, which is not a sim.buffer of this simulation}}
  sim.component @CB writes(@B) attributes {caches = [#sim.cache<@Nope, -1, 1>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
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
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op caches @B, which it writes; a cache holds interpolated values of another component's buffer}}
  sim.component @CB writes(@B) attributes {caches = [#sim.cache<@B, -1, 1>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
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
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op caches @A twice; one cache covers all window reads of a buffer}}
  sim.component @CB writes(@B) attributes {caches = [#sim.cache<@A, -1, 1>, #sim.cache<@A, 0, 2>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy hip>} {
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
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op has shared-memory caches, but the simulation's memory plan is not for the hip-cache strategy}}
  sim.component @CB writes(@B) attributes {caches = [#sim.cache<@A, -1, 1>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
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
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.component' op attribute 'caches' failed to satisfy constraint: array of #sim.cache}}
  sim.component @CB writes(@B) attributes {caches = [@A]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{#sim.cache of @A expects a window of more than one offset (lowest below highest), but got 2, 2}}
  sim.component @CA writes(@A) attributes {caches = [#sim.cache<@A, 2, 2>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A cache lives in a group's shared memory: a window of more than 2^20
// offsets (here the whole signed range, whose size overflowed) is refused.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{#sim.cache of @A spans offsets -2305843009213693952 to 2305843009213693952, more than 1048576 apart}}
  sim.component @CA writes(@A) attributes {caches = [#sim.cache<@A, -2305843009213693952, 2305843009213693952>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op advances by group_substeps but has no num_steps body to size them}}
  sim.component @CA writes(@A) attributes {advance = #sim<advance group_substeps>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op estimates the big step but has no num_steps body}}
  sim.component @CA writes(@A) attributes {estimates} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has a local_window that is not [lo, hi] with lo <= 0 <= hi}}
  sim.component @C writes(@B) attributes {local_window = array<i64: 1, 2>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op advances in local_steps, which needs a local_window and the lts strategy}}
  sim.component @C writes(@B) attributes {advance = #sim<advance local_steps>, local_window = array<i64: -1, 1>} num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) {
  sim.buffer @F : f32 interp(#sim.flux) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has a flux_window that is not [lo, hi] with lo <= hi}}
  sim.component @E writes(@F) attributes {flux_window = array<i64: 1, 0>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @F : f32 interp(#sim.flux) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op advances in local_flux, which needs a flux_window and the lts strategy}}
  sim.component @E writes(@F) attributes {advance = #sim<advance local_flux>, flux_window = array<i64: -1, 0>} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy lts>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_levels but does not advance in local_steps}}
  sim.component @C writes(@B) attributes {advance = #sim<advance group_substeps>, invariant_levels} num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy lts>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_levels, but its num_steps reads its local time}}
  sim.component @C writes(@B) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window = array<i64: -1, 1>} num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.trunci %t : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy lts>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_levels, but its num_steps reads @B}}
  sim.component @C writes(@B) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window = array<i64: -1, 1>} num_steps {
  ^bb0(%i: index, %t: i64):
    %x = sim.read @B[%i] : f32
    %n = arith.fptosi %x : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_estimate but does not advance in grid_substeps with a num_steps}}
  sim.component @C writes(@B) attributes {advance = #sim<advance group_substeps>, invariant_estimate} num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_estimate, but its num_steps reads its local time}}
  sim.component @C writes(@B) attributes {advance = #sim<advance grid_substeps>, invariant_estimate} num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.trunci %t : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_estimate, but its num_steps reads @B}}
  sim.component @C writes(@B) attributes {advance = #sim<advance grid_substeps>, invariant_estimate} num_steps {
  ^bb0(%i: index, %t: i64):
    %x = sim.read @B[%i] : f32
    %n = arith.fptosi %x : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(2) attributes {strategy = #sim<strategy hip>} {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op has invariant_estimate, but its num_steps reads @B}}
  sim.component @C writes(@B) attributes {advance = #sim<advance grid_substeps>, invariant_estimate} num_steps {
  ^bb0(%i: index, %t: i64):
    %x = sim.load source @B[%i] : f32
    %n = arith.fptosi %x : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}
