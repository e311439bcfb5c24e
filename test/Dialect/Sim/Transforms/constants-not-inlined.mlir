// Every stage after --sim-inline-constants relies on every buffer having a
// writer: given a simulation that still has a constant buffer, each says
// which pass to run first instead of deciding without it.
//
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-prune))' 2>&1 | FileCheck %s --check-prefix=PRUNE
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-schedule))' 2>&1 | FileCheck %s --check-prefix=SCHEDULE
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-substep-legality))' 2>&1 | FileCheck %s --check-prefix=LEGALITY
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-plan-memory))' 2>&1 | FileCheck %s --check-prefix=PLAN
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-insert-interpolation))' 2>&1 | FileCheck %s --check-prefix=INTERP
// RUN: not sim-opt %s --sim-print-dependency-graph 2>&1 | FileCheck %s --check-prefix=GRAPH
// RUN: not sim-opt %s --sim-lower-to-reference 2>&1 | FileCheck %s --check-prefix=REFERENCE
// RUN: not sim-opt %s --sim-lower-to-cpu 2>&1 | FileCheck %s --check-prefix=LOWERING
// RUN: not sim-opt %s --sim-lower-to-gpu 2>&1 | FileCheck %s --check-prefix=LOWERING
//
// The front end and the reference pipeline run it first.
// RUN: sim-opt %s --sim-front-end=strategy=lts | FileCheck %s --check-prefix=FRONT
// RUN: sim-opt %s --sim-reference-pipeline | FileCheck %s --check-prefix=REF-PIPELINE

// PRUNE: error: 'sim.simulation' op has the constant buffer @K, which no component writes; run --sim-inline-constants before --sim-prune
// PRUNE: note: @K is declared constant here
// SCHEDULE: run --sim-inline-constants before --sim-schedule
// LEGALITY: run --sim-inline-constants before --sim-substep-legality
// PLAN: run --sim-inline-constants before --sim-plan-memory
// INTERP: run --sim-inline-constants before --sim-insert-interpolation
// GRAPH: run --sim-inline-constants before --sim-print-dependency-graph
// REFERENCE: run --sim-inline-constants before --sim-lower-to-reference
// LOWERING: has the constant buffer @K, which no component writes; run the front end (--sim-front-end), whose first pass --sim-inline-constants replaces its reads, before lowering it

// FRONT-NOT: @K
// FRONT: sim.simulation @rod
// FRONT-SAME: strategy = #sim<strategy lts>
// FRONT-NOT: @K
// REF-PIPELINE-NOT: @K
// REF-PIPELINE: func.func @sim_ref_evaluate_
// REF-PIPELINE-NOT: @K

sim.simulation @rod range(64) dt(1.0e-3 : f32) max_steps(4) {
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %c32 = arith.constant 32 : i64
    %stiff = arith.cmpi sge, %i64, %c32 : i64
    %soft = arith.constant 1.0 : f32
    %hard = arith.constant 8.0 : f32
    %k = arith.select %stiff, %hard, %soft : f32
    sim.yield %k : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Conduct writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %k = sim.read @K[%i] : f32
    %eight = arith.constant 8.0 : f32
    %q = arith.divf %eight, %k : f32
    %n = arith.fptosi %q : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %kl = sim.read @K[%l] : f32
    %kr = sim.read @K[%r] : f32
    %ul = sim.read @U[%l] : f32
    %u = sim.read @U[%i] : f32
    %ur = sim.read @U[%r] : f32
    %fl = arith.mulf %kl, %ul : f32
    %fr = arith.mulf %kr, %ur : f32
    %s = arith.addf %fl, %fr : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %d = arith.mulf %h, %s : f32
    %v = arith.addf %u, %d : f32
    sim.yield %v : f32
  }
  sim.observe [@U]
}
