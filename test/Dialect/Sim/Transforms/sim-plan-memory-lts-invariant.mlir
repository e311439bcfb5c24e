// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality="remarks=false" --sim-plan-memory=strategy=lts --verify-diagnostics | FileCheck %s

// invariant_levels: a local_steps component whose num_steps (and that of
// its flux writer) reads neither %t nor a buffer (each has a writer) keeps
// its blocks' levels from one big step to the next.

// num_steps from the item and a parameter: invariant. num_steps that reads
// its own state, or %t: not.

// CHECK-LABEL: sim.simulation @material
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window
// CHECK: sim.component @ByState writes(@V) attributes {advance = #sim<advance local_steps>, local_window
// CHECK: sim.component @ByTime writes(@W) attributes {advance = #sim<advance local_steps>, local_window
sim.simulation @material range(64) dt(1.0e-2 : f32) max_steps(8) {
  sim.param @scale = 3.0 : f32
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %k = arith.sitofp %i64 : i64 to f32
    %s = sim.get_param @scale : f32
    %q = arith.mulf %k, %s : f32
    %n = arith.fptosi %q : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    sim.yield %ul : f32
  }
  sim.component @ByState writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %v = sim.read @V[%i] : f32
    %n = arith.fptosi %v : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %vl = sim.read @V[%l] : f32
    sim.yield %vl : f32
  }
  sim.component @ByTime writes(@W) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.trunci %t : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %wr = sim.read @W[%r] : f32
    sim.yield %wr : f32
  }
  sim.schedule [@Diffuse, @ByState, @ByTime]
  sim.observe [@U, @V, @W]
}

// -----

// num_steps that reads a buffer another component writes: not invariant.
// A component that does not take local steps never is.

// CHECK-LABEL: sim.simulation @coupled
// CHECK: sim.component @Source writes(@S) attributes {advance = #sim<advance group_substeps>, parity
// CHECK: sim.component @Diffuse writes(@U) attributes {advance = #sim<advance local_steps>, local_window
sim.simulation @coupled range(64) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.read @S[%i] : f32
    sim.yield %s : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %s = sim.read @S[%i] : f32
    %n = arith.fptosi %s : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %ul = sim.read @U[%l] : f32
    sim.yield %ul : f32
  }
  sim.observe [@U]
}

// -----

// A flux pair: the reader's num_steps is constant, but the flux writer's
// reads the reader's state, and its estimates bound the reader's blocks:
// not invariant. With a constant flux writer estimate it would be.

// CHECK-LABEL: sim.simulation @flux_by_state
// CHECK: sim.component @Flux writes(@F) attributes {advance = #sim<advance local_flux>
// CHECK: sim.component @Cells writes(@U) attributes {advance = #sim<advance local_steps>, local_window
sim.simulation @flux_by_state range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    %u = sim.read @U[%j] : f32
    %n = arith.fptosi %u : f32 to i32
    sim.yield %n : i32
  } evaluate {
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

// The same pair with constant estimates on both sides: invariant.

// CHECK-LABEL: sim.simulation @flux_constant
// CHECK: sim.component @Cells writes(@U) attributes {advance = #sim<advance local_steps>, invariant_levels, local_window
sim.simulation @flux_constant range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    %c3 = arith.constant 3 : i32
    sim.yield %c3 : i32
  } evaluate {
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
