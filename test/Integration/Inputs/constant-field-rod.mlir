// constant-field-rod: examples/physics/heat_rod.mlir with its conductivity
// as a constant buffer (@K, `constant`: no component writes it) instead of
// computed in each body. `--sim-inline-constants` computes @K's init where
// it is read (at i-1, i and i+1, under clamp), so every strategy gives the
// bits of heat_rod.mlir, whose bodies compute the same selects inline.
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

  sim.buffer @K : f64 constant init {
  ^bb0(%i: index):
    %range = sim.get_param @range : i64
    %c2_64 = arith.constant 2 : i64
    %mid = arith.divsi %range, %c2_64 : i64
    %ksoft = sim.get_param @k_soft : f64
    %ratio = sim.get_param @ratio : f64
    %kstiff = arith.mulf %ksoft, %ratio : f64
    %i64 = arith.index_cast %i : index to i64
    %r = arith.cmpi sge, %i64, %mid : i64
    %k = arith.select %r, %kstiff, %ksoft : f64
    sim.yield %k : f64
  }

  sim.component @Conduct writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %range = sim.get_param @range : i64
    %kl = sim.read @K[%il] : f64
    %k0 = sim.read @K[%i] : f64
    %kr = sim.read @K[%ir] : f64
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
    %kl = sim.read @K[%il] : f64
    %k0 = sim.read @K[%i] : f64
    %kr = sim.read @K[%ir] : f64
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
