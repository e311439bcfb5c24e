// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of sim.simulation and sim.param: the header values, what the body
// may hold, nesting, and parameter values and names.

// expected-error @+1 {{'sim.simulation' op expects a positive item range, but got 0}}
sim.simulation @s range(0) dt(1.0 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a positive item range, but got -5}}
sim.simulation @s range(-5) dt(1.0 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects an item range of at most 2^40, but got 1099511627777}}
sim.simulation @s range(1099511627777) dt(1.0 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects max_steps to be at least 1, but got 0}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(0) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects max_steps to be at least 1, but got -3}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(-3) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects max_steps to be at most 2^20, but got 1048577}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1048577) {
}

// -----

// A value beyond 32 bits is no wrapped i32: the parser names it as written.
// expected-error @+1 {{expects max_steps to be at most 2^20, but got 3000000000}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(3000000000) {
}

// -----

// expected-error @+1 {{expects max_steps to be at least 1, but got -3000000000}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(-3000000000) {
}

// -----

// expected-error @+1 {{'sim.simulation' op has a step_cap of 4, but a big step takes 1 to max_steps (3) base steps}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(3) attributes {step_cap = 4 : i32} {
}

// -----

// expected-error @+1 {{'sim.simulation' op has a step_cap of 0, but a big step takes 1 to max_steps (3) base steps}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(3) attributes {step_cap = 0 : i32} {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a positive, finite base time step dt, but got 0.000000e+00}}
sim.simulation @s range(16) dt(0.0 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a positive, finite base time step dt, but got -2.500000e+00}}
sim.simulation @s range(16) dt(-2.5 : f64) max_steps(1) {
}

// -----

// A subnormal dt is no time step: the runtime refuses to set one too.
// expected-error @+1 {{'sim.simulation' op expects a base time step dt that is a normal 'f32' value, but got 9.999946e-41, which is subnormal; give a larger dt}}
sim.simulation @s range(16) dt(1.0e-40 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a base time step dt that is a normal 'f64' value, but got 9.999889e-321, which is subnormal; give a larger dt}}
sim.simulation @s range(16) dt(1.0e-320 : f64) max_steps(1) {
}

// -----

// The smallest normal values are taken.
sim.simulation @s range(16) dt(1.17549435e-38 : f32) max_steps(1) {
}

// -----

sim.simulation @s range(16) dt(2.2250738585072014e-308 : f64) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a positive, finite base time step dt, but got nan}}
sim.simulation @s range(16) dt(0x7FC00000 : f32) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op expects a positive, finite base time step dt, but got INF}}
sim.simulation @s range(16) dt(0x7FF0000000000000 : f64) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op attribute 'dt' failed to satisfy constraint: 32-bit float attribute or 64-bit float attribute}}
sim.simulation @s range(16) dt(1.0 : f16) max_steps(1) {
}

// -----

// expected-error @+1 {{'sim.simulation' op attribute 'dt' failed to satisfy constraint: 32-bit float attribute or 64-bit float attribute}}
sim.simulation @s range(16) dt(1 : i32) max_steps(1) {
}

// -----

// The generic form can leave the body without a block.
// expected-error @+1 {{'sim.simulation' op region #0 ('body') failed to verify constraint: region with 1 blocks}}
"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32, max_steps = 1 : i32}> ({
}) : () -> ()

// -----

// expected-error @+1 {{'sim.simulation' op requires attribute 'max_steps'}}
"sim.simulation"() <{sym_name = "s", range = 16 : i64, dt = 1.0 : f32}> ({
^bb0:
}) : () -> ()

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'arith.constant' cannot appear directly in a simulation; it holds only sim.param, sim.buffer, sim.component, sim.total, sim.schedule and sim.observe}}
  %c = arith.constant 0 : i32
}

// -----

// expected-note @+1 {{the enclosing simulation is here}}
sim.simulation @outer range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.simulation' op cannot be nested inside another simulation}}
  sim.simulation @inner range(16) dt(1.0 : f32) max_steps(1) {
  }
}

// -----

sim.simulation @outer range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'sim.simulation' op symbol's parent must have the SymbolTable trait}}
    sim.simulation @inner range(16) dt(1.0 : f32) max_steps(1) {
    }
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A simulation nested behind an op that opens a symbol table.
// expected-note @+1 {{the enclosing simulation is here}}
sim.simulation @outer range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    builtin.module {
      // expected-error @+1 {{'sim.simulation' op cannot be nested inside another simulation}}
      sim.simulation @inner range(16) dt(1.0 : f32) max_steps(1) {
      }
    }
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A simulation in a nested module: the passes nest on the simulations of
// the top-level module and sim-translate looks for them there, so it was
// left as written, without a word.
module {
  // expected-note @+1 {{the enclosing op is here}}
  module @inner {
    // expected-error @+1 {{'sim.simulation' op must be directly in the top-level module, where the passes and sim-translate look for simulations, not in a nested 'builtin.module' @inner; move it to the top level}}
    sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
    }
  }
}

// -----

// The same beside a simulation at the top level (which is valid), in an
// unnamed module.
sim.simulation @top range(16) dt(1.0 : f32) max_steps(1) {
}
// expected-note @+1 {{the enclosing op is here}}
module {
  // expected-error @+1 {{'sim.simulation' op must be directly in the top-level module, where the passes and sim-translate look for simulations, not in a nested 'builtin.module'; move it to the top level}}
  sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  }
}

// -----

// Nor in a gpu.module, which opens a symbol table too.
// expected-note @+1 {{the enclosing op is here}}
gpu.module @kernels {
  // expected-error @+1 {{'sim.simulation' op must be directly in the top-level module, where the passes and sim-translate look for simulations, not in a nested 'gpu.module' @kernels; move it to the top level}}
  sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-note @+1 {{see existing symbol definition here}}
  sim.param @L = 1 : i32
  // expected-error @+1 {{redefinition of symbol named 'L'}}
  sim.param @L = 2 : i32
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.param' op expects an integer or float default value, but got "fast"}}
  sim.param @mode = "fast"
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.param' op expects an integer or float default value, but got 1 : ui32}}
  sim.param @L = 1 : ui32
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.param' op expects an integer or float default value, but got dense<1> : vector<2xi32>}}
  sim.param @L = dense<1> : vector<2xi32>
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.param' invalid kind of attribute specified}}
  sim.param @L = @other
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.param' op cannot be named 'dt': range, dt and max_steps name the simulation's own attributes}}
  sim.param @dt = 1.0 : f32
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.param' op cannot be named 'range': range, dt and max_steps name the simulation's own attributes}}
  sim.param @range = 1 : i64
}

// -----

// expected-error @+1 {{'sim.param' op expects parent op 'sim.simulation'}}
sim.param @L = 1 : i32

// -----

// The distributed decisions (--sim-plan-halos) count ghost items.
// expected-error @+1 {{'sim.simulation' op has a distributed_halo of -3 items; it must be 0 or more}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {distributed_halo = -3 : i64} {
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects a halo of two counts of items (below and above), 0 or more}}
  sim.buffer @B : f32 attributes {halo = array<i64: -5, 1>} init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{'sim.buffer' op expects a halo of two counts of items (below and above), 0 or more}}
  sim.buffer @B : f32 attributes {halo = array<i64: 1, 1, 1>} init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}
