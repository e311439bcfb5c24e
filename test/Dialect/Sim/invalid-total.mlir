// RUN: sim-opt %s --split-input-file --verify-diagnostics

sim.simulation @s range(4) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.total' op expects a total of type f32 or f64, but got 'i32'}}
  sim.total @T : i32 {
  ^bb0(%i: index):
    %c = arith.constant 0 : i32
    sim.yield %c : i32
  }
}

// -----

sim.simulation @s range(4) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.total' op expects the total body to yield one value of the total's type 'f64', but it yields ('f32')}}
  sim.total @T : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(4) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.total' op expects the total body to have arguments (index), but it has ('index', 'f64')}}
  sim.total @T : f32 {
  ^bb0(%i: index, %t: f64):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(4) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.total @T : f32 {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.load' op loads the target copy in a total body; a total reads the state at T, the source copy}}
    %x = sim.load target @X[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// expected-error @+1 {{'sim.total' op expects parent op 'sim.simulation'}}
sim.total @T : f32 {
^bb0(%i: index):
  %c = arith.constant 0.0 : f32
  sim.yield %c : f32
}
