// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=lts --sim-plan-halos | FileCheck %s --check-prefixes=CHECK,LTS
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip --sim-plan-halos | FileCheck %s --check-prefixes=CHECK,HIP

// Under lts a read of a neighbour through the time levels of a
// #sim.hermite buffer reads its derivative there too, so the derivative
// gets the buffer's ghost items; under hip the component reads its own
// state in step, and the derivative only at its own item.

// CHECK-LABEL: sim.simulation @chain
// LTS: sim.buffer @V : f64 attributes {halo = array<i64: 1, 1>} init
// HIP: sim.buffer @V : f64 init
// CHECK: sim.buffer @X : f64 interp(#sim.hermite<@V>) attributes {halo = array<i64: 1, 1>} init
// LTS: sim.component @Chain writes(@X, @V) attributes {advance = #sim<advance local_steps>
sim.simulation @chain range(256) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.component @Chain writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %xr = sim.read @X[%ir] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %s = arith.addf %xl, %xr : f64
    %v1 = math.fma %dt, %s, %v : f64
    %x1 = math.fma %dt, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.observe [@X]
}

// -----

// The writer of an item pair reads the integrator's positions through its
// time levels, the velocities with them.

// CHECK-LABEL: sim.simulation @pair
// CHECK: sim.buffer @X : f64 interp(#sim.hermite<@V>) attributes {halo = array<i64: 1, 1>} init
// LTS: sim.buffer @V : f64 attributes {halo = array<i64: 1, 1>} init
// HIP: sim.buffer @V : f64 init
// LTS: sim.component @Force writes(@F) attributes {advance = #sim<advance local_flux>
sim.simulation @pair range(256) dt(1.0e-2 : f64) max_steps(4) {
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
