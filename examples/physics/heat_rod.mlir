// heat_rod: a 1-D rod whose conductivity differs 100x between its halves
// (f64), written the natural way: one component that reads its neighbours.
//
// Physics. Cell i (width h = 1 / range) holds temperature u_i; the rod
// conducts with kappa_i = @k_soft in the left half and @k_soft * @ratio
// (default 100x) in the right half, insulated at both ends (boundary clamp:
// the missing neighbour has the end cell's temperature, so no heat leaves).
// Forward Euler on the conservative discretisation
//   u_i' = (k_{i+1/2} (u_{i+1} - u_i) - k_{i-1/2} (u_i - u_{i-1})) / h^2,
// with k_{i+1/2} the harmonic mean of the two cells' conductivities.
// Initially u_i = 1 + cos(2 pi x_i) with x_i = (i + 1/2) h.
// Explicit diffusion is stable for n dt kappa / h^2 <= 1/2; num_steps asks
// for at most @cfl (0.4) of that per step, using the largest conductivity
// the cell meets (its own and its neighbours'):
//   num_steps_i = floor(@cfl h^2 / (max kappa dt)), at least 1.
// At the default dt (2e-8) the stiff half takes 1 base step, the soft half
// 119 (capped at max_steps = 64). The total heat sum_i u_i h is conserved by the
// exact solution and up to the coupling error by the scheme (@Heat).
//
// Strategies: under hip the component reads @U at i-1 and i+1, so it
// sub-steps with the range-wide minimum (1): no gain. Under lts every thread
// group takes its own power-of-two step, limited to twice its neighbours'.
// The reference solution is `simple` at a finer base step (the accuracy
// study's dt / 16).
//
// Observed: @U. Total: @Heat.
sim.simulation @heat_rod range(4096) dt(2.0e-8 : f64) max_steps(64) {
  sim.param @k_soft = 1.0e-2 : f64
  sim.param @ratio = 1.0e2 : f64
  sim.param @cfl = 4.0e-1 : f64

  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %half = arith.constant 0.5 : f64
    %xi = arith.addf %fi, %half : f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %x = arith.divf %xi, %fr : f64
    %twopi = arith.constant 6.283185307179586 : f64
    %a = arith.mulf %twopi, %x : f64
    %c = math.cos %a : f64
    %one = arith.constant 1.0 : f64
    %u = arith.addf %one, %c : f64
    sim.yield %u : f64
  }

  sim.component @Conduct writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %range = sim.get_param @range : i64
    %c2_64 = arith.constant 2 : i64
    %mid = arith.divsi %range, %c2_64 : i64
    %ksoft = sim.get_param @k_soft : f64
    %ratio = sim.get_param @ratio : f64
    %kstiff = arith.mulf %ksoft, %ratio : f64
    %kl_i = arith.index_cast %il : index to i64
    %kl_r = arith.cmpi sge, %kl_i, %mid : i64
    %kl = arith.select %kl_r, %kstiff, %ksoft : f64
    %k0_i = arith.index_cast %i : index to i64
    %k0_r = arith.cmpi sge, %k0_i, %mid : i64
    %k0 = arith.select %k0_r, %kstiff, %ksoft : f64
    %kr_i = arith.index_cast %ir : index to i64
    %kr_r = arith.cmpi sge, %kr_i, %mid : i64
    %kr = arith.select %kr_r, %kstiff, %ksoft : f64
    %kmax0 = arith.maximumf %kl, %k0 : f64
    %kmax = arith.maximumf %kmax0, %kr : f64
    %cfl = sim.get_param @cfl : f64
    %fr = arith.sitofp %range : i64 to f64
    %h2inv = arith.mulf %fr, %fr : f64
    %dt = sim.get_param @dt : f64
    %den0 = arith.mulf %kmax, %dt : f64
    %den = arith.mulf %den0, %h2inv : f64
    %q = arith.divf %cfl, %den : f64
    %big = arith.constant 1.0e9 : f64
    %qc = arith.minimumf %q, %big : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %ul = sim.read @U[%il] : f64
    %u0 = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %range = sim.get_param @range : i64
    %c2_64 = arith.constant 2 : i64
    %mid = arith.divsi %range, %c2_64 : i64
    %ksoft = sim.get_param @k_soft : f64
    %ratio = sim.get_param @ratio : f64
    %kstiff = arith.mulf %ksoft, %ratio : f64
    %kl_i = arith.index_cast %il : index to i64
    %kl_r = arith.cmpi sge, %kl_i, %mid : i64
    %kl = arith.select %kl_r, %kstiff, %ksoft : f64
    %k0_i = arith.index_cast %i : index to i64
    %k0_r = arith.cmpi sge, %k0_i, %mid : i64
    %k0 = arith.select %k0_r, %kstiff, %ksoft : f64
    %kr_i = arith.index_cast %ir : index to i64
    %kr_r = arith.cmpi sge, %kr_i, %mid : i64
    %kr = arith.select %kr_r, %kstiff, %ksoft : f64
    // Face conductivities: harmonic means 2 a b / (a + b).
    %two = arith.constant 2.0 : f64
    %pw = arith.mulf %kl, %k0 : f64
    %sw = arith.addf %kl, %k0 : f64
    %pw2 = arith.mulf %two, %pw : f64
    %kw = arith.divf %pw2, %sw : f64
    %pe = arith.mulf %k0, %kr : f64
    %se = arith.addf %k0, %kr : f64
    %pe2 = arith.mulf %two, %pe : f64
    %ke = arith.divf %pe2, %se : f64
    %de = arith.subf %ur, %u0 : f64
    %dw = arith.subf %u0, %ul : f64
    %fe = arith.mulf %ke, %de : f64
    %fw = arith.mulf %kw, %dw : f64
    %div = arith.subf %fe, %fw : f64
    %fr = arith.sitofp %range : i64 to f64
    %h2inv = arith.mulf %fr, %fr : f64
    %rate = arith.mulf %div, %h2inv : f64
    %nf = arith.sitofp %n : i32 to f64
    %step = arith.mulf %nf, %dt : f64
    %u1 = math.fma %step, %rate, %u0 : f64
    sim.yield %u1 : f64
  }

  sim.total @Heat : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %h = arith.divf %u, %fr : f64
    sim.yield %h : f64
  }

  sim.observe [@U]
}
