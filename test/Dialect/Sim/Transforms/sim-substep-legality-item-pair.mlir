// RUN: sim-opt %s --split-input-file --sim-substep-legality --verify-diagnostics | FileCheck %s
//
// Pairs are lts's alone: the front end of another strategy (pair-remarks
// off) records the same attributes without a word about pairs.
// RUN: sim-opt %s --split-input-file --sim-substep-legality=pair-remarks=false 2>/dev/null | FileCheck %s
// RUN: sim-opt %S/../../../Integration/Inputs/force-integrate.mlir --sim-front-end=strategy=hip 2>&1 >/dev/null | FileCheck %s --check-prefix=QUIET --allow-empty
// RUN: sim-opt %S/../../../Integration/Inputs/force-integrate.mlir --sim-front-end=strategy=lts 2>&1 >/dev/null | FileCheck %s --check-prefix=LTS
// QUIET-NOT: pair
// LTS: @Force and @Integrate form an item pair

// Item pairs (docs/Model.md, "Item pairs"): the first component of the
// step bounds the big step and writes values that one component reads only
// at its own items, from the state that component alone writes (a force
// and an integrator). The pass records flux_window [0, 0] on the writer and
// widens the reader's local_window, or says in a remark on the writer which
// rule fails. Shapes that are no pair get no remark.

// A pair: @Force reads @X at i-1..i+1 and writes @F, which @Integrate
// reads at i. flux_window [0, 0] and local_window [-1, 1] on the writer,
// local_window [-1, 1] on the reader (through the forces).

// CHECK-LABEL: sim.simulation @pair
// CHECK: sim.component @Force writes(@F) attributes {flux_window = array<i64: 0, 0>, local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping in_kernel>}
// CHECK: sim.component @Integrate writes(@X, @V) attributes {local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping in_kernel>}

sim.simulation @pair range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{@Force and @Integrate form an item pair: under lts @Force evaluates an item whenever its block starts a sub-step, so its num_steps bounds that block rather than the big step (only its largest value does), and @Integrate's blocks take local time steps (window i-1..i+1)}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The integrator reads a neighbour's force: a value that is no flux is
// read only at the item's own index.

// CHECK-LABEL: sim.simulation @neighbour_force
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @neighbour_force range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Force and @Integrate form no pair, and @Force's num_steps bounds the big step as under hip: @Integrate reads @F at i-1; read @F only at the item's own index, or make it #sim.flux so that its value holds over its writer's step}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %f = sim.read @F[%il] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The integrator reads the force in its num_steps body, at T.

// CHECK-LABEL: sim.simulation @force_in_num_steps
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @force_in_num_steps range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Force and @Integrate form no pair, and @Force's num_steps bounds the big step as under hip: @Integrate reads @F in its num_steps body; read @Force's values only in evaluate}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %g = sim.read @F[%i] : f64
    %n = arith.fptosi %g : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The integrator has no num_steps: its blocks take their steps from the
// force's estimates alone.

// CHECK-LABEL: sim.simulation @no_reader_steps
// CHECK: sim.component @Force writes(@F) attributes {flux_window = array<i64: 0, 0>
// CHECK: sim.component @Integrate writes(@X, @V) attributes {local_window = array<i64: -1, 1>

sim.simulation @no_reader_steps range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{@Force and @Integrate form an item pair: under lts @Force evaluates an item whenever its block starts a sub-step, so its num_steps bounds that block rather than the big step (only its largest value does), and @Integrate's blocks take local time steps (window i-1..i+1)}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The force reads the positions through a gather.

// CHECK-LABEL: sim.simulation @gathered_positions
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @gathered_positions range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Force and @Integrate form no pair, and @Force's num_steps bounds the big step as under hip: it reads @X through a gather; read it through a window (%i plus a bounded offset, or an index clamped to %i - w .. %i + w with arith.maxsi and arith.minsi) so that the blocks an item of @Force reads are known}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %g = sim.read @V[%i] : f64
    %gi = arith.fptosi %g : f64 to i64
    %gx = arith.index_cast %gi : i64 to index
    %xl = sim.read @X[%gx] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The positions have no interpolation: a neighbour ahead in time has no
// value between its two time levels.

// CHECK-LABEL: sim.simulation @none_positions
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @none_positions range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Force and @Integrate form no pair, and @Force's num_steps bounds the big step as under hip: it reads @X, whose value between two time levels is not an interpolation of the two; use #sim.linear or #sim.cubic}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// The positions interpolate with their derivative (hermite), which the
// integrator writes too: @Force reads both at the integrator's two time
// levels.

// CHECK-LABEL: sim.simulation @hermite_positions
// CHECK: sim.component @Force writes(@F) attributes {flux_window = array<i64: 0, 0>, local_window = array<i64: -1, 1>
// CHECK: sim.component @Integrate writes(@X, @V) attributes {local_window = array<i64: -1, 1>

sim.simulation @hermite_positions range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{@Force and @Integrate form an item pair: under lts @Force evaluates an item whenever its block starts a sub-step, so its num_steps bounds that block rather than the big step (only its largest value does), and @Integrate's blocks take local time steps (window i-1..i+1)}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// A derivative under another boundary rule would be read at the
// positions' items.

// CHECK-LABEL: sim.simulation @hermite_boundaries
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @hermite_boundaries range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Force and @Integrate form no pair, and @Force's num_steps bounds the big step as under hip: it reads @X: @X's interpolation reads @V (derivative) at @X's items, but @V has boundary(wrap) where @X has boundary(clamp); give both one boundary rule}}
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// Without num_steps the force bounds nothing: no pair and no remark (the
// integrator sub-steps per group as under hip).

// CHECK-LABEL: sim.simulation @force_bounds_nothing
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @force_bounds_nothing range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Force writes(@F) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.schedule [@Force, @Integrate]
  sim.observe [@X]
}

// -----

// A third component reads the forces too: no pair shape, no remark.

// CHECK-LABEL: sim.simulation @two_readers
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @two_readers range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @M : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %d = arith.subf %xr, %xl : f64
    sim.yield %d : f64
  }
  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %v1 = math.fma %dt, %f, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.component @Monitor writes(@M) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    sim.yield %f : f64
  }
  sim.schedule [@Force, @Integrate, @Monitor] bounded_by [@Force]
  sim.observe [@X]
}

// -----

// A kick that updates its own velocity (leapfrog written as kick and
// drift): @Kick keeps state of its own, which @Drift reads only at its own
// items, so no pair (a writer with a rate of its own would be evaluated at
// its reader's), and the remark says how to write it as one.

// CHECK-LABEL: sim.simulation @kick_reads_own
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @kick_reads_own range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @U : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Kick and @Drift form no pair, and @Kick's num_steps bounds the big step as under hip: it reads its own @V, and @Drift reads @Kick's values only at its own items; in an item pair @Kick computes its values from @Drift's state alone: let @Kick write only what @Drift needs (a force or an acceleration, in a buffer of its own) and @Drift write @V instead, updating it from its own state}}
  sim.component @Kick writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %ul = sim.read @U[%il] : f64
    %ur = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %d = arith.subf %ur, %ul : f64
    %v1 = math.fma %dt, %d, %v : f64
    sim.yield %v1 : f64
  }
  sim.component @Drift writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : f64
    %u = sim.read @U[%i] : f64
    %u1 = math.fma %dt, %v, %u : f64
    sim.yield %u1 : f64
  }
  sim.schedule [@Kick, @Drift] bounded_by [@Kick]
  sim.observe [@U]
}

// -----

// The kick reads its own velocity in num_steps: an estimate at T of a
// value whose items are evaluated at different times under lts.

// CHECK-LABEL: sim.simulation @kick_estimates_own
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @kick_estimates_own range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @U : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Kick and @Drift form no pair, and @Kick's num_steps bounds the big step as under hip: it reads its own @V in its num_steps body; under lts its items are evaluated at different times, so read @V only in evaluate, at the item's own index}}
  sim.component @Kick writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %v = sim.read @V[%i] : f64
    %n = arith.fptosi %v : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %d = arith.subf %ur, %u : f64
    %v1 = math.fma %dt, %d, %v : f64
    sim.yield %v1 : f64
  }
  sim.component @Drift writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %vl = sim.read @V[%il] : f64
    %v = sim.read @V[%i] : f64
    %u = sim.read @U[%i] : f64
    %d = arith.subf %v, %vl : f64
    %u1 = math.fma %dt, %d, %u : f64
    sim.yield %u1 : f64
  }
  sim.schedule [@Kick, @Drift] bounded_by [@Kick]
  sim.observe [@U]
}

// -----

// A staggered pair whose writer keeps two buffers with different boundary
// rules, read at a neighbour: which items read item j is not one rule.

// CHECK-LABEL: sim.simulation @staggered_two_boundaries
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @staggered_two_boundaries range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @U : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @W : f64 boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Kick and @Drift form no pair, and @Kick's num_steps bounds the big step as under hip: @Drift reads its values at i-1..i, and @V and @W have different boundary rules; give them one}}
  sim.component @Kick writes(@V, @W) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %d = arith.subf %ur, %u : f64
    %v1 = math.fma %dt, %d, %v : f64
    sim.yield %v1, %d : f64, f64
  }
  sim.component @Drift writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %vl = sim.read @V[%il] : f64
    %w = sim.read @W[%i] : f64
    %u = sim.read @U[%i] : f64
    %d = arith.subf %w, %vl : f64
    %u1 = math.fma %dt, %d, %u : f64
    sim.yield %u1 : f64
  }
  sim.schedule [@Kick, @Drift] bounded_by [@Kick]
  sim.observe [@U]
}

// -----

// A slow component with state of its own next to a fast one, each reading
// the other at its own item only (a multirate split, as in kpr.mlir): no
// pair, which would evaluate @Slow at every step of @Fast's blocks.

// CHECK-LABEL: sim.simulation @multirate
// CHECK-NOT: flux_window
// CHECK: sim.observe

sim.simulation @multirate range(64) dt(1.0e-2 : f64) max_steps(16) {
  sim.buffer @U : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{under lts @Slow and @Fast form no pair, and @Slow's num_steps bounds the big step as under hip: it reads its own @U, and @Fast reads @Slow's values only at its own items; in an item pair @Slow computes its values from @Fast's state alone: let @Slow write only what @Fast needs (a force or an acceleration, in a buffer of its own) and @Fast write @U instead, updating it from its own state}}
  sim.component @Slow writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c10 = arith.constant 10 : i32
    sim.yield %c10 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %u1 = math.fma %dt, %v, %u : f64
    sim.yield %u1 : f64
  }
  sim.component @Fast writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %d = arith.subf %u, %v : f64
    %v1 = math.fma %dt, %d, %v : f64
    sim.yield %v1 : f64
  }
  sim.schedule [@Slow, @Fast] bounded_by [@Slow]
  sim.observe [@U, @V]
}

// -----

// The two halves of a staggered scheme: @Vel updates the faces @V from
// the cells @U (through the back edge) and its own @V at its item, @Disp
// the cells from the faces at i-1..i. A pair: each face steps with the
// coarsest block of cells that reads it. flux_window [-1, 0]; the cells'
// window widens by the faces' window of @U to i-1..i+1.

// CHECK-LABEL: sim.simulation @staggered
// CHECK: sim.component @Vel writes(@V) attributes {flux_window = array<i64: -1, 0>, local_window = array<i64: 0, 1>, sub_stepping = #sim<sub_stepping in_kernel>}
// CHECK: sim.component @Disp writes(@U) attributes {local_window = array<i64: -1, 1>, sub_stepping = #sim<sub_stepping in_kernel>}

sim.simulation @staggered range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  // expected-remark @+1 {{@Vel and @Disp form an item pair: under lts @Vel evaluates an item whenever the coarsest block that reads it (at i-1..i) starts a sub-step, and @Disp reads the value it computed then until the next one, so its num_steps bounds that block rather than the big step (only its largest value does), and @Disp's blocks take local time steps (window i-1..i+1)}}
  sim.component @Vel writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %d = arith.subf %ur, %u : f64
    %v1 = math.fma %dt, %d, %v : f64
    sim.yield %v1 : f64
  }
  sim.component @Disp writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %vl = sim.read @V[%il] : f64
    %v = sim.read @V[%i] : f64
    %u = sim.read @U[%i] : f64
    %d = arith.subf %v, %vl : f64
    %u1 = math.fma %dt, %d, %u : f64
    sim.yield %u1 : f64
  }
  sim.schedule [@Vel, @Disp] bounded_by [@Vel]
  sim.observe [@U]
}
