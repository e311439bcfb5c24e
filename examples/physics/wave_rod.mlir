// wave_rod: the 1-D wave equation u_tt = (c^2 u_x)_x on 1024 cells with a
// stiff middle, where the wave speed is @ratio (default 8) times the speed
// of the rest (f64).
//
// Physics. Cell i (width h = 1 / range) holds displacement u_i and velocity
// v_i; the speed is c_i = 1 outside [3/8, 5/8) and @ratio inside. One
// symplectic-Euler step of length s = n dt:
//   v_i += s * (k_{i+1/2} (u_{i+1} - u_i) - k_{i-1/2} (u_i - u_{i-1})) / h^2,
//   u_i += s * v_i (the new v_i),
// with k = c^2 and k_{i+1/2} the harmonic mean of the two cells'. Free ends
// (boundary clamp: the missing neighbour has the end cell's displacement).
// Initially a Gaussian pulse u = exp(-((x - 1/4) / 0.05)^2) at rest, which
// splits into two pulses; the right one crosses the stiff middle. The
// scheme is stable for s c_max / h <= 1; num_steps asks for @cfl (0.5) of
// that with the largest speed the cell meets (its own and its neighbours'):
// at the default dt the middle takes 1 base step, the rest 8 (max_steps).
//
// The discrete energy (@Energy: kinetic plus strain energy of the faces to
// the right, times h) is conserved up to O(s) oscillation by the scheme
// under simple. Under lts the middle blocks take 1 base step, the others up
// to 8 (limited to twice their neighbours'), coupled through interpolated
// neighbour values at the level boundaries; docs/accuracy.md states what
// that does to the energy over long runs. Reference: simple at dt / 8.
//
// Observed: @U, @V. Total: @Energy.
sim.simulation @wave_rod range(1024) dt(6.0e-5 : f64) max_steps(8) {
  sim.param @ratio = 8.0 : f64
  sim.param @cfl = 5.0e-1 : f64

  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %half = arith.constant 0.5 : f64
    %xi = arith.addf %fi, %half : f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %x = arith.divf %xi, %fr : f64
    %c = arith.constant 0.25 : f64
    %w = arith.constant 0.05 : f64
    %d = arith.subf %x, %c : f64
    %z = arith.divf %d, %w : f64
    %z2 = arith.mulf %z, %z : f64
    %nz2 = arith.negf %z2 : f64
    %u = math.exp %nz2 : f64
    sim.yield %u : f64
  }
  sim.buffer @V : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Wave writes(@V, @U) num_steps {
  ^bb0(%i: index, %t: i64):
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
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %il = arith.subi %i64, %c1 : i64
    %ir = arith.addi %i64, %c1 : i64
    // The largest speed among the cell and its neighbours.
    %a0 = arith.cmpi sge, %ir, %lo : i64
    %a1 = arith.cmpi slt, %il, %hi : i64
    %near = arith.andi %a0, %a1 : i1
    %cmax = arith.select %near, %ratio, %one : f64
    %cfl = sim.get_param @cfl : f64
    %fr = arith.sitofp %range : i64 to f64
    %dt = sim.get_param @dt : f64
    %den0 = arith.mulf %cmax, %dt : f64
    %den = arith.mulf %den0, %fr : f64
    %q = arith.divf %cfl, %den : f64
    %big = arith.constant 1.0e9 : f64
    %qc = arith.minimumf %q, %big : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
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
    %stiff = arith.mulf %ratio, %ratio : f64
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %il64 = arith.index_cast %il : index to i64
    %i64 = arith.index_cast %i : index to i64
    %ir64 = arith.index_cast %ir : index to i64
    // k = c^2 of the cell and its neighbours.
    %l0 = arith.cmpi sge, %il64, %lo : i64
    %l1 = arith.cmpi slt, %il64, %hi : i64
    %lin = arith.andi %l0, %l1 : i1
    %kl = arith.select %lin, %stiff, %one : f64
    %m0 = arith.cmpi sge, %i64, %lo : i64
    %m1 = arith.cmpi slt, %i64, %hi : i64
    %min = arith.andi %m0, %m1 : i1
    %k0 = arith.select %min, %stiff, %one : f64
    %r0 = arith.cmpi sge, %ir64, %lo : i64
    %r1 = arith.cmpi slt, %ir64, %hi : i64
    %rin = arith.andi %r0, %r1 : i1
    %kr = arith.select %rin, %stiff, %one : f64
    %two = arith.constant 2.0 : f64
    %pw = arith.mulf %kl, %k0 : f64
    %sw = arith.addf %kl, %k0 : f64
    %pw2 = arith.mulf %two, %pw : f64
    %kw = arith.divf %pw2, %sw : f64
    %pe = arith.mulf %k0, %kr : f64
    %se = arith.addf %k0, %kr : f64
    %pe2 = arith.mulf %two, %pe : f64
    %ke = arith.divf %pe2, %se : f64
    %ul = sim.read @U[%il] : f64
    %u0 = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v0 = sim.read @V[%i] : f64
    %de = arith.subf %ur, %u0 : f64
    %dw = arith.subf %u0, %ul : f64
    %fe = arith.mulf %ke, %de : f64
    %fw = arith.mulf %kw, %dw : f64
    %div = arith.subf %fe, %fw : f64
    %fr = arith.sitofp %range : i64 to f64
    %h2inv = arith.mulf %fr, %fr : f64
    %acc = arith.mulf %div, %h2inv : f64
    %nf = arith.sitofp %n : i32 to f64
    %s = arith.mulf %nf, %dt : f64
    %v1 = math.fma %s, %acc, %v0 : f64
    %u1 = math.fma %s, %v1, %u0 : f64
    sim.yield %v1, %u1 : f64, f64
  }

  // Kinetic energy plus the strain energy of the face to the right.
  sim.total @Energy : f64 {
  ^bb0(%i: index):
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
    %stiff = arith.mulf %ratio, %ratio : f64
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %i64 = arith.index_cast %i : index to i64
    %ir64 = arith.index_cast %ir : index to i64
    %m0 = arith.cmpi sge, %i64, %lo : i64
    %m1 = arith.cmpi slt, %i64, %hi : i64
    %min = arith.andi %m0, %m1 : i1
    %k0 = arith.select %min, %stiff, %one : f64
    %r0 = arith.cmpi sge, %ir64, %lo : i64
    %r1 = arith.cmpi slt, %ir64, %hi : i64
    %rin = arith.andi %r0, %r1 : i1
    %kr = arith.select %rin, %stiff, %one : f64
    %two = arith.constant 2.0 : f64
    %pe = arith.mulf %k0, %kr : f64
    %se = arith.addf %k0, %kr : f64
    %pe2 = arith.mulf %two, %pe : f64
    %ke = arith.divf %pe2, %se : f64
    %u0 = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v0 = sim.read @V[%i] : f64
    %fr = arith.sitofp %range : i64 to f64
    %de0 = arith.subf %ur, %u0 : f64
    %de = arith.mulf %de0, %fr : f64
    %strain0 = arith.mulf %de, %de : f64
    %strain = arith.mulf %ke, %strain0 : f64
    %kin = arith.mulf %v0, %v0 : f64
    %e2 = arith.addf %kin, %strain : f64
    %half = arith.constant 0.5 : f64
    %e1 = arith.mulf %half, %e2 : f64
    %e = arith.divf %e1, %fr : f64
    sim.yield %e : f64
  }

  sim.observe [@U, @V]
}
