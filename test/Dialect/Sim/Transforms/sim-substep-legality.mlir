// RUN: sim-opt %s --split-input-file --sim-substep-legality --verify-diagnostics | FileCheck %s

// Own item only (also through a second written buffer): in_kernel, no remark.
// Neighbour reads of other buffers do not matter.

// CHECK-LABEL: sim.simulation @legal
// CHECK: sim.component @Integrate writes(@X, @V) attributes {sub_stepping = #sim<sub_stepping in_kernel>}
// CHECK: sim.component @Smooth writes(@S) attributes {sub_stepping = #sim<sub_stepping in_kernel>}
sim.simulation @legal range(16) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Integrate writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %x1 = arith.addf %x, %v : f32
    sim.yield %x1, %v : f32, f32
  }
  sim.component @Smooth writes(@S) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %x = sim.read @X[%j] : f32
    %s = sim.read @S[%i] : f32
    %r = arith.addf %x, %s : f32
    sim.yield %r : f32
  }
  sim.observe [@S]
}

// -----

// A window read of the own buffer (a stencil on its own state): grid_sync.

// CHECK-LABEL: sim.simulation @own_window
// CHECK: sim.component @Diffuse writes(@U) attributes {local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @own_window range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Diffuse needs a grid-wide barrier between sub-steps: its evaluate body reads @U, which it writes, at i-1..i+1, so a thread could read another item while that item is between sub-steps}}
  sim.component @Diffuse writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %ur = sim.read @U[%r] : f32
    %s = arith.addf %ul, %ur : f32
    %d = arith.subf %s, %u : f32
    sim.yield %d : f32
  }
  sim.observe [@U]
}

// -----

// A gather of the second buffer a component writes, in num_steps.

// CHECK-LABEL: sim.simulation @own_gather
// CHECK: sim.component @P writes(@X, @V) attributes {local_window = array<i64: 0, 0>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @own_gather range(16) dt(1.0e-2 : f32) max_steps(2) {
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
  // expected-remark @+1 {{@P needs a grid-wide barrier between sub-steps: its num_steps body reads @V, which it writes, through a gather, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i)}}
  sim.component @P writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c7 = arith.constant 7 : index
    %j = arith.muli %i, %c7 : index
    // expected-note @+1 {{reads @V through a gather}}
    %v = sim.read @V[%j] : f32
    %n = arith.fptosi %v : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    sim.yield %x, %v : f32, f32
  }
  sim.observe [@X]
}
