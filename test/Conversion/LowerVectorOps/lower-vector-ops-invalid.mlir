// RUN: sim-opt %s --sim-lower-vector-ops --split-input-file --verify-diagnostics

// The pass lowers the vector ops of kernels and reference functions. Its
// lowerings start vectors from ub.poison, which a scene's bodies cannot
// hold, so a scene is refused at the first such op (it made a body with an
// unlocated poison before).

sim.simulation @scene range(16) dt(1.0e-3 : f32) max_steps(2) {
  sim.buffer @A : vector<4xf32> init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    // expected-error @below {{'vector.broadcast' op is in a body of a sim.simulation, whose vector ops --sim-lower-vector-ops does not lower (it lowers those of kernels); run it after --sim-lower-to-cpu, --sim-lower-to-gpu or --sim-lower-to-reference}}
    %v = vector.broadcast %z : f32 to vector<2x4xf32>
    %w = vector.shape_cast %v : vector<2x4xf32> to vector<8xf32>
    %r = vector.extract_strided_slice %w {offsets = [0], sizes = [4], strides = [1]} : vector<8xf32> to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
  sim.component @C writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : vector<4xf32>
    sim.yield %a : vector<4xf32>
  }
  sim.observe [@A]
}
