// The GPU lowering puts the kernels of simulation @X in a gpu.module
// @X_kernels. Another top-level symbol of that name is an error at that
// symbol, with a note at the simulation, before anything is lowered (it was
// the symbol table's "redefinition of symbol named 'X_kernels'", which
// named neither the simulation nor what to rename).
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --sim-front-end=strategy=hip --sim-lower-to-gpu

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

// expected-error @+1 {{simulation @decay needs the name 'decay_kernels' for its kernels (--sim-lower-to-gpu puts them in a module of that name); rename this symbol}}
func.func private @decay_kernels()

// -----

// The other symbol is a simulation: its own module is @decay_kernels_kernels.
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

// expected-error @+1 {{simulation @decay needs the name 'decay_kernels' for its kernels (--sim-lower-to-gpu puts them in a module of that name); rename this symbol}}
sim.simulation @decay_kernels range(16) dt(1.0e-2 : f32) max_steps(2) {
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

// expected-error @+1 {{simulation @a needs the name 'a_kernels' for its kernels (--sim-lower-to-gpu puts them in a module of that name); rename this symbol}}
func.func private @a_kernels()

// expected-error @+1 {{simulation @"b c" needs the name 'b c_kernels' for its kernels (--sim-lower-to-gpu puts them in a module of that name); rename this symbol}}
memref.global "private" @"b c_kernels" : memref<4xf32>
