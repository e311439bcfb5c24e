// The pipelines run on a builtin.module and nest their own passes on the
// simulations and gpu.modules inside. Nested under another op, the front
// end changed nothing and exited 0, and the reference pipeline aborted in
// LLVM ("Can't add pass ... restricted to 'builtin.module'"); each is now
// an error that says how to run it.
//
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-front-end))' 2>&1 | FileCheck %s --check-prefix=FRONT
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-reference-pipeline))' 2>&1 | FileCheck %s --check-prefix=REFERENCE
// RUN: not sim-opt %s --pass-pipeline='builtin.module(sim.simulation(sim-to-gpu-pipeline))' 2>&1 | FileCheck %s --check-prefix=TOGPU
// RUN: not sim-opt %s --pass-pipeline='builtin.module(func.func(sim-gpu-to-ptx))' 2>&1 | FileCheck %s --check-prefix=PTX
// RUN: sim-opt %s --pass-pipeline='builtin.module(sim-front-end{strategy=hip})' | FileCheck %s --check-prefix=MODULE
//
// FRONT: error: the sim-front-end pipeline runs on a builtin.module, whose sim.simulation and gpu.module ops it nests its passes on, not on 'sim.simulation': give --sim-front-end or --pass-pipeline='builtin.module(sim-front-end)'
// REFERENCE: error: the sim-reference-pipeline pipeline runs on a builtin.module{{.*}}not on 'sim.simulation'
// TOGPU: error: the sim-to-gpu-pipeline pipeline runs on a builtin.module{{.*}}not on 'sim.simulation'
// PTX: error: the sim-gpu-to-ptx pipeline runs on a builtin.module{{.*}}not on 'func.func'
// MODULE: sim.simulation @nested {{.*}}strategy = #sim<strategy hip>

sim.simulation @nested range(64) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
