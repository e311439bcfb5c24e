// RUN: sim-opt %s --split-input-file --verify-diagnostics --pass-pipeline='builtin.module(sim.simulation(sim-define-edge-cases))'

// A constant step that is not positive is a mistake, not an edge case.
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %lo = arith.constant 0 : index
    %hi = arith.constant 4 : index
    // expected-error @+1 {{scf.for has the constant step 0, so it never ends: give it a positive step}}
    %r = scf.for %k = %lo to %hi step %lo iter_args(%a = %x) -> f32 {
      scf.yield %a : f32
    }
    sim.yield %r : f32
  }
  sim.observe [@X]
}

// -----

sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @C writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 0 : i32
    %hi = arith.constant 4 : i32
    %step = arith.constant -2 : i32
    // expected-error @+1 {{scf.for has the constant step -2, so it never ends: give it a positive step}}
    %r = scf.for %k = %lo to %hi step %step iter_args(%a = %hi) -> i32 : i32 {
      scf.yield %a : i32
    }
    sim.yield %r : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
