// A buffer declared interp(none) has no value between the ends of a big
// step. Under hip and hip-cache a read that would need one (an interpolate
// read, in evaluate or num_steps) is an error of --sim-plan-memory; back-edge
// and own reads are fine, and so is every read under simple and traditional.
//
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory --verify-diagnostics
// RUN: not sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip-cache 2>&1 | FileCheck %s --check-prefix=CACHE
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=simple | FileCheck %s --check-prefix=ONE
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=traditional | FileCheck %s --check-prefix=ONE

// CACHE: error: 'sim.read' op reads @P at an intermediate time of the big step (@Drift's evaluate interpolates buffers advanced earlier in the step under hip-cache), but @P is declared interp(none)
// CACHE: error: 'sim.read' op reads @P at an intermediate time of the big step (@Drift's num_steps interpolates buffers advanced earlier in the step under hip-cache), but @P is declared interp(none)

// ONE-LABEL: sim.simulation @evaluate_reads_momentum
// ONE: sim.component @Drift
// ONE: sim.load target @P
// ONE-LABEL: sim.simulation @num_steps_reads_momentum
// ONE: sim.component @Drift
// ONE: sim.load source @P

sim.simulation @evaluate_reads_momentum range(64) dt(1.0e-2 : f32) max_steps(4) {
  // expected-note @+1 {{@P is declared interp(none) here: its value means nothing between the ends of a big step; read it through the back edge, or use strategy simple or traditional}}
  sim.buffer @P : f32 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // The kick reads the position at T (back edge) and its own momentum: fine.
  sim.component @Kick writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : f32
    %x = sim.read @X[%i] : f32
    %q = arith.subf %p, %x : f32
    sim.yield %q : f32
  }
  // The drift sub-steps (num_steps): it would read @P inside the big step.
  sim.component @Drift writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    // expected-error @+1 {{'sim.read' op reads @P at an intermediate time of the big step (@Drift's evaluate interpolates buffers advanced earlier in the step under hip), but @P is declared interp(none)}}
    %p = sim.read @P[%i] : f32
    %y = arith.addf %x, %p : f32
    sim.yield %y : f32
  }
  sim.schedule [@Kick]
  sim.observe [@X]
}

// -----

sim.simulation @num_steps_reads_momentum range(64) dt(1.0e-2 : f32) max_steps(4) {
  // expected-note @+1 {{@P is declared interp(none) here}}
  sim.buffer @P : f32 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Kick writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : f32
    sim.yield %p : f32
  }
  sim.component @Drift writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'sim.read' op reads @P at an intermediate time of the big step (@Drift's num_steps interpolates buffers advanced earlier in the step under hip), but @P is declared interp(none)}}
    %p = sim.read @P[%i] : f32
    %n = arith.fptosi %p : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
