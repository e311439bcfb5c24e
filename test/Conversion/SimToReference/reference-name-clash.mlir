// The reference lowering puts the body functions of simulation @X in a
// builtin.module @X_reference. Another top-level symbol of that name is an
// error at that symbol, with a note at the simulation, before anything is
// lowered (it was the symbol table's "redefinition of symbol named
// 'X_reference'", which named neither the simulation nor what to rename).
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-reference-pipeline

// expected-note @+1 {{the simulation is here}}
sim.simulation @decay range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %h = arith.mulf %x, %dt : f32
    %x1 = arith.subf %x, %h : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// expected-error @+1 {{simulation @decay needs the name 'decay_reference' for its reference functions (--sim-lower-to-reference puts them in a module of that name); rename this symbol}}
func.func private @decay_reference()

// -----

// The other symbol is a simulation: its own module is @decay_reference_reference.
// expected-note @+1 {{the simulation is here}}
sim.simulation @decay range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %h = arith.mulf %x, %dt : f32
    %x1 = arith.subf %x, %h : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// expected-error @+1 {{simulation @decay needs the name 'decay_reference' for its reference functions (--sim-lower-to-reference puts them in a module of that name); rename this symbol}}
sim.simulation @decay_reference range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %h = arith.mulf %x, %dt : f32
    %x1 = arith.subf %x, %h : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// -----

// Every clash is reported, not only the first.
// expected-note @+1 {{the simulation is here}}
sim.simulation @a range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %h = arith.mulf %x, %dt : f32
    %x1 = arith.subf %x, %h : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// expected-note @+1 {{the simulation is here}}
sim.simulation @"b c" range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Decay writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %h = arith.mulf %x, %dt : f32
    %x1 = arith.subf %x, %h : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// expected-error @+1 {{simulation @a needs the name 'a_reference' for its reference functions (--sim-lower-to-reference puts them in a module of that name); rename this symbol}}
func.func private @a_reference()

// expected-error @+1 {{simulation @"b c" needs the name 'b c_reference' for its reference functions (--sim-lower-to-reference puts them in a module of that name); rename this symbol}}
memref.global "private" @"b c_reference" : memref<4xf32>
