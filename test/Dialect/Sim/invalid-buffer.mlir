// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of sim.buffer: element types, init and exact bodies, interpolation
// auxiliary buffers, writers and initial-state cycles.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'i32'}}
  sim.buffer @B : i32 init {
  ^bb0(%i: index):
    %c = arith.constant 0 : i32
    sim.yield %c : i32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'f16'}}
  sim.buffer @B : f16 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f16
    sim.yield %c : f16
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'vector<4xi32>'}}
  sim.buffer @B : vector<4xi32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0> : vector<4xi32>
    sim.yield %c : vector<4xi32>
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'vector<17xf32>'}}
  sim.buffer @B : vector<17xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<17xf32>
    sim.yield %c : vector<17xf32>
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'vector<9223372036854775807xf32>'}}
  sim.buffer @B : vector<9223372036854775807xf32> init {
  ^bb0(%i: index):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'vector<2x2xf32>'}}
  sim.buffer @B : vector<2x2xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2x2xf32>
    sim.yield %c : vector<2x2xf32>
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects an element type of f32, f64, or a vector of 1 to 16 of them, but got 'vector<[4]xf32>'}}
  sim.buffer @B : vector<[4]xf32> init {
  ^bb0(%i: index):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op region #0 ('init') failed to verify constraint: region with 1 blocks}}
  sim.buffer @B : f32 init {
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op region #0 ('init') failed to verify constraint: region with 1 blocks}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  ^bb1:
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to have arguments (index), but it has ()}}
  sim.buffer @B : f32 init {
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to have arguments (index), but it has ('i64')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: i64):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to have arguments (index), but it has ('index', 'f64')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index, %t: f64):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to end in 'sim.yield'}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to end in 'sim.yield'}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
  }
}

// -----

// An empty block in the generic form: must be diagnosed, not crash.
"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32, max_steps = 1 : i32}> ({
  // expected-error @+1 {{'sim.buffer' op expects the init body to end in 'sim.yield'}}
  "sim.buffer"() <{sym_name = "B", element_type = f32}> ({
  ^bb0(%i: index):
  }, {
  }) : () -> ()
}) : () -> ()

// -----

// expected-error @+1 {{'sim.buffer' op expected 2 regions}}
"sim.buffer"() <{sym_name = "B", element_type = f32}> ({
^bb0(%i: index):
  %c = "arith.constant"() <{value = 0.0 : f32}> : () -> f32
  "sim.yield"(%c) : (f32) -> ()
}) : () -> ()

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to yield one value of the element type 'f32', but it yields ('f64')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to yield one value of the element type 'vector<4xf32>', but it yields ()}}
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the init body to yield one value of the element type 'f32', but it yields ('f32', 'f32')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c, %c : f32, f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the exact body to have arguments (index, f64), but it has ('index', 'f32')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index, %t: f32):
    sim.yield %t : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the exact body to have arguments (index, f64), but it has ('index')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the exact body to end in 'sim.yield'}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %c = arith.constant 0.0 : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects the exact body to yield one value of the element type 'f32', but it yields ('f64')}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    sim.yield %t : f64
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op region #1 ('exact') failed to verify constraint: region with at most 1 blocks}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  ^bb1:
    %d = arith.constant 0.0 : f32
    sim.yield %d : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op cannot be its own derivative buffer in its interpolation #sim.hermite<@B>}}
  sim.buffer @B : f32 interp(#sim.hermite<@B>) init {
  ^bb0(%i: index):
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
  // expected-error @+1 {{'sim.buffer' op names @V as the derivative buffer of its interpolation, but the simulation has no such buffer}}
  sim.buffer @B : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
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

// The derivative must be a buffer, not another kind of symbol.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @V = 1.0 : f32
  // expected-error @+1 {{'sim.buffer' op names @V as the derivative buffer of its interpolation, but the simulation has no such buffer}}
  sim.buffer @B : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
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
  // expected-error @+1 {{'sim.buffer' op has element type 'vector<3xf32>', but its derivative buffer @V has element type 'vector<3xf64>'; they must match}}
  sim.buffer @X : vector<3xf32> interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<3xf32>
    sim.yield %c : vector<3xf32>
  }
  sim.buffer @V : vector<3xf64> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<3xf64>
    sim.yield %c : vector<3xf64>
  }
  sim.component @C writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : vector<3xf32>
    %v = sim.read @V[%i] : vector<3xf64>
    sim.yield %x, %v : vector<3xf32>, vector<3xf64>
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op is not written by any component; every buffer needs exactly one writer, or is declared 'constant' when its init gives its value at every time}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op has an initial state that depends on itself through the init bodies of @A -> @B -> @C -> @A}}
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %x = sim.read @C[%i] : f32
    sim.yield %x : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  sim.component @W writes(@A, @B, @C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x, %x, %x : f32, f32, f32
  }
}

// -----

// Symbol names are unique across buffers, components and parameters.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-note @+1 {{see existing symbol definition here}}
  sim.param @B = 1.0 : f32
  // expected-error @+1 {{redefinition of symbol named 'B'}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

// expected-error @+1 {{'sim.buffer' op expects parent op 'sim.simulation'}}
sim.buffer @B : f32 init {
^bb0(%i: index):
  %c = arith.constant 0.0 : f32
  sim.yield %c : f32
}

// -----

// A constant buffer: no writer, no interpolation, no exact body, not
// observed, and no buffer's Hermite derivative.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-note @+1 {{@K is declared constant here}}
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.component' op writes buffer @K, which is declared constant; remove 'constant' from @K or this component's writes entry}}
  sim.component @C writes(@K) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %k = sim.read @K[%i] : f32
    sim.yield %k : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op is constant, so it takes no interp(...) clause: its value is its init at every time, with nothing to interpolate}}
  sim.buffer @K : f32 constant interp(#sim.cubic) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op is constant, so it takes no exact body: its init is its value at every time}}
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-note @+1 {{@K is declared constant here}}
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %k = sim.read @K[%i] : f32
    sim.yield %k : f32
  }
  // expected-error @+1 {{'sim.observe' op observes @K, which is constant: no run changes it, and no backend stores it (its init is computed where it is read); observe the buffers components write, or a sim.total}}
  sim.observe [@U, @K]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{'sim.buffer' op names the constant buffer @K as the derivative buffer of its interpolation; the derivative of a buffer a component writes changes with it: write @K in the same component}}
  sim.buffer @U : f32 interp(#sim.hermite<@K>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %k = sim.read @K[%i] : f32
    sim.yield %k : f32
  }
}
