// wave_staggered: the 1-D wave equation in first-order, staggered form
// (Yee's scheme; leapfrog in time), u_t = v_x, v_t = (c^2 u)_x on 1024
// cells, with a stiff middle where the wave speed is @ratio (default 8)
// times the speed of the rest (f64). Written the way FDTD codes are: two
// components that read each other's neighbours.
//
// Physics. Cell i (width h = 1 / range) holds u_i; face i, between cells i
// and i + 1, holds v_i. The speed is c_i = @ratio at the faces i in
// [3/8, 5/8) of the range and 1 elsewhere. One step of length s = n dt:
//   @Vel:  v_i += s c_i^2 (u_{i+1} - u_i) / h   (u through the back edge),
//   @Disp: u_i += s (v_i - v_{i-1}) / h         (the new v),
// a leapfrog in time. Both ends are walls: v is 0 beyond the first face
// (@V boundary(zero)) and stays 0 at the last (u clamped: no gradient).
// Initially a Gaussian pulse u = exp(-((x - 1/4) / 0.05)^2) with v = 0,
// which splits into two; the right one crosses the stiff middle. Stable
// for s c / h <= 1; each component's num_steps asks for @cfl (0.5) of that
// with the largest speed it meets: 1 base step in the middle at the
// default dt, 8 (max_steps) elsewhere.
//
// Under hip @Vel reads @U through the back edge, so its num_steps bounds
// the big step of the whole scene (1 base step). Under lts the two form an
// item pair (docs/Model.md, "Item pairs"): face i steps with the coarsest
// block of cells that reads it, each block of 32 cells takes its own step,
// and the outer three quarters take 8 base steps at once.
//
// The energy (@Energy: h (u^2 + v^2 / c^2) / 2 summed over cells and faces)
// is conserved by the scheme up to an O(s) oscillation; docs/accuracy.md
// states its bound under lts. Reference: simple at dt / 8.
//
// Observed: @U, @V. Total: @Energy.
sim.simulation @wave_staggered range(1024) dt(6.0e-5 : f64) max_steps(8) {
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
  sim.buffer @V : f64 interp(#sim.linear) boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Vel writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %ir = arith.addi %i64, %c1 : i64
    %a0 = arith.cmpi sge, %ir, %lo : i64
    %a1 = arith.cmpi slt, %i64, %hi : i64
    %near = arith.andi %a0, %a1 : i1
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
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
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %u0 = sim.read @U[%i] : f64
    %u1 = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %i64 = arith.index_cast %i : index to i64
    %m0 = arith.cmpi sge, %i64, %lo : i64
    %m1 = arith.cmpi slt, %i64, %hi : i64
    %in = arith.andi %m0, %m1 : i1
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
    %r2 = arith.mulf %ratio, %ratio : f64
    %c2 = arith.select %in, %r2, %one : f64
    %fr = arith.sitofp %range : i64 to f64
    %g0 = arith.subf %u1, %u0 : f64
    %g = arith.mulf %g0, %fr : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hc = arith.mulf %h, %c2 : f64
    %v1 = math.fma %hc, %g, %v : f64
    sim.yield %v1 : f64
  }
  sim.component @Disp writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %il = arith.subi %i64, %c1 : i64
    %a0 = arith.cmpi sge, %i64, %lo : i64
    %a1 = arith.cmpi slt, %il, %hi : i64
    %near = arith.andi %a0, %a1 : i1
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
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
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %vl = sim.read @V[%il] : f64
    %v0 = sim.read @V[%i] : f64
    %u = sim.read @U[%i] : f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %g0 = arith.subf %v0, %vl : f64
    %g = arith.mulf %g0, %fr : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %u1 = math.fma %h, %g, %u : f64
    sim.yield %u1 : f64
  }
  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %range = sim.get_param @range : i64
    %c3 = arith.constant 3 : i64
    %c5 = arith.constant 5 : i64
    %c8 = arith.constant 8 : i64
    %r3 = arith.muli %range, %c3 : i64
    %lo = arith.divsi %r3, %c8 : i64
    %r5 = arith.muli %range, %c5 : i64
    %hi = arith.divsi %r5, %c8 : i64
    %i64 = arith.index_cast %i : index to i64
    %m0 = arith.cmpi sge, %i64, %lo : i64
    %m1 = arith.cmpi slt, %i64, %hi : i64
    %in = arith.andi %m0, %m1 : i1
    %one = arith.constant 1.0 : f64
    %ratio = sim.get_param @ratio : f64
    %r2 = arith.mulf %ratio, %ratio : f64
    %c2 = arith.select %in, %r2, %one : f64
    %uu = arith.mulf %u, %u : f64
    %vv = arith.mulf %v, %v : f64
    %vc = arith.divf %vv, %c2 : f64
    %e2 = arith.addf %uu, %vc : f64
    %half = arith.constant 0.5 : f64
    %e = arith.mulf %e2, %half : f64
    %fr = arith.sitofp %range : i64 to f64
    %eh = arith.divf %e, %fr : f64
    sim.yield %eh : f64
  }
  sim.schedule [@Vel, @Disp]
  sim.observe [@U, @V]
}
