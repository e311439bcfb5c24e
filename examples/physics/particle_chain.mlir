// particle_chain: a ring of 2048 particles joined by anharmonic springs
// (the Fermi-Pasta-Ulam-Tsingou beta chain), with a light segment whose
// particles are @ratio^2 (default 64) times lighter, so they oscillate
// @ratio (8) times faster (f64). Each particle reads its neighbours'
// positions: under hip the one component sub-steps with the range-wide
// minimum (the light segment's), under lts every block of 32 particles
// takes its own step.
//
// Physics. Particle i has displacement q_i from its lattice site, velocity
// v_i and mass m_i (1, or 1 / @ratio^2 in [3/8, 5/8) of the ring); the bond
// between i and i + 1 (around the ring: boundary wrap) stretched by
// d = q_(i+1) - q_i pulls with f(d) = d + @beta d^3 and stores
// V(d) = d^2 / 2 + @beta d^4 / 4. One symplectic-Euler step of s = n dt:
//   v_i += s (f(q_(i+1) - q_i) - f(q_i - q_(i-1))) / m_i,
//   q_i += s v_i (the new v_i).
// Initially a Gaussian displacement of amplitude @amp and width 20 sites
// centred at 5/16 of the ring, at rest: it splits into two pulses, one of
// which runs into the light segment and speeds up 8x there.
//
// num_steps reads the neighbours too: the linearised bond stiffness
// k = 1 + 3 @beta d^2 of the more stretched of its two bonds and the
// smallest mass the particle meets give the local frequency
// w = 2 sqrt(k / m), and the step asks for @cfl (0.5) of symplectic
// Euler's bound s w <= 2: at the default dt the light segment takes 1 base
// step, the rest 8 (max_steps). A state-dependent estimate: a strongly
// stretched bond shortens its particles' steps.
//
// The energy (@Energy: kinetic plus the bond to the right) is conserved by
// the scheme up to a bounded O(s) oscillation under simple; under lts the
// level boundaries couple through interpolated neighbour positions, and
// docs/accuracy.md states the drift measured. Reference: simple at dt / 8.
//
// Observed: @Q, @V. Total: @Energy.
sim.simulation @particle_chain range(2048) dt(6.25e-2 : f64) max_steps(8) {
  sim.param @ratio = 8.0 : f64
  sim.param @beta = 1.0 : f64
  sim.param @amp = 5.0e-1 : f64
  sim.param @cfl = 5.0e-1 : f64

  sim.buffer @Q : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %c = arith.constant 3.125e-1 : f64
    %centre = arith.mulf %c, %fr : f64
    %d = arith.subf %fi, %centre : f64
    %w = arith.constant 2.0e1 : f64
    %z = arith.divf %d, %w : f64
    %z2 = arith.mulf %z, %z : f64
    %nz2 = arith.negf %z2 : f64
    %g = math.exp %nz2 : f64
    %amp = sim.get_param @amp : f64
    %q = arith.mulf %amp, %g : f64
    sim.yield %q : f64
  }
  sim.buffer @V : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Chain writes(@Q, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %ip = arith.addi %i, %c1 : index
    %il = arith.subi %i, %c1 : index
    %ql = sim.read @Q[%il] : f64
    %q0 = sim.read @Q[%i] : f64
    %qr = sim.read @Q[%ip] : f64
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
    %r2 = arith.mulf %ratio, %ratio : f64
    %light = arith.divf %one, %r2 : f64
    // The neighbours around the ring, for their masses.
    %zero64 = arith.constant 0 : i64
    %one64 = arith.constant 1 : i64
    %self = arith.index_cast %i : index to i64
    %up = arith.addi %self, %one64 : i64
    %wr = arith.remsi %up, %range : i64
    %down = arith.addi %self, %range : i64
    %down1 = arith.subi %down, %one64 : i64
    %wl = arith.remsi %down1, %range : i64
    %li64 = arith.addi %wl, %zero64 : i64
    %la = arith.cmpi sge, %li64, %lo : i64
    %lb = arith.cmpi slt, %li64, %hi : i64
    %lin = arith.andi %la, %lb : i1
    %lm = arith.select %lin, %light, %one : f64
    %oi64 = arith.index_cast %i : index to i64
    %oa = arith.cmpi sge, %oi64, %lo : i64
    %ob = arith.cmpi slt, %oi64, %hi : i64
    %oin = arith.andi %oa, %ob : i1
    %om = arith.select %oin, %light, %one : f64
    %ri64 = arith.addi %wr, %zero64 : i64
    %ra = arith.cmpi sge, %ri64, %lo : i64
    %rb = arith.cmpi slt, %ri64, %hi : i64
    %rin = arith.andi %ra, %rb : i1
    %rm = arith.select %rin, %light, %one : f64
    %m01 = arith.minimumf %lm, %om : f64
    %m = arith.minimumf %m01, %rm : f64
    %de = arith.subf %qr, %q0 : f64
    %dw = arith.subf %q0, %ql : f64
    %ae = math.absf %de : f64
    %aw = math.absf %dw : f64
    %dmax = arith.maximumf %ae, %aw : f64
    %beta = sim.get_param @beta : f64
    %three = arith.constant 3.0 : f64
    %d2 = arith.mulf %dmax, %dmax : f64
    %b3 = arith.mulf %three, %beta : f64
    %k = math.fma %b3, %d2, %one : f64
    %km = arith.divf %k, %m : f64
    %root = math.sqrt %km : f64
    %two = arith.constant 2.0 : f64
    %omega = arith.mulf %two, %root : f64
    %cfl = sim.get_param @cfl : f64
    %dt = sim.get_param @dt : f64
    %wdt = arith.mulf %omega, %dt : f64
    %bound = arith.mulf %cfl, %two : f64
    %q = arith.divf %bound, %wdt : f64
    %n = arith.fptosi %q : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %ip = arith.addi %i, %c1 : index
    %il = arith.subi %i, %c1 : index
    %ql = sim.read @Q[%il] : f64
    %q0 = sim.read @Q[%i] : f64
    %qr = sim.read @Q[%ip] : f64
    %v0 = sim.read @V[%i] : f64
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
    %r2 = arith.mulf %ratio, %ratio : f64
    %light = arith.divf %one, %r2 : f64
    %oi64 = arith.index_cast %i : index to i64
    %oa = arith.cmpi sge, %oi64, %lo : i64
    %ob = arith.cmpi slt, %oi64, %hi : i64
    %oin = arith.andi %oa, %ob : i1
    %om = arith.select %oin, %light, %one : f64
    %beta = sim.get_param @beta : f64
    %de = arith.subf %qr, %q0 : f64
    %dw = arith.subf %q0, %ql : f64
    %ed2 = arith.mulf %de, %de : f64
    %ed3 = arith.mulf %ed2, %de : f64
    %ef = math.fma %beta, %ed3, %de : f64
    %wd2 = arith.mulf %dw, %dw : f64
    %wd3 = arith.mulf %wd2, %dw : f64
    %wf = math.fma %beta, %wd3, %dw : f64
    %net = arith.subf %ef, %wf : f64
    %acc = arith.divf %net, %om : f64
    %nf = arith.sitofp %n : i32 to f64
    %s = arith.mulf %nf, %dt : f64
    %v1 = math.fma %s, %acc, %v0 : f64
    %q1 = math.fma %s, %v1, %q0 : f64
    sim.yield %q1, %v1 : f64, f64
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %c1 = arith.constant 1 : index
    %ip = arith.addi %i, %c1 : index
    %q0 = sim.read @Q[%i] : f64
    %qr = sim.read @Q[%ip] : f64
    %v0 = sim.read @V[%i] : f64
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
    %r2 = arith.mulf %ratio, %ratio : f64
    %light = arith.divf %one, %r2 : f64
    %oi64 = arith.index_cast %i : index to i64
    %oa = arith.cmpi sge, %oi64, %lo : i64
    %ob = arith.cmpi slt, %oi64, %hi : i64
    %oin = arith.andi %oa, %ob : i1
    %om = arith.select %oin, %light, %one : f64
    %beta = sim.get_param @beta : f64
    %d = arith.subf %qr, %q0 : f64
    %d2 = arith.mulf %d, %d : f64
    %d4 = arith.mulf %d2, %d2 : f64
    %half = arith.constant 0.5 : f64
    %quarter = arith.constant 0.25 : f64
    %bq = arith.mulf %beta, %quarter : f64
    %p4 = arith.mulf %bq, %d4 : f64
    %p = math.fma %half, %d2, %p4 : f64
    %v2 = arith.mulf %v0, %v0 : f64
    %mv2 = arith.mulf %om, %v2 : f64
    %ke = arith.mulf %half, %mv2 : f64
    %e = arith.addf %ke, %p : f64
    sim.yield %e : f64
  }

  sim.observe [@Q, @V]
}
