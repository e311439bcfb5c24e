// Math functions that have no LLVM intrinsic (erf, cbrt, asinh, acosh,
// atanh: libm calls, one per element of the CPU's widened lanes), fpowi
// (one integer exponent per element) and ipowi (no lowering upstream:
// --sim-expand-integer-powers), in f32 and f64, for math-functions.test.
// @P holds ipowi(i - 32, t mod 5 - 2) summed over the steps (negative
// exponents included), which the test recomputes in Python.
sim.simulation @math_functions range(64) dt(1.0e-3 : f64) max_steps(4) {
  sim.buffer @D : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 1.5625e-2 : f64
    %x = arith.mulf %f, %s : f64
    sim.yield %x : f64
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    %s = arith.constant 1.5625e-2 : f32
    %x = arith.mulf %f, %s : f32
    sim.yield %x : f32
  }
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Double writes(@D) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @D[%i] : f64
    %a = math.erf %x : f64
    %b = math.cbrt %x : f64
    %c = math.asinh %x : f64
    %one = arith.constant 1.0 : f64
    %x1 = arith.addf %x, %one : f64
    %d = math.acosh %x1 : f64
    %h = arith.constant 5.0e-1 : f64
    %xh = arith.mulf %x, %h : f64
    %e = math.atanh %xh : f64
    %k = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %k3 = arith.remsi %k, %c3 : i32
    %f = math.fpowi %x1, %k3 : f64, i32
    %s1 = arith.addf %a, %b : f64
    %s2 = arith.addf %c, %d : f64
    %s3 = arith.addf %e, %f : f64
    %s4 = arith.addf %s1, %s2 : f64
    %s5 = arith.addf %s4, %s3 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h1 = arith.mulf %nf, %dt : f64
    %step = arith.mulf %s5, %h1 : f64
    %r = arith.addf %x, %step : f64
    sim.yield %r : f64
  }
  sim.component @Single writes(@S) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @S[%i] : f32
    %a = math.erf %x : f32
    %b = math.cbrt %x : f32
    %c = math.asinh %x : f32
    %one = arith.constant 1.0 : f32
    %x1 = arith.addf %x, %one : f32
    %d = math.acosh %x1 : f32
    %h = arith.constant 5.0e-1 : f32
    %xh = arith.mulf %x, %h : f32
    %e = math.atanh %xh : f32
    %c3 = arith.constant 3 : i32
    %f = math.fpowi %x1, %c3 : f32, i32
    %s1 = arith.addf %a, %b : f32
    %s2 = arith.addf %c, %d : f32
    %s3 = arith.addf %e, %f : f32
    %s4 = arith.addf %s1, %s2 : f32
    %s5 = arith.addf %s4, %s3 : f32
    %nf = arith.sitofp %n : i32 to f32
    %dt32 = arith.truncf %dt : f64 to f32
    %h1 = arith.mulf %nf, %dt32 : f32
    %step = arith.mulf %s5, %h1 : f32
    %r = arith.addf %x, %step : f32
    sim.yield %r : f32
  }
  sim.component @Power writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @P[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %c32 = arith.constant 32 : i64
    %b = arith.subi %i64, %c32 : i64
    %c5 = arith.constant 5 : i64
    %e = arith.remsi %t, %c5 : i64
    %c2 = arith.constant 2 : i64
    %e2 = arith.subi %e, %c2 : i64
    %q = math.ipowi %b, %e2 : i64
    %qf = arith.sitofp %q : i64 to f64
    %nf = arith.sitofp %n : i32 to f64
    %qn = arith.mulf %qf, %nf : f64
    %r = arith.addf %u, %qn : f64
    sim.yield %r : f64
  }
  sim.schedule [@Double, @Single, @Power]
  sim.observe [@D, @S, @P]
}
