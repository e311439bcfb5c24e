// A Hermite-interpolated position with its velocity buffer.
//
// @Osc advances an oscillator X'' = -w^2 X (w = 1 + i / 20) with
// semi-implicit Euler, 1 + i % 3 base steps at a time, writing @V (declared
// first, interp(none)) and @X (interp(#sim.hermite<@V>)). @Probe, later in the
// step, integrates X over time (P += n dt X(t + n)) one base step at a time,
// so under hip it reads X interpolated at every base step inside the big
// step. Nothing reads through the back edge: hip takes max_steps (4).
sim.simulation @hermite range(64) dt(2.0e-2 : f32) max_steps(4) {
  sim.param @force = 0 : i32

  sim.buffer @V : f32 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Osc writes(@V, @X) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c3 : i32
    %n = arith.addi %r, %c1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 5.0e-2 : f32
    %one = arith.constant 1.0 : f32
    %fs = arith.mulf %f, %s : f32
    %w = arith.addf %fs, %one : f32
    %w2 = arith.mulf %w, %w : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %wx = arith.mulf %w2, %x : f32
    %acc = arith.negf %wx : f32
    %v1 = math.fma %h, %acc, %v : f32
    %x1 = math.fma %h, %v1, %x : f32
    sim.yield %v1, %x1 : f32, f32
  }

  sim.component @Probe writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %p = sim.read @P[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %p1 = math.fma %h, %x, %p : f32
    sim.yield %p1 : f32
  }

  sim.schedule [@Osc, @Probe]
  sim.observe [@X, @P]
}
