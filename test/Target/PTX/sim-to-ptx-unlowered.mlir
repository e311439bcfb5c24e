// Without the lowering of scenes to GPU kernels in the build
// (SIM_HAVE_SIM_TO_GPU is OFF), --sim-to-ptx runs the front end and the GPU
// back end, finds the simulation still there and says so rather than writing
// an empty PTX file.
//
// UNSUPPORTED: sim-to-gpu
// RUN: sim-translate --sim-to-ptx %s --verify-diagnostics

// expected-error @+1 {{'sim.simulation' op was not compiled to GPU kernels by the pipeline}}
sim.simulation @decay range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Decay writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %dx = arith.mulf %h, %x : f32
    %next = arith.subf %x, %dx : f32
    sim.yield %next : f32
  }
  sim.observe [@X]
}
