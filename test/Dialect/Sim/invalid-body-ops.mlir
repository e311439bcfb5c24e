// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of the operations of component and buffer bodies: sim.read,
// sim.load, sim.get_param, sim.big_step and sim.yield.

//===----------------------------------------------------------------------===//
// sim.read
//===----------------------------------------------------------------------===//

%i = arith.constant 0 : index
// expected-error @+1 {{'sim.read' op must be inside a num_steps, evaluate, init or exact body}}
%x = sim.read @B[%i] : f32

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  %i = arith.constant 0 : index
  // expected-error @+1 {{'sim.read' op must be inside a num_steps, evaluate, init or exact body}}
  %x = sim.read @B[%i] : f32
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.read' op has a read role, but roles only apply to reads in component bodies}}
    %x = sim.read @B[%i] interpolate : f32
    sim.yield %x : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@A, @B) evaluate {
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
  } exact {
  ^bb0(%i: index, %t: f64):
    // expected-error @+1 {{'sim.read' op has a read role, but roles only apply to reads in component bodies}}
    %x = sim.read @B[%i] own : f32
    sim.yield %x : f32
  }
  sim.component @C writes(@B) evaluate {
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
    // expected-error @+1 {{'sim.read' op reads @Nope, which is not a sim.buffer of this simulation}}
    %x = sim.read @Nope[%i] : f32
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
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // A component is a symbol of the simulation, but not a buffer.
    // expected-error @+1 {{'sim.read' op reads @C, which is not a sim.buffer of this simulation}}
    %x = sim.read @C[%i] : f32
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
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.read' op result type 'f32' does not match the element type 'vector<4xf32>' of buffer @B}}
    %x = sim.read @B[%i] : f32
    %c = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.read' op reads @B in its own init body; the initial state cannot depend on itself}}
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C writes(@B) evaluate {
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
    // expected-note @-1 {{prior use here}}
    // The index must be an index, not the local time.
    // expected-error @+1 {{use of value '%t' expects different type than prior uses: 'index' vs 'i64'}}
    %x = sim.read @B[%t] : f32
    sim.yield %x : f32
  }
}

// -----

//===----------------------------------------------------------------------===//
// sim.load
//===----------------------------------------------------------------------===//

%i = arith.constant 0 : index
// expected-error @+1 {{'sim.load' op must be inside a component's num_steps or evaluate body}}
%x = sim.load source @B[%i] : f32

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.load' op must be inside a component's num_steps or evaluate body}}
    %x = sim.load source @B[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C writes(@A, @B) evaluate {
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
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.load' op reads @Nope, which is not a sim.buffer of this simulation}}
    %x = sim.load target @Nope[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.load' op result type 'f32' does not match the element type 'f64' of buffer @B}}
    %x = sim.load snapshot @B[%i] : f32
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
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
  sim.component @CB writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.load' op loads the local state of @A, but component @CB does not write it}}
    %x = sim.load local @A[%i] : f32
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A snapshot load needs a snapshot in the memory plan.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
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
    %x = sim.load local @A[%i] : f32
    sim.yield %x : f32
  }
  sim.component @CB writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.load' op loads the snapshot of @A, but the memory plan keeps none: the buffer is not marked 'snapshot'}}
    %x = sim.load snapshot @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

//===----------------------------------------------------------------------===//
// sim.get_param
//===----------------------------------------------------------------------===//

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.get_param' op @k does not name a sim.param of the enclosing simulation}}
    %k = sim.get_param @k : f32
    sim.yield %k : f32
  }
  sim.component @C writes(@B) evaluate {
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
    // expected-error @+1 {{'sim.get_param' op @B does not name a sim.param of the enclosing simulation}}
    %x = sim.get_param @B : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.get_param' op result type 'i64' does not match the type 'i32' of parameter @L}}
    %L = sim.get_param @L : i64
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// The simulation's range is read as i64.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.get_param' op result type 'i32' does not match the type 'i64' of the simulation's range}}
    %p = sim.get_param @range : i32
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// The simulation's dt is read as f32.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.get_param' op result type 'f64' does not match the type 'f32' of the simulation's dt}}
    %p = sim.get_param @dt : f64
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// The simulation's max_steps is read as i32.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.get_param' op result type 'i64' does not match the type 'i32' of the simulation's max_steps}}
    %p = sim.get_param @max_steps : i64
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// expected-error @+1 {{'sim.get_param' op must be inside a num_steps, evaluate, init or exact body}}
%L = sim.get_param @L : i32

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  // expected-error @+1 {{'sim.get_param' op must be inside a num_steps, evaluate, init or exact body}}
  %L = sim.get_param @L : i32
}

// -----

//===----------------------------------------------------------------------===//
// sim.big_step
//===----------------------------------------------------------------------===//

// expected-error @+1 {{'sim.big_step' op must be inside a component's num_steps or evaluate body}}
%T, %m = sim.big_step : i64, i64

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    // expected-error @+1 {{'sim.big_step' op must be inside a component's num_steps or evaluate body}}
    %T, %m = sim.big_step : i64, i64
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
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
    // expected-error @+1 {{'sim.big_step' op result #0 must be 64-bit signless integer, but got 'i32'}}
    %T, %m = sim.big_step : i32, i64
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

//===----------------------------------------------------------------------===//
// sim.yield
//===----------------------------------------------------------------------===//

// expected-error @+1 {{'sim.yield' op expects parent op to be one of 'sim.buffer, sim.component, sim.fill_cache, sim.total'}}
sim.yield

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
    %r = scf.execute_region -> f32 {
      // expected-error @+1 {{'sim.yield' op expects parent op to be one of 'sim.buffer, sim.component, sim.fill_cache, sim.total'}}
      sim.yield %x : f32
    }
    sim.yield %r : f32
  }
}

// -----

// A yield that is not the last operation: the body's owner reports it.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to end in 'sim.yield'}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
    %d = arith.constant 1.0 : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}
