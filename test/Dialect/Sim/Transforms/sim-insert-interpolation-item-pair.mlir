// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=lts --sim-insert-interpolation 2>/dev/null | FileCheck %s

// Under lts the reader of an item pair (docs/Model.md, "Item pairs") reads
// its writer's value as it is: the writer evaluated the item when the
// item's block started the sub-step, so there is nothing to interpolate.
// The writer reads the reader's state at its local time, from the time
// levels. Without the pair (the reader reads a neighbour's force) the
// writer takes the big step whole and the reader interpolates the force
// between the ends of the big step, as under hip.

// CHECK-LABEL: sim.simulation @pair
// CHECK: sim.component @Force writes(@F) attributes {advance = #sim<advance local_flux>
// CHECK: evaluate
// CHECK: sim.load local @X
// CHECK: sim.load local @X
// CHECK: sim.component @Integrate writes(@X, @V) attributes {advance = #sim<advance local_steps>
// CHECK: evaluate
// CHECK-NEXT: ^bb0
// CHECK-NEXT: sim.load target @F[%{{.*}}] : f64
// CHECK-NEXT: sim.load local @X
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
  sim.schedule [@Force, @Integrate]
  sim.observe [@X]
}

// -----

// CHECK-LABEL: sim.simulation @no_pair
// CHECK: sim.component @Force writes(@F) attributes {advance = #sim<advance whole_step>
// CHECK: sim.component @Integrate writes(@X, @V) attributes {advance = #sim<advance group_substeps>
// CHECK: evaluate
// CHECK: sim.load source @F
// CHECK: sim.load target @F
sim.simulation @no_pair range(64) dt(1.0e-2 : f64) max_steps(4) {
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
  sim.schedule [@Force, @Integrate]
  sim.observe [@X]
}

// -----

// The pair's reader reads its writer's value as it is, so a force that has
// no value between time levels (interp(none)) is fine under lts (hip, which
// interpolates it, rejects it).

// CHECK-LABEL: sim.simulation @none_force
// CHECK: sim.component @Integrate writes(@X, @V) attributes {advance = #sim<advance local_steps>
// CHECK: evaluate
// CHECK-NEXT: ^bb0
// CHECK-NEXT: sim.load target @F[%{{.*}}] : f64
sim.simulation @none_force range(64) dt(1.0e-2 : f64) max_steps(4) {
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
  sim.buffer @F : f64 interp(none) init {
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
  sim.schedule [@Force, @Integrate]
  sim.observe [@X]
}
