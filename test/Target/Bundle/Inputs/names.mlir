// A scene whose names are no identifiers: spaces, quotes, a dash, a
// non-ASCII letter, and two buffers whose names differ only in a character
// that kernel names cannot hold. "unused buffer" and its writer are pruned
// from every plan, so plan and scene buffer indices differ.
sim.simulation @"my scene" range(64) dt(1.0e-2 : f32) max_steps(2) {
  sim.param @"gain 1" = 2.0 : f32
  sim.param @"böse \"Wert\"" = 7 : i64
  sim.buffer @"unused buffer" : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @"X 0" : f32 interp(#sim.hermite<@"X-rate">) init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @"X-rate" : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @X_0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 3.0 : f32
    sim.yield %c : f32
  }
  sim.component @"cool-down \"fast\"" writes(@"X 0", @"X-rate") num_steps {
  ^bb0(%i: index, %t: i64):
    %two = arith.constant 2 : i32
    sim.yield %two : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @"X 0"[%i] : f32
    %g = sim.get_param @"gain 1" : f32
    %y = arith.mulf %x, %g : f32
    sim.yield %y, %x : f32, f32
  }
  sim.component @"follow X_0" writes(@X_0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @"X 0"[%i] : f32
    %w = sim.get_param @"böse \"Wert\"" : i64
    %wf = arith.sitofp %w : i64 to f32
    %y = arith.addf %x, %wf : f32
    sim.yield %y : f32
  }
  sim.component @"unused writer" writes(@"unused buffer") evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @"unused buffer"[%i] : f32
    sim.yield %u : f32
  }
  sim.total @"sum of X" : f64 {
  ^bb0(%i: index):
    %x = sim.read @X_0[%i] : f32
    %e = arith.extf %x : f32 to f64
    sim.yield %e : f64
  }
  sim.schedule [@"cool-down \"fast\"", @"follow X_0"]
  sim.observe [@"X 0", @X_0]
}
