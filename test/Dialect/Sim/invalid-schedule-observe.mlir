// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of sim.schedule and sim.observe: the symbols they list, and at most
// one of each per simulation. Every case uses the same two buffers @B0, @B1
// and their writers @C0, @C1.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op expects at least the component that starts a step}}
  sim.schedule []
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @C2 in order, but it is not a sim.component of this simulation}}
  sim.schedule [@C0, @C2]
}

// -----

// A buffer is not a component.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @B0 in order, but it is not a sim.component of this simulation}}
  sim.schedule [@B0]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @C0 twice in order}}
  sim.schedule [@C0, @C1, @C0]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @X in bounded_by, but it is not a sim.component of this simulation}}
  sim.schedule [@C0, @C1] bounded_by [@X]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @C1 twice in bounded_by}}
  sim.schedule [@C0, @C1] bounded_by [@C1, @C1]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op lists @C0 in bounded_by, but it has no num_steps body, so it never bounds a step}}
  sim.schedule [@C0] bounded_by [@C0]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-note @+1 {{the first schedule is here}}
  sim.schedule [@C0]
  // expected-error @+1 {{'sim.schedule' op is the second schedule of this simulation; a simulation has at most one}}
  sim.schedule [@C1]
}

// -----

// Names are flat symbols of the simulation.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.schedule' op attribute 'order' failed to satisfy constraint: flat symbol ref array attribute}}
  sim.schedule [@s::@C0]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.observe' op expects at least one observed buffer}}
  sim.observe []
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.observe' op lists @B2 in observe, but it is not a sim.buffer of this simulation}}
  sim.observe [@B0, @B2]
}

// -----

// A component is not a buffer.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.observe' op lists @C0 in observe, but it is not a sim.buffer of this simulation}}
  sim.observe [@C0]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.observe' op lists @B1 twice in observe}}
  sim.observe [@B1, @B0, @B1]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-note @+1 {{the first observe list is here}}
  sim.observe [@B0]
  // expected-error @+1 {{'sim.observe' op is the second observe list of this simulation; list all observed buffers in one}}
  sim.observe [@B1]
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  // expected-error @+1 {{'sim.observe' op attribute 'buffers' failed to satisfy constraint: flat symbol ref array attribute}}
  sim.observe [@s::@B0]
}

// -----

// expected-error @+1 {{'sim.schedule' op expects parent op 'sim.simulation'}}
sim.schedule [@C0]

// -----

// expected-error @+1 {{'sim.observe' op expects parent op 'sim.simulation'}}
sim.observe [@B0]
