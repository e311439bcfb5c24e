// springs: a chain of masses on springs of graded stiffness (f64).
//
// Physics. Item i is a unit mass at displacement x_i, tied to its rest
// position by an on-site spring of stiffness K_i = 10^(4 i / (range - 1))
// (1 at one end of the chain, 1e4 at the other: frequencies from 1 to 100)
// and to its neighbours by springs of stiffness @kc (default 10):
//   x_i'' = -K_i x_i + kc (x_{i-1} - 2 x_i + x_{i+1}),
// free ends (boundary clamp: the missing neighbour sits where the end item
// is). Initially x_i = sin(8 pi i / range), at rest. There is no closed-form
// solution: the reference is `simple` at a finer base step
// (python/accuracy_study.py runs it at dt / 8 and compares the dumps), and
// `sim-run --reference simple` gives the multirate error at the same dt.
//
// Components:
//   @Couple  (first) writes @F, the coupling force predicted at the end of
//            its step: kc L(x + h v) with L the discrete Laplacian over
//            X[i-1..i+1] and V[i-1..i+1], both read through the back edge
//            (values at T), h = n dt. num_steps = @m_couple (default 8), the
//            same for every item, so under hip the big step is @m_couple.
//   @Osc     writes @V, @X (the mass) and @Fp (the coupling force at its own
//            local time, so that velocity Verlet has the force at both ends
//            of a step); reads @F[i] interpolated (#sim.linear, the line
//            marked `study-interp`) at the end of each sub-step.
//            num_steps = floor(@c / (sqrt(K_i + 2 kc) dt)): at most @c
//            (0.1) radians of the local frequency per step, 1 base step for
//            the stiffest items and 8 (max_steps) for the softest at
//            dt = 1e-3.
// Under hip the stiff end sub-steps every base step while the soft end takes
// 8 at once, and the coupling is evaluated once per big step; under
// traditional every step is the global minimum (1). K grows smoothly along
// the chain, so a thread group of 32 items (--group-size 32) has nearly one
// stiffness. (Stiffness that alternates from item to item would put a stiff
// item in every group and leave nothing to gain; a stiff spring *between*
// neighbours would make the back-edge reader bound the step by it.)
//
// Observed: @X.
sim.simulation @springs range(1024) dt(1.0e-3 : f64) max_steps(8) {
  sim.param @kc = 1.0e1 : f64
  sim.param @c = 1.0e-1 : f64
  sim.param @m_couple = 8 : i32

  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %eightpi = arith.constant 25.132741228718345 : f64
    %a0 = arith.mulf %fi, %eightpi : f64
    %a = arith.divf %a0, %fr : f64
    %x = math.sin %a : f64
    sim.yield %x : f64
  }
  sim.buffer @F : f64 interp(#sim.linear) init { // study-interp
  ^bb0(%i: index):
    %kc = sim.get_param @kc : f64
    %m1 = arith.constant -1 : index
    %p1 = arith.constant 1 : index
    %il = arith.addi %i, %m1 : index
    %ir = arith.addi %i, %p1 : index
    %xl = sim.read @X[%il] : f64
    %x0 = sim.read @X[%i] : f64
    %xr = sim.read @X[%ir] : f64
    %s = arith.addf %xl, %xr : f64
    %two = arith.constant 2.0 : f64
    %x2 = arith.mulf %two, %x0 : f64
    %lap2 = arith.subf %s, %x2 : f64
    %f = arith.mulf %kc, %lap2 : f64
    sim.yield %f : f64
  }
  sim.buffer @Fp : f64 interp(none) init {
  ^bb0(%i: index):
    %f = sim.read @F[%i] : f64
    sim.yield %f : f64
  }

  sim.component @Couple writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %m = sim.get_param @m_couple : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %st = arith.constant 1 : index
    %zero = arith.constant 0.0 : f64
    %m2 = arith.constant -2.0 : f64
    %one = arith.constant 1.0 : f64
    %c0 = arith.constant 0 : index
    // L(x + h v) = sum over k = -1..1 of w_k (x + h v)[i + k], w = (1, -2, 1).
    %lap = scf.for %k = %lo to %hi step %st iter_args(%acc = %zero) -> (f64) {
      %j = arith.addi %i, %k : index
      %x = sim.read @X[%j] : f64
      %v = sim.read @V[%j] : f64
      %p = math.fma %h, %v, %x : f64
      %mid = arith.cmpi eq, %k, %c0 : index
      %w = arith.select %mid, %m2, %one : f64
      %next = math.fma %w, %p, %acc : f64
      scf.yield %next : f64
    }
    %kc = sim.get_param @kc : f64
    %f = arith.mulf %kc, %lap : f64
    sim.yield %f : f64
  }

  sim.component @Osc writes(@V, @X, @Fp) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %one = arith.constant 1.0 : f64
    %rm1 = arith.subf %fr, %one : f64
    %frac = arith.divf %fi, %rm1 : f64
    %ln1e4 = arith.constant 9.210340371976184 : f64
    %lk = arith.mulf %frac, %ln1e4 : f64
    %K = math.exp %lk : f64
    %kc = sim.get_param @kc : f64
    %two = arith.constant 2.0 : f64
    %k2 = math.fma %two, %kc, %K : f64
    %w = math.sqrt %k2 : f64
    %c = sim.get_param @c : f64
    %dt = sim.get_param @dt : f64
    %wdt = arith.mulf %w, %dt : f64
    %q = arith.divf %c, %wdt : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : f64
    %x = sim.read @X[%i] : f64
    %f0 = sim.read @Fp[%i] : f64
    // The coupling force at the end of this sub-step (interpolated under hip).
    %f1 = sim.read @F[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %one = arith.constant 1.0 : f64
    %rm1 = arith.subf %fr, %one : f64
    %frac = arith.divf %fi, %rm1 : f64
    %ln1e4 = arith.constant 9.210340371976184 : f64
    %lk = arith.mulf %frac, %ln1e4 : f64
    %K = math.exp %lk : f64
    %nK = arith.negf %K : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %half = arith.constant 0.5 : f64
    %hh = arith.mulf %h, %half : f64
    // Velocity Verlet with the on-site force -K x and the coupling force.
    %a0 = math.fma %nK, %x, %f0 : f64
    %vh = math.fma %hh, %a0, %v : f64
    %x1 = math.fma %h, %vh, %x : f64
    %a1 = math.fma %nK, %x1, %f1 : f64
    %v1 = math.fma %hh, %a1, %vh : f64
    sim.yield %v1, %x1, %f1 : f64, f64, f64
  }

  sim.schedule [@Couple, @Osc]
  sim.observe [@X]
}
