// The front end runs once: after it the component bodies hold explicit
// loads, and every stage that would re-decide what the loads rely on
// refuses the simulation (the first one in the pipeline reports it).
// --sim-insert-interpolation itself is idempotent: no view read is left.
//
// RUN: sim-opt %s --sim-front-end > %t.once
// RUN: not sim-opt %t.once --sim-front-end 2>&1 | FileCheck %s --check-prefix=PRUNE
// RUN: not sim-opt %t.once --sim-front-end=prune=false 2>&1 | FileCheck %s --check-prefix=SCHEDULE
// RUN: not sim-opt %t.once --sim-plan-memory=strategy=simple 2>&1 | FileCheck %s --check-prefix=PLAN
// sim-translate compiles a scene as written, and says so (its message
// named only a pass sim-translate does not offer).
// RUN: not sim-translate %t.once --sim-to-bundle --sim-cpu-isas=host -o %t.simb 2>&1 | FileCheck %s --check-prefix=PRUNE
// RUN: sim-opt %t.once --sim-insert-interpolation > %t.twice
// RUN: diff %t.once %t.twice
// RUN: FileCheck %s --input-file=%t.once

// PRUNE: error: 'sim.simulation' op has explicit loads, so its components and buffers are fixed; run --sim-prune before --sim-insert-interpolation (this simulation has been through the front end already, for strategy 'hip': give the scene as written, before --sim-front-end)
// PRUNE: note: the first explicit access is this 'sim.load'
// SCHEDULE: error: 'sim.simulation' op has explicit loads, so its schedule and read roles are fixed; run --sim-schedule before --sim-insert-interpolation
// PLAN: error: 'sim.simulation' op has explicit loads, so its memory plan is fixed; run --sim-plan-memory before --sim-insert-interpolation

// The plan the loads rely on: @U ping-pongs (grid_sync with num_steps), so
// @Sample reads its value at T from the snapshot.
// CHECK-LABEL: sim.simulation @twice
// CHECK: sim.buffer @U : f32 attributes {snapshot}
// CHECK: sim.component @Sample
// CHECK: sim.load snapshot @U
sim.simulation @twice range(16) dt(1.0e-2 : f32) max_steps(2) {
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
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %u = sim.read @U[%l] : f32
    sim.yield %u : f32
  }
  sim.component @Sample writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %w = sim.read @W[%i] : f32
    %s = arith.addf %u, %w : f32
    sim.yield %s : f32
  }
  sim.observe [@W]
}
