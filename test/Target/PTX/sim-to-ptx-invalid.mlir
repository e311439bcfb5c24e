// Errors of sim-translate --sim-to-ptx that do not depend on the lowering of
// scenes to GPU kernels.
//
// RUN: sim-translate --sim-to-ptx %s --split-input-file --verify-diagnostics
//
// PTX alone runs on a GPU, whose groups are whole warps and have at most
// 1024 threads (a bundle may plan larger groups for its CPU kernels); the
// error names the scene it would compile.
// RUN: not sim-translate --sim-to-ptx %s --sim-group-size=2048 -o %t.ptx 2>&1 | FileCheck %s --check-prefix=GROUP -DSIZE=2048
// RUN: not sim-translate --sim-to-ptx %s --sim-group-size=33 -o %t.ptx 2>&1 | FileCheck %s --check-prefix=GROUP -DSIZE=33
// RUN: not sim-translate --sim-to-ptx %s --sim-group-size=0 -o %t.ptx 2>&1 | FileCheck %s --check-prefix=GROUP -DSIZE=0
// GROUP: sim-to-ptx-invalid.mlir:[[@LINE+13]]:1: error: --sim-group-size must be a multiple of 32 (a GPU warp) from 32 to 1024 (a CUDA group), not [[SIZE]]
// GROUP-NOT: error

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
