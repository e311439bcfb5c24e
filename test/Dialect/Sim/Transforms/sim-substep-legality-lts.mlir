// RUN: sim-opt %s --split-input-file --sim-substep-legality --verify-diagnostics | FileCheck %s

// Whether a grid_sync component may take local time steps under lts: the
// joined window of its reads of its own buffers at other items is recorded
// as local_window, or the remark says what prevents it.

// A window in num_steps and evaluate: only evaluate's counts,
// local_window [-2, 0]. num_steps runs at T, where every block is: its
// reads see no level boundary (under hip it runs at every sub-step, so its
// read at i+3 makes the component grid_sync).

// CHECK-LABEL: sim.simulation @window
// CHECK: sim.component @Diffuse writes(@U) attributes {local_window = array<i64: -2, 0>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @window range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Diffuse needs a grid-wide barrier between sub-steps: its num_steps body reads @U, which it writes, at i+3, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i-2..i)}}
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c3 = arith.constant 3 : index
    %j = arith.addi %i, %c3 : index
    // expected-note @+1 {{reads @U at i+3}}
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
  sim.observe [@U]
}

// -----

// A gather of its own buffer: no local_window.

// CHECK-LABEL: sim.simulation @gather
// CHECK: sim.component @Scatter writes(@U) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @gather range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts it cannot take local time steps: its evaluate body reads @U through a gather, so the blocks it reads are not known; a window (%i plus a bounded offset, or an index clamped to %i - w .. %i + w with arith.maxsi and arith.minsi) lets the levels of neighbouring blocks be limited}}
  sim.component @Scatter writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c7 = arith.constant 7 : index
    %j = arith.muli %i, %c7 : index
    // expected-note @+1 {{reads @U through a gather}}
    %g = sim.read @U[%j] : f32
    sim.yield %g : f32
  }
  sim.observe [@U]
}

// -----

// The same gather clamped around the item (a neighbour list given a
// reach) is a window: local_window [-40, 3], wider than a block.

// CHECK-LABEL: sim.simulation @clamped_gather
// CHECK: sim.component @Scatter writes(@U) attributes {local_window = array<i64: -40, 3>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @clamped_gather range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Scatter needs a grid-wide barrier between sub-steps: its evaluate body reads @U, which it writes, at i-40..i+3, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i-40..i+3)}}
  sim.component @Scatter writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c7 = arith.constant 7 : index
    %c40 = arith.constant 40 : index
    %c3 = arith.constant 3 : index
    %j = arith.muli %i, %c7 : index
    %below = arith.subi %i, %c40 : index
    %above = arith.addi %i, %c3 : index
    %atLeast = arith.maxsi %j, %below : index
    %k = arith.minsi %above, %atLeast : index
    // expected-note @+1 {{reads @U at i-40..i+3}}
    %g = sim.read @U[%k] : f32
    sim.yield %g : f32
  }
  sim.observe [@U]
}

// -----

// A neighbour wrapped around by hand, (%i + 1) mod 64: a gather, and the
// remark names the window that boundary(wrap) gives instead.

// CHECK-LABEL: sim.simulation @wrapped_by_hand
// CHECK: sim.component @Ring writes(@U) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @wrapped_by_hand range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{a window (%i plus a bounded offset, or an index clamped to %i - w .. %i + w with arith.maxsi and arith.minsi) lets the levels of neighbouring blocks be limited; the index wraps %i + 1 around the range by hand: with boundary(wrap) on @U, @U[%i + 1] reads the same item (where the divisor is the range) as a window}}
  sim.component @Ring writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c64 = arith.constant 64 : index
    %right = arith.addi %i, %c1 : index
    %j = arith.remui %right, %c64 : index
    // expected-note @+1 {{reads @U through a gather}}
    %u = sim.read @U[%j] : f32
    sim.yield %u : f32
  }
  sim.observe [@U]
}

// -----

// A gather of its own buffer in num_steps only: num_steps runs at T under
// lts, so the blocks still take local time steps (grid_sync under hip).

// CHECK-LABEL: sim.simulation @estimate_gather
// CHECK: sim.component @Spread writes(@U) attributes {local_window = array<i64: -1, 0>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @estimate_gather range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Spread needs a grid-wide barrier between sub-steps: its num_steps body reads @U, which it writes, through a gather, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i-1..i)}}
  sim.component @Spread writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c5 = arith.constant 5 : index
    %j = arith.muli %i, %c5 : index
    // expected-note @+1 {{reads @U through a gather}}
    %u = sim.read @U[%j] : f32
    %n = arith.fptosi %u : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %l = sim.read @U[%j] : f32
    %r = arith.addf %u, %l : f32
    sim.yield %r : f32
  }
  sim.observe [@U]
}

// -----

// A neighbour of an interp(none) buffer: no value between time levels.

// CHECK-LABEL: sim.simulation @none
// CHECK: sim.component @Hop writes(@U) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @none range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts it cannot take local time steps: @U is interp(none), and a read of a neighbour that is ahead in time needs a value between its time levels; give @U an interpolation}}
  sim.component @Hop writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    // expected-note @+1 {{reads @U at i+1}}
    %u = sim.read @U[%j] : f32
    sim.yield %u : f32
  }
  sim.observe [@U]
}

// -----

// A neighbour of a Hermite buffer whose derivative the component writes
// too: each item keeps both at the same two time levels.

// CHECK-LABEL: sim.simulation @hermite
// CHECK: sim.component @Wave writes(@X, @V) attributes {local_window = array<i64: -1, 0>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @hermite range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Wave needs a grid-wide barrier between sub-steps: its evaluate body reads @X, which it writes, at i-1, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i-1..i)}}
  sim.component @Wave writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @X at i-1}}
    %l = sim.read @X[%j] : f32
    %v = sim.read @V[%i] : f32
    %x1 = arith.addf %l, %v : f32
    sim.yield %x1, %v : f32, f32
  }
  sim.observe [@X]
}

// -----

// Its derivative written by another component has no two time levels.

// CHECK-LABEL: sim.simulation @hermite_other_writer
// CHECK: sim.component @Wave writes(@X) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @hermite_other_writer range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Push writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  // expected-remark @+1 {{under lts it cannot take local time steps: @X's interpolation reads @V (derivative), which @Wave does not write, so it is not kept at every item's two time levels; let @Wave write @V, or use #sim.linear or #sim.cubic for @X}}
  sim.component @Wave writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @X at i-1}}
    %l = sim.read @X[%j] : f32
    %v = sim.read @V[%i] : f32
    %x1 = arith.addf %l, %v : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}

// -----

// A derivative under another boundary rule would be read at other items.

// CHECK-LABEL: sim.simulation @hermite_boundaries
// CHECK: sim.component @Wave writes(@X, @V) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @hermite_boundaries range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @V : f32 boundary(clamp) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{under lts it cannot take local time steps: @X's interpolation reads @V (derivative) at @X's items, but @V has boundary(clamp) where @X has boundary(wrap); give both one boundary rule}}
  sim.component @Wave writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @X at i-1}}
    %l = sim.read @X[%j] : f32
    %v = sim.read @V[%i] : f32
    %x1 = arith.addf %l, %v : f32
    sim.yield %x1, %v : f32, f32
  }
  sim.observe [@X]
}

// -----

// A component that bounds the big step (it reads @W through the back edge)
// takes it whole under lts too: no local_window, and the remark says why and
// which schedule would let it take local steps.

// CHECK-LABEL: sim.simulation @bounding
// CHECK: sim.component @Lead writes(@U) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @bounding range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Lead needs a grid-wide barrier between sub-steps: its evaluate body reads @U, which it writes, at i-1, so a thread could read another item while that item is between sub-steps; under lts it still takes the big step whole: it reads through the back edge, so its num_steps bounds the big step of the whole scene (per-region big steps are not built, docs/Model.md); a component that does not bound it takes local time steps: 'sim.schedule [@Follow, @Lead]' would start a step at @Follow, which then reads through the back edge, and @Lead would not bound it}}
  sim.component @Lead writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %w = sim.read @W[%i] : f32
    %s = arith.addf %ul, %w : f32
    sim.yield %s : f32
  }
  sim.component @Follow writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Lead, @Follow] bounded_by [@Lead]
  sim.observe [@W]
}

// -----

// No other entry lets @Hub take local steps: it reads what @Left and @Right
// write, and both read what it writes, so a step that starts at either has a
// cycle inside it. The remark names no schedule.

// CHECK-LABEL: sim.simulation @hub
// CHECK: sim.component @Hub writes(@U) attributes {sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @hub range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark-re @+1 {{@Hub needs a grid-wide barrier between sub-steps: {{.*}}; a component that does not bound it takes local time steps{{$}}}}
  sim.component @Hub writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %s = arith.addf %ul, %x : f32
    %r = arith.addf %s, %y : f32
    sim.yield %r : f32
  }
  sim.component @Left writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.component @Right writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Hub, @Left, @Right] bounded_by [@Hub]
  sim.observe [@U]
}

// -----

// Two stencils that read each other: whichever starts the step reads the
// other's buffer through the back edge and bounds it. Starting at @B would
// only move the bound onto @B: which start is better depends on the two
// num_steps at run time, so the remark names that order and says what it
// trades instead of suggesting it.

// CHECK-LABEL: sim.simulation @two_stencils
sim.simulation @two_stencils range(64) dt(1.0e-2 : f32) max_steps(4) {
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
  // expected-remark-re @+1 {{@A needs a grid-wide barrier between sub-steps: {{.*}}; a component that does not bound it takes local time steps; 'sim.schedule [@B, @A]' would let @A take local time steps, but @B, which reads its own neighbours too, would bound the big step instead: start the step at the component whose num_steps is the larger and varies less across items; or write @U and @V in one component (writes(@U, @V)), which reads them at its blocks' time levels and takes local time steps unless it reads another component's buffer through the back edge{{$}}}}
  sim.component @A writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @U at i-1}}
    %ul = sim.read @U[%l] : f32
    %v = sim.read @V[%i] : f32
    %s = arith.addf %ul, %v : f32
    sim.yield %s : f32
  }
  // expected-remark-re @+1 {{@B needs a grid-wide barrier between sub-steps: {{.*}}; under lts its blocks of 32 items take local time steps (window i-1..i)}}
  sim.component @B writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    // expected-note @+1 {{reads @V at i-1}}
    %vl = sim.read @V[%l] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %vl, %u : f32
    sim.yield %s : f32
  }
  sim.schedule [@A, @B] bounded_by [@A]
  sim.observe [@U, @V]
}

// -----

// A five-point stencil on a 128x128 grid flattened row-major: the note
// points at the read that sets the window's width (the row above, i-128),
// not at the first read of a neighbour (i-1). local_window [-128, 128]; the
// reads leave gaps of more than two blocks, so local_reads records their
// windows.

// CHECK-LABEL: sim.simulation @plate
// CHECK: sim.component @Heat writes(@U) attributes {local_reads = array<i64: -128, -128, -1, 1, 128, 128>, local_window = array<i64: -128, 128>, sub_stepping = #sim<sub_stepping grid_sync>}
sim.simulation @plate range(16384) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @U : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{@Heat needs a grid-wide barrier between sub-steps: its evaluate body reads @U, which it writes, at i-128..i+128, so a thread could read another item while that item is between sub-steps; under lts its blocks of 32 items take local time steps (window i-128..i+128)}}
  sim.component @Heat writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c128 = arith.constant 128 : index
    %iw = arith.subi %i, %c1 : index
    %ie = arith.addi %i, %c1 : index
    %is = arith.subi %i, %c128 : index
    %in = arith.addi %i, %c128 : index
    %uw = sim.read @U[%iw] : f64
    %ue = sim.read @U[%ie] : f64
    // expected-note @+1 {{reads @U at i-128}}
    %us = sim.read @U[%is] : f64
    %un = sim.read @U[%in] : f64
    %u = sim.read @U[%i] : f64
    %s1 = arith.addf %uw, %ue : f64
    %s2 = arith.addf %us, %un : f64
    %s = arith.addf %s1, %s2 : f64
    %four = arith.constant 4.0 : f64
    %u4 = arith.mulf %four, %u : f64
    %lap = arith.subf %s, %u4 : f64
    %u1 = math.fma %dt, %lap, %u : f64
    sim.yield %u1 : f64
  }
  sim.observe [@U]
}
