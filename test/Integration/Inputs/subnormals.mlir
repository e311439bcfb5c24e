// Values that decay into subnormals: @X (f32) starts at 1e-36 and @Y (f64)
// at 1e-306, and each base step halves them (n = 0 leaves them). After 10 base steps both are
// subnormal under IEEE arithmetic (below 2^-126 and 2^-1022) and zero when
// the bundle flushes subnormals (sim-translate --sim-ftz).
// test/Integration/subnormals.test.
sim.simulation @decay range(64) dt(1.0e-2 : f32) max_steps(2) {
  sim.param @factor = 5.0e-1 : f32

  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %x = arith.constant 1.0e-36 : f32
    sim.yield %x : f32
  }
  sim.buffer @Y : f64 init {
  ^bb0(%i: index):
    %y = arith.constant 1.0e-306 : f64
    sim.yield %y : f64
  }
  sim.component @HalveX writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %f = sim.get_param @factor : f32
    %x1 = arith.mulf %x, %f : f32
    %zero = arith.constant 0 : i32
    %still = arith.cmpi eq, %n, %zero : i32
    %x2 = arith.select %still, %x, %x1 : f32
    sim.yield %x2 : f32
  }
  sim.component @HalveY writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %y = sim.read @Y[%i] : f64
    %f = sim.get_param @factor : f32
    %f64 = arith.extf %f : f32 to f64
    %y1 = arith.mulf %y, %f64 : f64
    %zero = arith.constant 0 : i32
    %still = arith.cmpi eq, %n, %zero : i32
    %y2 = arith.select %still, %y, %y1 : f64
    sim.yield %y2 : f64
  }
  sim.schedule [@HalveX, @HalveY]
  sim.observe [@X, @Y]
}
