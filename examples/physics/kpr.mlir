// kpr: the Kvaerno-Prothero-Robinson multirate test problem (f64), as in
// SUNDIALS ARKODE's ark_kpr_mri example, with G = -100, e = 0.5 and a fast
// frequency w = @omega (default 100; anything from 10 to 1000 is meant):
//
//   u' = G a/(2u) + e b/(2v) - sin(s)/(2u)
//   v' = e a/(2u) -   b/(2v) - w sin(w s)/(2v)
//   a = u^2 - 3 - cos(s),  b = v^2 - 2 - cos(w s)
//
// whose exact solution is u = sqrt(3 + cos s), v = sqrt(2 + cos(w s)).
// The range is a batch of independent copies: item i solves the problem from
// s = phi_i = i * @phase (default 0.1) on, i.e. at local time t it is at
// s = t + phi_i, starting exactly on the solution. (All copies see the same
// stiffness G; they differ only in phase, so groups make the same choices.)
//
// Components (both explicit Heun / RK2 steps of h = n dt per evaluation):
//   @Slow  writes @U; reads its own @U and @V through the back edge: the
//          coupling term e b/(2v) is frozen at T over the slow step (v and
//          cos(w s) both at T, so it stays as small as v's error).
//          num_steps = @m_slow (default 10).
//   @Fast  writes @V and @Up (u at the fast component's own local time, kept
//          so that Heun has u at both ends of its step); reads @U
//          interpolated at the end of each sub-step. num_steps = @m_fast
//          (default 1).
// Under hip the big step is @m_slow (the slow component reads through the
// back edge) and the fast component takes @m_slow / @m_fast sub-steps inside
// it; under traditional the big step is the global minimum, 1, so the slow
// part is evaluated every base step, as under simple.
//
// Stability and accuracy: dt = 5e-4; the slow step h = 10 dt = 5e-3 gives
// h G = -0.5 (Heun is stable for h |G| <= 2, so @m_slow <= 40 at this dt; keep
// @m_slow <= max_steps = 20); the fast step gives w dt = 0.05 at w = 100 (for
// w = 1000 set dt = 5e-5). Measured on the CPU at t = 5 (10^4 base steps),
// rms-rel against the exact solution: U 2.3e-7 under simple and 1.0e-6 under
// hip (4.5x, with 10x fewer slow evaluations), V 6.4e-5 under both.
//
// Observed: @U and @V, both with exact bodies (`sim-run --reference exact`).
// The interpolation of @U (#sim.linear, the line marked `study-interp`) is what
// the fast component sees inside a big step under hip;
// python/accuracy_study.py substitutes #sim.cubic.
sim.simulation @kpr range(64) dt(5.0e-4 : f64) max_steps(20) {
  sim.param @omega = 1.0e2 : f64
  sim.param @G = -1.0e2 : f64
  sim.param @e = 5.0e-1 : f64
  // Initial time of item i: i * @phase.
  sim.param @phase = 1.0e-1 : f64
  sim.param @m_slow = 10 : i32
  sim.param @m_fast = 1 : i32

  sim.buffer @U : f64 interp(#sim.linear) init { // study-interp
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phase = sim.get_param @phase : f64
    %s = arith.mulf %fi, %phase : f64
    %c = math.cos %s : f64
    %three = arith.constant 3.0 : f64
    %a = arith.addf %three, %c : f64
    %u = math.sqrt %a : f64
    sim.yield %u : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phase = sim.get_param @phase : f64
    %s = math.fma %fi, %phase, %t : f64
    %c = math.cos %s : f64
    %three = arith.constant 3.0 : f64
    %a = arith.addf %three, %c : f64
    %u = math.sqrt %a : f64
    sim.yield %u : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phase = sim.get_param @phase : f64
    %s = arith.mulf %fi, %phase : f64
    %w = sim.get_param @omega : f64
    %ws = arith.mulf %w, %s : f64
    %c = math.cos %ws : f64
    %two = arith.constant 2.0 : f64
    %a = arith.addf %two, %c : f64
    %v = math.sqrt %a : f64
    sim.yield %v : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phase = sim.get_param @phase : f64
    %s = math.fma %fi, %phase, %t : f64
    %w = sim.get_param @omega : f64
    %ws = arith.mulf %w, %s : f64
    %c = math.cos %ws : f64
    %two = arith.constant 2.0 : f64
    %a = arith.addf %two, %c : f64
    %v = math.sqrt %a : f64
    sim.yield %v : f64
  }
  sim.buffer @Up : f64 interp(none) init {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f64
    sim.yield %u : f64
  }

  sim.component @Slow writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %m = sim.get_param @m_slow : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    // The fast variable at T (back edge), frozen over the slow step.
    %v = sim.read @V[%i] : f64
    %G = sim.get_param @G : f64
    %e = sim.get_param @e : f64
    %w = sim.get_param @omega : f64
    %phase = sim.get_param @phase : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phi = arith.mulf %fi, %phase : f64
    %tf = arith.sitofp %t : i64 to f64
    %s0 = math.fma %tf, %dt, %phi : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %s1 = arith.addf %s0, %h : f64
    %half = arith.constant 0.5 : f64
    %two = arith.constant 2.0 : f64
    %three = arith.constant 3.0 : f64
    // The coupling term b/(2v) frozen at T, where v is known: v and
    // cos(w s) at the same time s0, for both stages. (Mixing v at s0 with
    // cos(w s1) would add a residual of order e w h that the exact
    // solution does not have.)
    %ws0 = arith.mulf %w, %s0 : f64
    %cw0 = math.cos %ws0 : f64
    %v2 = arith.mulf %v, %v : f64
    %b0a = arith.subf %v2, %two : f64
    %b0 = arith.subf %b0a, %cw0 : f64
    %twov = arith.mulf %two, %v : f64
    %q0 = arith.divf %b0, %twov : f64
    // k1 = f(s0, u, v).
    %c0 = math.cos %s0 : f64
    %sn0 = math.sin %s0 : f64
    %u2 = arith.mulf %u, %u : f64
    %a0a = arith.subf %u2, %three : f64
    %a0 = arith.subf %a0a, %c0 : f64
    %twou = arith.mulf %two, %u : f64
    %ga0 = arith.mulf %G, %a0 : f64
    %r0 = arith.subf %ga0, %sn0 : f64
    %p0 = arith.divf %r0, %twou : f64
    %k1 = math.fma %e, %q0, %p0 : f64
    // k2 = f(s1, u + h k1, v).
    %us = math.fma %h, %k1, %u : f64
    %c1 = math.cos %s1 : f64
    %sn1 = math.sin %s1 : f64
    %us2 = arith.mulf %us, %us : f64
    %a1a = arith.subf %us2, %three : f64
    %a1 = arith.subf %a1a, %c1 : f64
    %twous = arith.mulf %two, %us : f64
    %ga1 = arith.mulf %G, %a1 : f64
    %r1 = arith.subf %ga1, %sn1 : f64
    %p1 = arith.divf %r1, %twous : f64
    %k2 = math.fma %e, %q0, %p1 : f64
    %ksum = arith.addf %k1, %k2 : f64
    %hh = arith.mulf %h, %half : f64
    %u1 = math.fma %hh, %ksum, %u : f64
    sim.yield %u1 : f64
  }

  sim.component @Fast writes(@V, @Up) num_steps {
  ^bb0(%i: index, %t: i64):
    %m = sim.get_param @m_fast : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : f64
    %u0 = sim.read @Up[%i] : f64
    // The slow variable at the end of this sub-step (interpolated under hip).
    %u1 = sim.read @U[%i] : f64
    %e = sim.get_param @e : f64
    %w = sim.get_param @omega : f64
    %phase = sim.get_param @phase : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %phi = arith.mulf %fi, %phase : f64
    %tf = arith.sitofp %t : i64 to f64
    %s0 = math.fma %tf, %dt, %phi : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %s1 = arith.addf %s0, %h : f64
    %half = arith.constant 0.5 : f64
    %two = arith.constant 2.0 : f64
    %three = arith.constant 3.0 : f64
    // e a/(2u) at the start (u0) and at the end (u1) of the step.
    %c0 = math.cos %s0 : f64
    %u02 = arith.mulf %u0, %u0 : f64
    %a0a = arith.subf %u02, %three : f64
    %a0 = arith.subf %a0a, %c0 : f64
    %twou0 = arith.mulf %two, %u0 : f64
    %p0 = arith.divf %a0, %twou0 : f64
    %c1 = math.cos %s1 : f64
    %u12 = arith.mulf %u1, %u1 : f64
    %a1a = arith.subf %u12, %three : f64
    %a1 = arith.subf %a1a, %c1 : f64
    %twou1 = arith.mulf %two, %u1 : f64
    %p1 = arith.divf %a1, %twou1 : f64
    // k1 = g(s0, u0, v).
    %ws0 = arith.mulf %w, %s0 : f64
    %cw0 = math.cos %ws0 : f64
    %sw0 = math.sin %ws0 : f64
    %v2 = arith.mulf %v, %v : f64
    %b0a = arith.subf %v2, %two : f64
    %b0 = arith.subf %b0a, %cw0 : f64
    %wsw0 = arith.mulf %w, %sw0 : f64
    %r0 = arith.addf %b0, %wsw0 : f64
    %twov = arith.mulf %two, %v : f64
    %q0 = arith.divf %r0, %twov : f64
    %ep0 = arith.mulf %e, %p0 : f64
    %k1 = arith.subf %ep0, %q0 : f64
    // k2 = g(s1, u1, v + h k1).
    %vs = math.fma %h, %k1, %v : f64
    %ws1 = arith.mulf %w, %s1 : f64
    %cw1 = math.cos %ws1 : f64
    %sw1 = math.sin %ws1 : f64
    %vs2 = arith.mulf %vs, %vs : f64
    %b1a = arith.subf %vs2, %two : f64
    %b1 = arith.subf %b1a, %cw1 : f64
    %wsw1 = arith.mulf %w, %sw1 : f64
    %r1 = arith.addf %b1, %wsw1 : f64
    %twovs = arith.mulf %two, %vs : f64
    %q1 = arith.divf %r1, %twovs : f64
    %ep1 = arith.mulf %e, %p1 : f64
    %k2 = arith.subf %ep1, %q1 : f64
    %ksum = arith.addf %k1, %k2 : f64
    %hh = arith.mulf %h, %half : f64
    %v1 = math.fma %hh, %ksum, %v : f64
    sim.yield %v1, %u1 : f64, f64
  }

  sim.schedule [@Slow, @Fast]
  sim.observe [@U, @V]
}
