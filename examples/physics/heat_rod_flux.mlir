// heat_rod_flux: the heat rod of heat_rod.mlir (4096 cells, conductivity
// 100x between the halves, insulated ends) written in flux form (f64): one
// component computes the heat flux through every interface, a second
// updates the cells from the fluxes on their two sides.
//
// Physics. Cell i (width h = 1 / range) holds temperature u_i; interface j
// lies between cells j and j + 1 and carries the flux
//   F_j = k_{j+1/2} (u_{j+1} - u_j) / h,
// with k_{j+1/2} the harmonic mean of the two cells' conductivities (0 at
// the top end: the missing cell has the end cell's temperature, boundary
// clamp). Forward Euler on
//   u_i' = (F_i - F_{i-1}) / h,
// with F_{-1} = 0 (@F has boundary zero): no heat leaves the rod, so the
// total heat sum_i u_i h (@Heat) is conserved by the scheme up to round-off,
// whatever step each cell takes, as long as the two cells of an interface
// integrate the same flux over the same time. Initially u_i = 1 + cos(2 pi
// x_i), x_i = (i + 1/2) h.
//
// @F has interp(#sim.flux): its value is the flux over its writer's whole
// step, so every reader of an interface integrates the same amount. Under
// lts (docs/Model.md, "Conservation") the interface steps with the coarser
// of its two cells' blocks, and each cell adds its share of that flux in
// its own sub-steps: the total stays conserved to round-off while the soft
// half takes up to 64x longer steps than the stiff half.
//
// Both components estimate explicit diffusion's bound n dt k / h^2 <= 1/2
// at @cfl (0.4) of it: @Flux for its interface's conductivity, @Cells for
// the largest conductivity a cell meets. At the default dt (2e-8) the
// stiff half takes 1 base step, the soft half 119 (capped at max_steps =
// 64). Under hip @Flux reads @U through the back edge, so its estimate
// bounds the big step of the whole rod: no gain. The reference solution is
// `simple` at a finer base step (the accuracy study's dt / 16).
//
// Observed: @U. Total: @Heat.
sim.simulation @heat_rod_flux range(4096) dt(2.0e-8 : f64) max_steps(64) {
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

  // F_j: the flux from cell j + 1 into cell j, per unit time.
  sim.buffer @F : f64 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.schedule [@Flux]

  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %range = sim.get_param @range : i64
    %c2_64 = arith.constant 2 : i64
    %mid = arith.divsi %range, %c2_64 : i64
    %ksoft = sim.get_param @k_soft : f64
    %ratio = sim.get_param @ratio : f64
    %kstiff = arith.mulf %ksoft, %ratio : f64
    %kl_i = arith.index_cast %j : index to i64
    %kl_r = arith.cmpi sge, %kl_i, %mid : i64
    %kl = arith.select %kl_r, %kstiff, %ksoft : f64
    %kr_i = arith.index_cast %jr : index to i64
    %kr_r = arith.cmpi sge, %kr_i, %mid : i64
    %kr = arith.select %kr_r, %kstiff, %ksoft : f64
    %kmax = arith.maximumf %kl, %kr : f64
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
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %ul = sim.read @U[%j] : f64
    %ur = sim.read @U[%jr] : f64
    %range = sim.get_param @range : i64
    %c2_64 = arith.constant 2 : i64
    %mid = arith.divsi %range, %c2_64 : i64
    %ksoft = sim.get_param @k_soft : f64
    %ratio = sim.get_param @ratio : f64
    %kstiff = arith.mulf %ksoft, %ratio : f64
    %kl_i = arith.index_cast %j : index to i64
    %kl_r = arith.cmpi sge, %kl_i, %mid : i64
    %kl = arith.select %kl_r, %kstiff, %ksoft : f64
    %kr_i = arith.index_cast %jr : index to i64
    %kr_r = arith.cmpi sge, %kr_i, %mid : i64
    %kr = arith.select %kr_r, %kstiff, %ksoft : f64
    // The interface's conductivity: the harmonic mean 2 a b / (a + b).
    %two = arith.constant 2.0 : f64
    %p = arith.mulf %kl, %kr : f64
    %s = arith.addf %kl, %kr : f64
    %p2 = arith.mulf %two, %p : f64
    %k = arith.divf %p2, %s : f64
    %du = arith.subf %ur, %ul : f64
    %fr = arith.sitofp %range : i64 to f64
    %grad = arith.mulf %du, %fr : f64
    %flux = arith.mulf %k, %grad : f64
    sim.yield %flux : f64
  }

  sim.component @Cells writes(@U) num_steps {
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
    %fw = sim.read @F[%il] : f64
    %fe = sim.read @F[%i] : f64
    %u0 = sim.read @U[%i] : f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %div = arith.subf %fe, %fw : f64
    %rate = arith.mulf %div, %fr : f64
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
