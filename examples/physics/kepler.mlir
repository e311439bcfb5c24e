// kepler: Kepler orbits of eccentricity @ecc = 0.6 (f64), one per item.
//
// Physics. A test body around a point mass, GM = 1, semi-major axis a = 1
// (period 2 pi, mean motion 1): x'' = -x / |x|^3 in the plane. Item i is the
// same orbit at a different phase: its mean anomaly is M = 2 pi i / range + t,
// pericentre on the +x axis. The exact solution solves Kepler's equation
// E - e sin E = M with 12 Newton steps (scf.for, from E0 = M + e sin M) and
// gives x = (cos E - e, sqrt(1 - e^2) sin E) and
// v = (-sin E, sqrt(1 - e^2) cos E) / (1 - e cos E); the init bodies are the
// same at t = 0. Energy v^2/2 - 1/r = -1/2 and angular momentum
// x v_y - y v_x = sqrt(1 - e^2) = 0.8 are conserved; the scene declares
// both as totals (sums over the orbits, computed on the device).
//
// Components: one, @Orbit, writes @V (interp(none)) and @X (interpolated with
// cubic Hermite through @V; nothing reads it inside a step, so the choice
// does not change results). Each evaluation is one kick-drift-kick leapfrog
// step (velocity Verlet, symplectic at a fixed step) of h = n dt. Kick and
// drift are not separate components: one of them would then read the other's
// buffer through the back edge, and under hip a back-edge reader with
// num_steps bounds the big step by the global minimum (the body nearest its
// pericentre), which removes the per-item adaptivity this scene is about.
// With one component nothing reads through the back edge, so under hip the
// big step is max_steps (8) and each thread group sub-steps by its smallest
// num_steps; under traditional every step is the global minimum.
//
// num_steps = floor(@eta r^1.5 / dt), a fixed fraction of the local
// dynamical time: with dt = 1e-3 and @eta = 4e-3, 1 base step at pericentre
// (r = 0.4) to 8 at apocentre (r = 1.6). Neighbouring items have neighbouring
// phases, so a group of 32 items (--group-size 32) spans 1/8 of the orbit.
// A varying step makes leapfrog not exactly symplectic: the energy drift
// measures that.
//
// Observed: @X and @V, with exact bodies (`sim-run --reference exact`); one
// orbit is 6283 base steps.
sim.simulation @kepler range(256) dt(1.0e-3 : f64) max_steps(8) {
  // Eccentricity of every orbit.
  sim.param @ecc = 6.0e-1 : f64
  // num_steps = floor(@eta * r^1.5 / dt): a fixed fraction of the local
  // dynamical time.
  sim.param @eta = 4.0e-3 : f64

  sim.buffer @V : vector<2xf64> interp(none) init {
  ^bb0(%i: index):
    %t0 = arith.constant 0.0 : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %twopi = arith.constant 6.283185307179586 : f64
    %ph = arith.divf %fi, %fr : f64
    %m0 = arith.mulf %ph, %twopi : f64
    %M = arith.addf %m0, %t0 : f64
    %ecc = sim.get_param @ecc : f64
    %sM = math.sin %M : f64
    %E0 = math.fma %ecc, %sM, %M : f64
    %lo = arith.constant 0 : index
    %hi = arith.constant 12 : index
    %st = arith.constant 1 : index
    %one = arith.constant 1.0 : f64
    // Newton's method on Kepler's equation E - e sin E = M.
    %E = scf.for %k = %lo to %hi step %st iter_args(%e = %E0) -> (f64) {
      %se = math.sin %e : f64
      %ce = math.cos %e : f64
      %esn = arith.mulf %ecc, %se : f64
      %g0 = arith.subf %e, %esn : f64
      %g = arith.subf %g0, %M : f64
      %ecs = arith.mulf %ecc, %ce : f64
      %dg = arith.subf %one, %ecs : f64
      %d = arith.divf %g, %dg : f64
      %e1 = arith.subf %e, %d : f64
      scf.yield %e1 : f64
    }
    %cE = math.cos %E : f64
    %sE = math.sin %E : f64
    %e2 = arith.mulf %ecc, %ecc : f64
    %om = arith.subf %one, %e2 : f64
    %b = math.sqrt %om : f64
    %ecE = arith.mulf %ecc, %cE : f64
    %den = arith.subf %one, %ecE : f64
    %Ed = arith.divf %one, %den : f64
    %nsE = arith.negf %sE : f64
    %vx = arith.mulf %nsE, %Ed : f64
    %bcE = arith.mulf %b, %cE : f64
    %vy = arith.mulf %bcE, %Ed : f64
    %v = vector.from_elements %vx, %vy : vector<2xf64>
    sim.yield %v : vector<2xf64>
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %twopi = arith.constant 6.283185307179586 : f64
    %ph = arith.divf %fi, %fr : f64
    %m0 = arith.mulf %ph, %twopi : f64
    %M = arith.addf %m0, %t : f64
    %ecc = sim.get_param @ecc : f64
    %sM = math.sin %M : f64
    %E0 = math.fma %ecc, %sM, %M : f64
    %lo = arith.constant 0 : index
    %hi = arith.constant 12 : index
    %st = arith.constant 1 : index
    %one = arith.constant 1.0 : f64
    // Newton's method on Kepler's equation E - e sin E = M.
    %E = scf.for %k = %lo to %hi step %st iter_args(%e = %E0) -> (f64) {
      %se = math.sin %e : f64
      %ce = math.cos %e : f64
      %esn = arith.mulf %ecc, %se : f64
      %g0 = arith.subf %e, %esn : f64
      %g = arith.subf %g0, %M : f64
      %ecs = arith.mulf %ecc, %ce : f64
      %dg = arith.subf %one, %ecs : f64
      %d = arith.divf %g, %dg : f64
      %e1 = arith.subf %e, %d : f64
      scf.yield %e1 : f64
    }
    %cE = math.cos %E : f64
    %sE = math.sin %E : f64
    %e2 = arith.mulf %ecc, %ecc : f64
    %om = arith.subf %one, %e2 : f64
    %b = math.sqrt %om : f64
    %ecE = arith.mulf %ecc, %cE : f64
    %den = arith.subf %one, %ecE : f64
    %Ed = arith.divf %one, %den : f64
    %nsE = arith.negf %sE : f64
    %vx = arith.mulf %nsE, %Ed : f64
    %bcE = arith.mulf %b, %cE : f64
    %vy = arith.mulf %bcE, %Ed : f64
    %v = vector.from_elements %vx, %vy : vector<2xf64>
    sim.yield %v : vector<2xf64>
  }
  sim.buffer @X : vector<2xf64> interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %t0 = arith.constant 0.0 : f64
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %twopi = arith.constant 6.283185307179586 : f64
    %ph = arith.divf %fi, %fr : f64
    %m0 = arith.mulf %ph, %twopi : f64
    %M = arith.addf %m0, %t0 : f64
    %ecc = sim.get_param @ecc : f64
    %sM = math.sin %M : f64
    %E0 = math.fma %ecc, %sM, %M : f64
    %lo = arith.constant 0 : index
    %hi = arith.constant 12 : index
    %st = arith.constant 1 : index
    %one = arith.constant 1.0 : f64
    // Newton's method on Kepler's equation E - e sin E = M.
    %E = scf.for %k = %lo to %hi step %st iter_args(%e = %E0) -> (f64) {
      %se = math.sin %e : f64
      %ce = math.cos %e : f64
      %esn = arith.mulf %ecc, %se : f64
      %g0 = arith.subf %e, %esn : f64
      %g = arith.subf %g0, %M : f64
      %ecs = arith.mulf %ecc, %ce : f64
      %dg = arith.subf %one, %ecs : f64
      %d = arith.divf %g, %dg : f64
      %e1 = arith.subf %e, %d : f64
      scf.yield %e1 : f64
    }
    %cE = math.cos %E : f64
    %sE = math.sin %E : f64
    %e2 = arith.mulf %ecc, %ecc : f64
    %om = arith.subf %one, %e2 : f64
    %b = math.sqrt %om : f64
    %px = arith.subf %cE, %ecc : f64
    %py = arith.mulf %b, %sE : f64
    %p = vector.from_elements %px, %py : vector<2xf64>
    sim.yield %p : vector<2xf64>
  } exact {
  ^bb0(%i: index, %t: f64):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %twopi = arith.constant 6.283185307179586 : f64
    %ph = arith.divf %fi, %fr : f64
    %m0 = arith.mulf %ph, %twopi : f64
    %M = arith.addf %m0, %t : f64
    %ecc = sim.get_param @ecc : f64
    %sM = math.sin %M : f64
    %E0 = math.fma %ecc, %sM, %M : f64
    %lo = arith.constant 0 : index
    %hi = arith.constant 12 : index
    %st = arith.constant 1 : index
    %one = arith.constant 1.0 : f64
    // Newton's method on Kepler's equation E - e sin E = M.
    %E = scf.for %k = %lo to %hi step %st iter_args(%e = %E0) -> (f64) {
      %se = math.sin %e : f64
      %ce = math.cos %e : f64
      %esn = arith.mulf %ecc, %se : f64
      %g0 = arith.subf %e, %esn : f64
      %g = arith.subf %g0, %M : f64
      %ecs = arith.mulf %ecc, %ce : f64
      %dg = arith.subf %one, %ecs : f64
      %d = arith.divf %g, %dg : f64
      %e1 = arith.subf %e, %d : f64
      scf.yield %e1 : f64
    }
    %cE = math.cos %E : f64
    %sE = math.sin %E : f64
    %e2 = arith.mulf %ecc, %ecc : f64
    %om = arith.subf %one, %e2 : f64
    %b = math.sqrt %om : f64
    %px = arith.subf %cE, %ecc : f64
    %py = arith.mulf %b, %sE : f64
    %p = vector.from_elements %px, %py : vector<2xf64>
    sim.yield %p : vector<2xf64>
  }

  sim.component @Orbit writes(@V, @X) num_steps {
  ^bb0(%i: index, %t: i64):
    %x = sim.read @X[%i] : vector<2xf64>
    %x2 = arith.mulf %x, %x : vector<2xf64>
    %zero = arith.constant 0.0 : f64
    %r2 = vector.reduction <add>, %x2, %zero : vector<2xf64> into f64
    %r = math.sqrt %r2 : f64
    %r3 = arith.mulf %r2, %r : f64
    %r15 = math.sqrt %r3 : f64
    %eta = sim.get_param @eta : f64
    %dt = sim.get_param @dt : f64
    %er = arith.mulf %eta, %r15 : f64
    %q = arith.divf %er, %dt : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %half = arith.constant 0.5 : f64
    %hh = arith.mulf %h, %half : f64
    %hv = vector.broadcast %h : f64 to vector<2xf64>
    %hhv = vector.broadcast %hh : f64 to vector<2xf64>
    %zero = arith.constant 0.0 : f64
    // Kick: a = -x / r^3 (GM = 1).
    %x2 = arith.mulf %x, %x : vector<2xf64>
    %r2 = vector.reduction <add>, %x2, %zero : vector<2xf64> into f64
    %r = math.sqrt %r2 : f64
    %r3 = arith.mulf %r2, %r : f64
    %m1 = arith.constant -1.0 : f64
    %s0 = arith.divf %m1, %r3 : f64
    %s0v = vector.broadcast %s0 : f64 to vector<2xf64>
    %a0 = arith.mulf %s0v, %x : vector<2xf64>
    %vh = vector.fma %hhv, %a0, %v : vector<2xf64>
    // Drift.
    %x1 = vector.fma %hv, %vh, %x : vector<2xf64>
    // Kick.
    %x12 = arith.mulf %x1, %x1 : vector<2xf64>
    %r12 = vector.reduction <add>, %x12, %zero : vector<2xf64> into f64
    %r1 = math.sqrt %r12 : f64
    %r13 = arith.mulf %r12, %r1 : f64
    %s1 = arith.divf %m1, %r13 : f64
    %s1v = vector.broadcast %s1 : f64 to vector<2xf64>
    %a1 = arith.mulf %s1v, %x1 : vector<2xf64>
    %v1 = vector.fma %hhv, %a1, %vh : vector<2xf64>
    sim.yield %v1, %x1 : vector<2xf64>, vector<2xf64>
  }

  // Totals over the orbits, computed on the device at every output time
  // (`sim-run --report-every N`): the energy v^2/2 - 1/r (exactly -range/2)
  // and the angular momentum x v_y - y v_x (exactly 0.8 range).
  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %zero = arith.constant 0.0 : f64
    %x2 = arith.mulf %x, %x : vector<2xf64>
    %r2 = vector.reduction <add>, %x2, %zero : vector<2xf64> into f64
    %r = math.sqrt %r2 : f64
    %v2v = arith.mulf %v, %v : vector<2xf64>
    %v2 = vector.reduction <add>, %v2v, %zero : vector<2xf64> into f64
    %half = arith.constant 0.5 : f64
    %kinetic = arith.mulf %half, %v2 : f64
    %one = arith.constant 1.0 : f64
    %potential = arith.divf %one, %r : f64
    %e = arith.subf %kinetic, %potential : f64
    sim.yield %e : f64
  }
  sim.total @AngularMomentum : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %x0 = vector.extract %x[0] : f64 from vector<2xf64>
    %x1 = vector.extract %x[1] : f64 from vector<2xf64>
    %v0 = vector.extract %v[0] : f64 from vector<2xf64>
    %v1 = vector.extract %v[1] : f64 from vector<2xf64>
    %a = arith.mulf %x0, %v1 : f64
    %b = arith.mulf %x1, %v0 : f64
    %l = arith.subf %a, %b : f64
    sim.yield %l : f64
  }

  sim.schedule [@Orbit]
  sim.observe [@X, @V]
}
