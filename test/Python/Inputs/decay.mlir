// Exponential decay that bounds its own step (num_steps = 4, max_steps 4).
sim.simulation @decay range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Decay writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %four = arith.constant 4 : i32
    sim.yield %four : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %dx = arith.mulf %h, %x : f32
    %next = arith.subf %x, %dx : f32
    sim.yield %next : f32
  }
  sim.schedule [@Decay]
  sim.observe [@X]
}
