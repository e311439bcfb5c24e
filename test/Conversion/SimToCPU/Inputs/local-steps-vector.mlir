sim.simulation @t range(64) dt(1.0e-3 : f32) max_steps(4) {
  sim.buffer @U : vector<4xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<1.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
  sim.component @C writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %u = sim.read @U[%j] : vector<4xf32>
    sim.yield %u : vector<4xf32>
  }
  sim.observe [@U]
}
