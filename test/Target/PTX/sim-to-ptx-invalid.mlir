// Errors of sim-translate --sim-to-ptx that do not depend on the lowering of
// scenes to GPU kernels.
//
// RUN: sim-translate --sim-to-ptx %s --split-input-file --verify-diagnostics
//
// PTX alone runs on a GPU, whose groups have at most 1024 threads (a
// bundle may plan larger groups for its CPU kernels).
// RUN: not sim-translate --sim-to-ptx %s --sim-group-size=2048 -o %t.ptx 2>&1 | FileCheck %s --check-prefix=GROUP
// GROUP: error: --sim-group-size 2048 is more than the 1024 threads a CUDA group can have

// expected-error @+1 {{there is no sim.simulation to compile to PTX}}
module attributes {gpu.container_module} {
  gpu.module @kernels {
  }
}

// -----

// A scene the front end rejects: its diagnostic, and nothing after it.
// expected-error @+1 {{has no 'sim.observe', so nothing is needed; list the observed output buffers before pruning}}
sim.simulation @unobserved range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
}
