// A scene whose state turns NaN and infinite in its first base step, for
// sim-run's tables (nan-tables.test). @X becomes (x - x) / (x - x), 0 / 0
// at run time: the default NaN, which x86 makes with its sign bit set.
// @Y becomes y / 0 with y = -1: -infinity. @Sum sums @X (NaN), @Low
// sums @Y (-infinity) and @High its negation (infinity).
sim.simulation @blow_up range(4) dt(1.0e-2 : f64) max_steps(1) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  }
  sim.buffer @Y : f64 init {
  ^bb0(%i: index):
    %minus = arith.constant -1.0 : f64
    sim.yield %minus : f64
  }

  sim.component @Blow writes(@X, @Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %y = sim.read @Y[%i] : f64
    %zero = arith.subf %x, %x : f64
    %x1 = arith.divf %zero, %zero : f64
    %c0 = arith.constant 0.0 : f64
    %y1 = arith.divf %y, %c0 : f64
    sim.yield %x1, %y1 : f64, f64
  }

  sim.total @Sum : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.total @Low : f64 {
  ^bb0(%i: index):
    %y = sim.read @Y[%i] : f64
    sim.yield %y : f64
  }
  sim.total @High : f64 {
  ^bb0(%i: index):
    %y = sim.read @Y[%i] : f64
    %minus = arith.negf %y : f64
    sim.yield %minus : f64
  }

  sim.observe [@X, @Y]
}
