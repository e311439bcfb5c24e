// An index that becomes the poison index -1 only when the lowering folds it
// (here 0 - 1; the verifier rejects -1 where it is written or a constant,
// test/Dialect/Sim/invalid-poison.mlir) makes `ub.poison` in the upstream
// conversions. The CPU kernels lower it to LLVM's poison, as the GPU back
// end does, instead of failing to translate an op without a location.
//
// RUN: sim-translate %s --sim-to-bundle --sim-strategies=simple -o %t.simb
// RUN: %python %S/../Bundle/Inputs/dump-bundle.py --flatc %flatc --schema %bundle_schema %t.simb | FileCheck %s

// CHECK: ptx: .target sm_90, chip sm_90, {{[0-9]+}} kernels, every one an .entry
// CHECK: cpu x86-64: shared object, {{[0-9]+}} kernels, every one exported

sim.simulation @fold range(64) dt(1.0e-3 : f32) max_steps(4) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %m1 = arith.subi %c0, %c1 : index
    %x = vector.extract %v[%m1] : f32 from vector<4xf32>
    %r = vector.broadcast %x : f32 to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
  sim.observe [@B]
}
