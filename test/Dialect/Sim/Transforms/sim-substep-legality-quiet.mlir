// RUN: sim-opt %s --split-input-file --sim-substep-legality="remarks=false" --verify-diagnostics | FileCheck %s

// remarks=false (the front end of simple and traditional, a bundle's
// reference lowering): the same verdicts, windows and flux pairs are
// recorded, and only the remark that holds under every strategy (clamped
// fluxes do not conserve) is emitted.

// A window and a gather of the component's own buffer: grid_sync, with and
// without local_window, and no remark.

// CHECK-LABEL: sim.simulation @verdicts
// CHECK: sim.component @Diffuse writes(@U) attributes {local_window = array<i64: -2, 0>, sub_stepping = #sim<sub_stepping grid_sync>}
// CHECK: sim.component @Scatter writes(@G) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @verdicts range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @G : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c3 = arith.constant 3 : index
    %j = arith.addi %i, %c3 : index
    %u = sim.read @U[%j] : f32
    %n = arith.fptosi %u : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c2 = arith.constant 2 : index
    %j = arith.subi %i, %c2 : index
    %u = sim.read @U[%i] : f32
    %l = sim.read @U[%j] : f32
    %r = arith.addf %u, %l : f32
    sim.yield %r : f32
  }
  sim.component @Scatter writes(@G) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c7 = arith.constant 7 : index
    %j = arith.muli %i, %c7 : index
    %g = sim.read @G[%j] : f32
    sim.yield %g : f32
  }
  sim.observe [@U, @G]
}

// -----

// A flux pair with clamped fluxes: the pair is recorded without its
// remark; the conservation remark stays.

// CHECK-LABEL: sim.simulation @clamped
// CHECK: sim.component @Flux writes(@F) attributes {flux_window = array<i64: -1, 0>, local_window = array<i64: 0, 1>, sub_stepping = #sim<sub_stepping in_kernel>}
// CHECK: sim.component @Cells writes(@U) attributes {local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping in_kernel>}
sim.simulation @clamped range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@F has boundary(clamp): @Cells's reads at i-1..i past an end of the range take the last interface again, which no cell gives back, so a total of @Cells's state is not conserved}}
  sim.buffer @F : f32 interp(#sim.flux) boundary(clamp) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Flux writes(@F) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %a = sim.read @U[%j] : f32
    %b = sim.read @U[%jr] : f32
    %d = arith.subf %b, %a : f32
    sim.yield %d : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %u = sim.read @U[%i] : f32
    %d = arith.subf %fe, %fw : f32
    %s = arith.mulf %d, %dt : f32
    %r = arith.addf %u, %s : f32
    sim.yield %r : f32
  }
  sim.schedule [@Flux]
  sim.observe [@U]
}

// -----

// A flux writer that is not first: no pair, and no remark saying so.

// CHECK-LABEL: sim.simulation @reader_first
// CHECK: sim.component @Flux writes(@F) attributes {sub_stepping = #sim<sub_stepping in_kernel>}
sim.simulation @reader_first range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Flux writes(@F) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %a = sim.read @U[%j] : f32
    %b = sim.read @U[%jr] : f32
    %d = arith.subf %b, %a : f32
    sim.yield %d : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %u = sim.read @U[%i] : f32
    %d = arith.subf %fe, %fw : f32
    %s = arith.mulf %d, %dt : f32
    %r = arith.addf %u, %s : f32
    sim.yield %r : f32
  }
  sim.schedule [@Cells, @Flux]
  sim.observe [@U]
}
