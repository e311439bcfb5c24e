// RUN: sim-opt %s --split-input-file --sim-substep-legality --verify-diagnostics | FileCheck %s

// Flux pairs (docs/Model.md, "Conservation"): the first component of the
// step writes only #sim.flux buffers, one component reads them through
// windows and writes what the first reads. The pass records flux_window on
// the writer and widens the reader's local_window, or says in a remark on
// the writer which rule fails.

// A flux pair: @Flux writes only the #sim.flux @F, which @Cells alone reads
// at i-1..i; @Flux reads @U at i..i+1. flux_window [-1, 0] and
// local_window [0, 1] (where it reads the reader's state) on the writer,
// local_window [-1, 1] (through the fluxes) on the reader.

// CHECK-LABEL: sim.simulation @pair
// CHECK: sim.component @Flux writes(@F) attributes {flux_window = array<i64: -1, 0>, local_window = array<i64: 0, 1>, sub_stepping = #sim<sub_stepping in_kernel>}
// CHECK: sim.component @Cells writes(@U) attributes {local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping in_kernel>}

sim.simulation @pair range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{@Flux and @Cells form a flux pair: under lts every interface of its fluxes steps with the coarsest block that reads it (at i-1..i), and @Cells's blocks take local time steps (window i-1..i+1)}}
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

// The reader is the first component of the step: no pair.

// CHECK-LABEL: sim.simulation @reader_first
// CHECK: sim.component @Flux writes(@F) attributes {sub_stepping
// CHECK: sim.component @Cells writes(@U) attributes {sub_stepping

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
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: it is not the first component of the step; name it first in sim.schedule so that it reads @Cells's state through the back edge}}
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
  sim.schedule [@Cells]
  sim.observe [@U]
}

// -----

// The same with the cells bounding the big step (as --sim-schedule records
// it): the cells and the flux writer have the shape of an item pair too,
// but only the flux pair's remark comes, since advice to read the cells'
// state @U only at the own item would mislead.

// CHECK-LABEL: sim.simulation @reader_first_bounding
// CHECK-NOT: flux_window

sim.simulation @reader_first_bounding range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: it is not the first component of the step; name it first in sim.schedule so that it reads @Cells's state through the back edge}}
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
  sim.schedule [@Cells, @Flux] bounded_by [@Cells]
  sim.observe [@U]
}

// -----

// Two components read the fluxes: no pair.

// CHECK-LABEL: sim.simulation @two_readers
// CHECK-NOT: flux_window

sim.simulation @two_readers range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: both @Cells and @Other read its fluxes; a flux pair has one reader, which updates the conserved state}}
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
  sim.component @Other writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %u = sim.read @V[%i] : f32
    %d = arith.subf %fe, %fw : f32
    %s = arith.mulf %d, %dt : f32
    %r = arith.addf %u, %s : f32
    sim.yield %r : f32
  }
  sim.schedule [@Flux]
  sim.observe [@U, @V]
}

// -----

// The reader reads the fluxes through a gather: no pair.

// CHECK-LABEL: sim.simulation @gather
// CHECK-NOT: flux_window

sim.simulation @gather range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: @Cells reads @F through a gather; the items that share an interface must be known: read it through a window (%i plus a bounded offset, or an index clamped to %i - w .. %i + w with arith.maxsi and arith.minsi)}}
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
    %g = arith.muli %i, %il : index
    %fw = sim.read @F[%g] : f32
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

// The writer writes a buffer that is not a flux too: no pair.

// CHECK-LABEL: sim.simulation @mixed
// CHECK-NOT: flux_window

sim.simulation @mixed range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: it also writes @W, which is not #sim.flux; a flux writer writes only fluxes (move @W to another component)}}
  sim.component @Flux writes(@F, @W) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %a = sim.read @U[%j] : f32
    %b = sim.read @U[%jr] : f32
    %d = arith.subf %b, %a : f32
    sim.yield %d, %d : f32, f32
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
  sim.observe [@U, @W]
}

// -----

// Neither the writer nor the reader has num_steps: no pair.

// CHECK-LABEL: sim.simulation @no_estimate
// CHECK-NOT: flux_window

sim.simulation @no_estimate range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: neither @Flux nor @Cells has num_steps, so the blocks have no step of their own}}
  sim.component @Flux writes(@F) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %a = sim.read @U[%j] : f32
    %b = sim.read @U[%jr] : f32
    %d = arith.subf %b, %a : f32
    sim.yield %d : f32
  }
  sim.component @Cells writes(@U) evaluate {
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

// Two fluxes with different boundary rules: no pair.

// CHECK-LABEL: sim.simulation @boundaries
// CHECK-NOT: flux_window

sim.simulation @boundaries range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  sim.buffer @G : f32 interp(#sim.flux) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: its fluxes @F and @G have different boundary rules; give them one}}
  sim.component @Flux writes(@F, @G) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %a = sim.read @U[%j] : f32
    %b = sim.read @U[%jr] : f32
    %d = arith.subf %b, %a : f32
    sim.yield %d, %d : f32, f32
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
    %u0 = sim.read @U[%i] : f32
    %gg = sim.read @G[%i] : f32
    %u = arith.addf %u0, %gg : f32
    %d = arith.subf %fe, %fw : f32
    %s = arith.mulf %d, %dt : f32
    %r = arith.addf %u, %s : f32
    sim.yield %r : f32
  }
  sim.schedule [@Flux]
  sim.observe [@U]
}

// -----

// Clamped fluxes still form a pair, with a remark: the interface read past
// an end of the range repeats the last one, which does not conserve.

// CHECK-LABEL: sim.simulation @clamped
// CHECK: sim.component @Flux writes(@F) attributes {flux_window = array<i64: -1, 0>
sim.simulation @clamped range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@F has boundary(clamp): @Cells's reads at i-1..i past an end of the range take the last interface again, which no cell gives back, so a total of @Cells's state is not conserved; boundary(zero) closes the ends, boundary(wrap) makes a ring}}
  sim.buffer @F : f32 interp(#sim.flux) boundary(clamp) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Flux and @Cells form a flux pair: under lts every interface of its fluxes steps with the coarsest block that reads it (at i-1..i), and @Cells's blocks take local time steps (window i-1..i+1)}}
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

// A reader of fluxes 4096 items apart or more: no pair (every interface
// would bound the blocks of thousands of readers). 4095 apart still pairs.

// CHECK-LABEL: sim.simulation @wide_flux_window
// CHECK: sim.component @Flux writes(@F) attributes {sub_stepping
// CHECK-LABEL: sim.simulation @widest_flux_window
// CHECK: sim.component @Flux writes(@F) attributes {flux_window = array<i64: -4095, 0>

sim.simulation @wide_flux_window range(8192) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{under lts @Flux and the readers of its fluxes take the big step as under hip: @Cells reads its fluxes at i-4096..i, more than 4096 items apart; read them within 4096 items of the reading item}}
  sim.component @Flux writes(@F) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @U[%j] : f32
    sim.yield %a : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %far = arith.constant 4096 : index
    %il = arith.subi %i, %far : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %d = arith.subf %fe, %fw : f32
    sim.yield %d : f32
  }
  sim.schedule [@Flux]
  sim.observe [@U]
}

sim.simulation @widest_flux_window range(8192) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark @+1 {{@Flux and @Cells form a flux pair}}
  sim.component @Flux writes(@F) evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @U[%j] : f32
    sim.yield %a : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %far = arith.constant 4095 : index
    %il = arith.subi %i, %far : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %d = arith.subf %fe, %fw : f32
    sim.yield %d : f32
  }
  sim.schedule [@Flux]
  sim.observe [@U]
}
