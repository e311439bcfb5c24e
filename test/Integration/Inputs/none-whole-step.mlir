// An oscillator field (@Osc, a stencil that sub-steps) whose velocity @V is
// interp(none), and @Probe, which has no num_steps and so takes the big step
// whole: it reads @X through a window (hermite, with @V as the derivative)
// and @V through a gather, both at the end of the big step, where @V has a
// value. For none-whole-step.test.
sim.simulation @none_whole_step range(70) dt(1.0e-3 : f64) max_steps(8) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 0.2 : f64
    %a = arith.mulf %f, %s : f64
    %v = math.sin %a : f64
    sim.yield %v : f64
  }
  sim.buffer @V : f64 interp(none) boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Osc writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c10 = arith.constant 10 : i32
    %lt = arith.cmpi slt, %i32, %c10 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %lt, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %im = arith.subi %i, %c1 : index
    %ip = arith.addi %i, %c1 : index
    %x0 = sim.read @X[%i] : f64
    %v0 = sim.read @V[%i] : f64
    %vm = sim.read @V[%im] : f64
    %vp = sim.read @V[%ip] : f64
    %s = arith.addf %vm, %vp : f64
    %two = arith.constant 2.0 : f64
    %v2 = arith.mulf %two, %v0 : f64
    %l = arith.subf %s, %v2 : f64
    %k = arith.constant 5.0 : f64
    %kl = arith.mulf %k, %l : f64
    %acc = arith.subf %kl, %x0 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %v1 = math.fma %h, %acc, %v0 : f64
    %x1 = math.fma %h, %v1, %x0 : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.component @Probe writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c2 = arith.constant 2 : index
    %ip = arith.addi %i, %c2 : index
    %x = sim.read @X[%ip] : f64
    %c5 = arith.constant 5 : index
    %j0 = arith.muli %i, %c5 : index
    %r = arith.constant 70 : index
    %j = arith.remui %j0, %r : index
    %v = sim.read @V[%j] : f64
    %p = arith.addf %x, %v : f64
    sim.yield %p : f64
  }
  sim.schedule [@Osc, @Probe]
  sim.observe [@X, @V, @P]
}
