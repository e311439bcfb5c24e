// nbody: a softened gravitational N-body system, a Plummer sphere (f64).
//
// Physics. range (256) bodies of mass 1/range, G = 1, total mass 1, Plummer
// scale length 1 (crossing time about 1), softening @eps = 0.05:
//   x_i'' = sum_j m (x_j - x_i) / (|x_j - x_i|^2 + eps^2)^(3/2).
// Initial conditions are deterministic: item i draws its uniforms from
// splitmix64 of 16 i + k (as examples/paper does): the Plummer radius
// r = (u^(-2/3) - 1)^(-1/2) (the outer 0.1 % of the mass cut off), an
// isotropic direction, and a speed q v_esc(r) with q drawn by rejection from
// q^2 (1 - q^2)^(7/2) (up to 64 tries, keys 8 (64 i + try) + 5, + 6). There is
// no closed-form solution: the reference is `simple` at a finer base step
// (python/accuracy_study.py runs it at dt / 8 and compares the dumps).
//
// Components (kick-drift split, symplectic Euler at a fixed step:
// v += h a(x); x += h v):
//   @Kick   (first) writes @V; reads @A[i] through the back edge (the
//           acceleration at T). num_steps = floor(@eta sqrt(@eps / |a|) / dt),
//           the usual acceleration criterion: close encounters take small
//           steps.
//   @Drift  writes @X; reads @V[i] after this step's kick (interpolated).
//   @Force  writes @A; reads @X[j] for every j (an scf.for to @range: the
//           compiler treats it as a gather), the all-pairs sum.
// Because @Kick reads through the back edge and has num_steps, both hip and
// traditional take the global minimum of its num_steps as the big step: this
// is a shared adaptive time step, not per-item multirate (a per-item step
// would need the force of every body at every sub-step time of every other,
// which a back-edge read cannot give). @Drift and @Force take the whole big
// step in one evaluation. With @eta = 0.02 and dt = 1e-3 the big step is a
// few base steps (max_steps 16).
//
// Observed: @X and @V (energy can be computed from the dump).
sim.simulation @nbody range(256) dt(1.0e-3 : f64) max_steps(16) {
  // Plummer softening length.
  sim.param @eps = 5.0e-2 : f64
  // num_steps = floor(@eta sqrt(@eps / |a|) / dt).
  sim.param @eta = 2.0e-2 : f64

  sim.buffer @X : vector<3xf64> init {
  ^bb0(%i: index):
    %golden = arith.constant -7046029254386353131 : i64 // 0x9E3779B97F4A7C15
    %mix1 = arith.constant -4658895280553007687 : i64 // 0xBF58476D1CE4E5B9
    %mix2 = arith.constant -7723592293110705685 : i64 // 0x94D049BB133111EB
    %c30 = arith.constant 30 : i64
    %c27 = arith.constant 27 : i64
    %c31 = arith.constant 31 : i64
    %c11 = arith.constant 11 : i64
    %c16 = arith.constant 16 : i64
    %two_m53 = arith.constant 1.1102230246251565E-16 : f64 // 2^-53
    %two_m54 = arith.constant 5.5511151231257827E-17 : f64 // 2^-54
    %one = arith.constant 1.0 : f64
    %two = arith.constant 2.0 : f64
    %twopi = arith.constant 6.283185307179586 : f64
    %i64 = arith.index_cast %i : index to i64
    %key = arith.muli %i64, %c16 : i64
    %k0c = arith.constant 0 : i64
    %k0 = arith.addi %key, %k0c : i64
    %k1c = arith.constant 1 : i64
    %k1 = arith.addi %key, %k1c : i64
    %k2c = arith.constant 2 : i64
    %k2 = arith.addi %key, %k2c : i64
    %u0_x = arith.addi %k0, %golden : i64
    %u0_s1 = arith.shrui %u0_x, %c30 : i64
    %u0_z1 = arith.xori %u0_x, %u0_s1 : i64
    %u0_z2 = arith.muli %u0_z1, %mix1 : i64
    %u0_s2 = arith.shrui %u0_z2, %c27 : i64
    %u0_z3 = arith.xori %u0_z2, %u0_s2 : i64
    %u0_z4 = arith.muli %u0_z3, %mix2 : i64
    %u0_s3 = arith.shrui %u0_z4, %c31 : i64
    %u0_z5 = arith.xori %u0_z4, %u0_s3 : i64
    %u0_top = arith.shrui %u0_z5, %c11 : i64
    %u0_f = arith.uitofp %u0_top : i64 to f64
    %u0 = math.fma %u0_f, %two_m53, %two_m54 : f64
    %u1_x = arith.addi %k1, %golden : i64
    %u1_s1 = arith.shrui %u1_x, %c30 : i64
    %u1_z1 = arith.xori %u1_x, %u1_s1 : i64
    %u1_z2 = arith.muli %u1_z1, %mix1 : i64
    %u1_s2 = arith.shrui %u1_z2, %c27 : i64
    %u1_z3 = arith.xori %u1_z2, %u1_s2 : i64
    %u1_z4 = arith.muli %u1_z3, %mix2 : i64
    %u1_s3 = arith.shrui %u1_z4, %c31 : i64
    %u1_z5 = arith.xori %u1_z4, %u1_s3 : i64
    %u1_top = arith.shrui %u1_z5, %c11 : i64
    %u1_f = arith.uitofp %u1_top : i64 to f64
    %u1 = math.fma %u1_f, %two_m53, %two_m54 : f64
    %u2_x = arith.addi %k2, %golden : i64
    %u2_s1 = arith.shrui %u2_x, %c30 : i64
    %u2_z1 = arith.xori %u2_x, %u2_s1 : i64
    %u2_z2 = arith.muli %u2_z1, %mix1 : i64
    %u2_s2 = arith.shrui %u2_z2, %c27 : i64
    %u2_z3 = arith.xori %u2_z2, %u2_s2 : i64
    %u2_z4 = arith.muli %u2_z3, %mix2 : i64
    %u2_s3 = arith.shrui %u2_z4, %c31 : i64
    %u2_z5 = arith.xori %u2_z4, %u2_s3 : i64
    %u2_top = arith.shrui %u2_z5, %c11 : i64
    %u2_f = arith.uitofp %u2_top : i64 to f64
    %u2 = math.fma %u2_f, %two_m53, %two_m54 : f64
    // Plummer radius (a = 1): r = 1 / sqrt(u^(-2/3) - 1), with u = 0.999 u0
    // (the outermost 0.1 % of the mass is cut off).
    %cut = arith.constant 0.999 : f64
    %m = arith.mulf %u0, %cut : f64
    %mm23 = arith.constant -0.66666666666666663 : f64
    %p = math.powf %m, %mm23 : f64
    %p1 = arith.subf %p, %one : f64
    %sq = math.sqrt %p1 : f64
    %r = arith.divf %one, %sq : f64
    %dir_ct0 = arith.mulf %two, %u1 : f64
    %dir_ct = arith.subf %dir_ct0, %one : f64
    %dir_ct2 = arith.mulf %dir_ct, %dir_ct : f64
    %dir_st2 = arith.subf %one, %dir_ct2 : f64
    %dir_st = math.sqrt %dir_st2 : f64
    %dir_ph = arith.mulf %twopi, %u2 : f64
    %dir_cp = math.cos %dir_ph : f64
    %dir_sp = math.sin %dir_ph : f64
    %dir_x = arith.mulf %dir_st, %dir_cp : f64
    %dir_y = arith.mulf %dir_st, %dir_sp : f64
    %dir = vector.from_elements %dir_x, %dir_y, %dir_ct : vector<3xf64>
    %rv = vector.broadcast %r : f64 to vector<3xf64>
    %x = arith.mulf %rv, %dir : vector<3xf64>
    sim.yield %x : vector<3xf64>
  }
  sim.buffer @V : vector<3xf64> init {
  ^bb0(%i: index):
    %golden = arith.constant -7046029254386353131 : i64 // 0x9E3779B97F4A7C15
    %mix1 = arith.constant -4658895280553007687 : i64 // 0xBF58476D1CE4E5B9
    %mix2 = arith.constant -7723592293110705685 : i64 // 0x94D049BB133111EB
    %c30 = arith.constant 30 : i64
    %c27 = arith.constant 27 : i64
    %c31 = arith.constant 31 : i64
    %c11 = arith.constant 11 : i64
    %c16 = arith.constant 16 : i64
    %two_m53 = arith.constant 1.1102230246251565E-16 : f64 // 2^-53
    %two_m54 = arith.constant 5.5511151231257827E-17 : f64 // 2^-54
    %one = arith.constant 1.0 : f64
    %two = arith.constant 2.0 : f64
    %twopi = arith.constant 6.283185307179586 : f64
    %i64 = arith.index_cast %i : index to i64
    %key = arith.muli %i64, %c16 : i64
    %k3c = arith.constant 3 : i64
    %k3 = arith.addi %key, %k3c : i64
    %k4c = arith.constant 4 : i64
    %k4 = arith.addi %key, %k4c : i64
    %u3_x = arith.addi %k3, %golden : i64
    %u3_s1 = arith.shrui %u3_x, %c30 : i64
    %u3_z1 = arith.xori %u3_x, %u3_s1 : i64
    %u3_z2 = arith.muli %u3_z1, %mix1 : i64
    %u3_s2 = arith.shrui %u3_z2, %c27 : i64
    %u3_z3 = arith.xori %u3_z2, %u3_s2 : i64
    %u3_z4 = arith.muli %u3_z3, %mix2 : i64
    %u3_s3 = arith.shrui %u3_z4, %c31 : i64
    %u3_z5 = arith.xori %u3_z4, %u3_s3 : i64
    %u3_top = arith.shrui %u3_z5, %c11 : i64
    %u3_f = arith.uitofp %u3_top : i64 to f64
    %u3 = math.fma %u3_f, %two_m53, %two_m54 : f64
    %u4_x = arith.addi %k4, %golden : i64
    %u4_s1 = arith.shrui %u4_x, %c30 : i64
    %u4_z1 = arith.xori %u4_x, %u4_s1 : i64
    %u4_z2 = arith.muli %u4_z1, %mix1 : i64
    %u4_s2 = arith.shrui %u4_z2, %c27 : i64
    %u4_z3 = arith.xori %u4_z2, %u4_s2 : i64
    %u4_z4 = arith.muli %u4_z3, %mix2 : i64
    %u4_s3 = arith.shrui %u4_z4, %c31 : i64
    %u4_z5 = arith.xori %u4_z4, %u4_s3 : i64
    %u4_top = arith.shrui %u4_z5, %c11 : i64
    %u4_f = arith.uitofp %u4_top : i64 to f64
    %u4 = math.fma %u4_f, %two_m53, %two_m54 : f64
    %x = sim.read @X[%i] : vector<3xf64>
    %x2 = arith.mulf %x, %x : vector<3xf64>
    %zero = arith.constant 0.0 : f64
    %r2 = vector.reduction <add>, %x2, %zero : vector<3xf64> into f64
    // Speed q * v_esc, v_esc = sqrt(2) (1 + r^2)^(-1/4), q drawn from
    // g(q) = q^2 (1 - q^2)^(7/2) by rejection (Aarseth, Henon and Wielen
    // 1974) with up to 64 deterministic tries; 0.5 if all fail.
    %lo = arith.constant 0 : index
    %hi = arith.constant 64 : index
    %st = arith.constant 1 : index
    %c64 = arith.constant 64 : i64
    %c8 = arith.constant 8 : i64
    %tenth = arith.constant 0.1 : f64
    %q0 = arith.constant 0.5 : f64
    %false = arith.constant false
    %seven2 = arith.constant 3.5 : f64
    %res:2 = scf.for %k = %lo to %hi step %st iter_args(%q = %q0, %found = %false) -> (f64, i1) {
      %k64 = arith.index_cast %k : index to i64
      %base0 = arith.muli %i64, %c64 : i64
      %base1 = arith.addi %base0, %k64 : i64
      %base = arith.muli %base1, %c8 : i64
      %kb = arith.constant 5 : i64
      %ka = arith.addi %base, %kb : i64
      %kc1 = arith.constant 1 : i64
      %kd = arith.addi %ka, %kc1 : i64
      %xa_x = arith.addi %ka, %golden : i64
      %xa_s1 = arith.shrui %xa_x, %c30 : i64
      %xa_z1 = arith.xori %xa_x, %xa_s1 : i64
      %xa_z2 = arith.muli %xa_z1, %mix1 : i64
      %xa_s2 = arith.shrui %xa_z2, %c27 : i64
      %xa_z3 = arith.xori %xa_z2, %xa_s2 : i64
      %xa_z4 = arith.muli %xa_z3, %mix2 : i64
      %xa_s3 = arith.shrui %xa_z4, %c31 : i64
      %xa_z5 = arith.xori %xa_z4, %xa_s3 : i64
      %xa_top = arith.shrui %xa_z5, %c11 : i64
      %xa_f = arith.uitofp %xa_top : i64 to f64
      %xa = math.fma %xa_f, %two_m53, %two_m54 : f64
      %xb_x = arith.addi %kd, %golden : i64
      %xb_s1 = arith.shrui %xb_x, %c30 : i64
      %xb_z1 = arith.xori %xb_x, %xb_s1 : i64
      %xb_z2 = arith.muli %xb_z1, %mix1 : i64
      %xb_s2 = arith.shrui %xb_z2, %c27 : i64
      %xb_z3 = arith.xori %xb_z2, %xb_s2 : i64
      %xb_z4 = arith.muli %xb_z3, %mix2 : i64
      %xb_s3 = arith.shrui %xb_z4, %c31 : i64
      %xb_z5 = arith.xori %xb_z4, %xb_s3 : i64
      %xb_top = arith.shrui %xb_z5, %c11 : i64
      %xb_f = arith.uitofp %xb_top : i64 to f64
      %xb = math.fma %xb_f, %two_m53, %two_m54 : f64
      %xa2 = arith.mulf %xa, %xa : f64
      %oma = arith.subf %one, %xa2 : f64
      %pw = math.powf %oma, %seven2 : f64
      %g = arith.mulf %xa2, %pw : f64
      %y = arith.mulf %tenth, %xb : f64
      %acc = arith.cmpf olt, %y, %g : f64
      %nf = arith.constant true
      %notfound = arith.xori %found, %nf : i1
      %take = arith.andi %acc, %notfound : i1
      %q1 = arith.select %take, %xa, %q : f64
      %f1 = arith.ori %found, %acc : i1
      scf.yield %q1, %f1 : f64, i1
    }
    %r2p = arith.addf %one, %r2 : f64
    %mq = arith.constant -0.25 : f64
    %pr = math.powf %r2p, %mq : f64
    %sqrt2 = arith.constant 1.4142135623730951 : f64
    %vesc = arith.mulf %sqrt2, %pr : f64
    %speed = arith.mulf %res#0, %vesc : f64
    %dir_ct0 = arith.mulf %two, %u3 : f64
    %dir_ct = arith.subf %dir_ct0, %one : f64
    %dir_ct2 = arith.mulf %dir_ct, %dir_ct : f64
    %dir_st2 = arith.subf %one, %dir_ct2 : f64
    %dir_st = math.sqrt %dir_st2 : f64
    %dir_ph = arith.mulf %twopi, %u4 : f64
    %dir_cp = math.cos %dir_ph : f64
    %dir_sp = math.sin %dir_ph : f64
    %dir_x = arith.mulf %dir_st, %dir_cp : f64
    %dir_y = arith.mulf %dir_st, %dir_sp : f64
    %dir = vector.from_elements %dir_x, %dir_y, %dir_ct : vector<3xf64>
    %sv = vector.broadcast %speed : f64 to vector<3xf64>
    %v = arith.mulf %sv, %dir : vector<3xf64>
    sim.yield %v : vector<3xf64>
  }
  sim.buffer @A : vector<3xf64> init {
  ^bb0(%i: index):
    %xi = sim.read @X[%i] : vector<3xf64>
    %eps = sim.get_param @eps : f64
    %eps2 = arith.mulf %eps, %eps : f64
    %range = sim.get_param @range : i64
    %nb = arith.index_cast %range : i64 to index
    %fr = arith.sitofp %range : i64 to f64
    %one = arith.constant 1.0 : f64
    %mass = arith.divf %one, %fr : f64
    %lo = arith.constant 0 : index
    %st = arith.constant 1 : index
    %zero = arith.constant 0.0 : f64
    %zv = arith.constant dense<0.0> : vector<3xf64>
    // All pairs: a_i = sum_j m (x_j - x_i) / (|x_j - x_i|^2 + eps^2)^(3/2).
    %acc = scf.for %j = %lo to %nb step %st iter_args(%a = %zv) -> (vector<3xf64>) {
      %xj = sim.read @X[%j] : vector<3xf64>
      %d = arith.subf %xj, %xi : vector<3xf64>
      %d2v = arith.mulf %d, %d : vector<3xf64>
      %d2 = vector.reduction <add>, %d2v, %eps2 : vector<3xf64> into f64
      %rinv = math.rsqrt %d2 : f64
      %rinv2 = arith.mulf %rinv, %rinv : f64
      %rinv3 = arith.mulf %rinv2, %rinv : f64
      %s = arith.mulf %mass, %rinv3 : f64
      %sv = vector.broadcast %s : f64 to vector<3xf64>
      %a1 = vector.fma %sv, %d, %a : vector<3xf64>
      scf.yield %a1 : vector<3xf64>
    }
    sim.yield %acc : vector<3xf64>
  }

  sim.component @Kick writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %a = sim.read @A[%i] : vector<3xf64>
    %a2v = arith.mulf %a, %a : vector<3xf64>
    %tiny = arith.constant 1.0e-30 : f64
    %a2 = vector.reduction <add>, %a2v, %tiny : vector<3xf64> into f64
    %am = math.sqrt %a2 : f64
    %eps = sim.get_param @eps : f64
    %eta = sim.get_param @eta : f64
    %dt = sim.get_param @dt : f64
    %ea = arith.divf %eps, %am : f64
    %s = math.sqrt %ea : f64
    %es = arith.mulf %eta, %s : f64
    %q = arith.divf %es, %dt : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : vector<3xf64>
    // The acceleration at T (back edge).
    %a = sim.read @A[%i] : vector<3xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hv = vector.broadcast %h : f64 to vector<3xf64>
    %v1 = vector.fma %hv, %a, %v : vector<3xf64>
    sim.yield %v1 : vector<3xf64>
  }

  sim.component @Drift writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : vector<3xf64>
    // The velocity after this step's kick.
    %v = sim.read @V[%i] : vector<3xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hv = vector.broadcast %h : f64 to vector<3xf64>
    %x1 = vector.fma %hv, %v, %x : vector<3xf64>
    sim.yield %x1 : vector<3xf64>
  }

  sim.component @Force writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %xi = sim.read @X[%i] : vector<3xf64>
    %eps = sim.get_param @eps : f64
    %eps2 = arith.mulf %eps, %eps : f64
    %range = sim.get_param @range : i64
    %nb = arith.index_cast %range : i64 to index
    %fr = arith.sitofp %range : i64 to f64
    %one = arith.constant 1.0 : f64
    %mass = arith.divf %one, %fr : f64
    %lo = arith.constant 0 : index
    %st = arith.constant 1 : index
    %zero = arith.constant 0.0 : f64
    %zv = arith.constant dense<0.0> : vector<3xf64>
    // All pairs: a_i = sum_j m (x_j - x_i) / (|x_j - x_i|^2 + eps^2)^(3/2).
    %acc = scf.for %j = %lo to %nb step %st iter_args(%a = %zv) -> (vector<3xf64>) {
      %xj = sim.read @X[%j] : vector<3xf64>
      %d = arith.subf %xj, %xi : vector<3xf64>
      %d2v = arith.mulf %d, %d : vector<3xf64>
      %d2 = vector.reduction <add>, %d2v, %eps2 : vector<3xf64> into f64
      %rinv = math.rsqrt %d2 : f64
      %rinv2 = arith.mulf %rinv, %rinv : f64
      %rinv3 = arith.mulf %rinv2, %rinv : f64
      %s = arith.mulf %mass, %rinv3 : f64
      %sv = vector.broadcast %s : f64 to vector<3xf64>
      %a1 = vector.fma %sv, %d, %a : vector<3xf64>
      scf.yield %a1 : vector<3xf64>
    }
    sim.yield %acc : vector<3xf64>
  }

  // The total energy, computed on the device at every output time
  // (`sim-run --report-every N`): per body m v^2 / 2 plus half its softened
  // potential energy with every other body, -m^2 / sqrt(d^2 + eps^2) (the
  // softening pairs each body with itself too: a constant, eps-dependent
  // offset that does not change the drift). And the total momentum along x.
  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %xi = sim.read @X[%i] : vector<3xf64>
    %vi = sim.read @V[%i] : vector<3xf64>
    %eps = sim.get_param @eps : f64
    %eps2 = arith.mulf %eps, %eps : f64
    %range = sim.get_param @range : i64
    %nb = arith.index_cast %range : i64 to index
    %fr = arith.sitofp %range : i64 to f64
    %one = arith.constant 1.0 : f64
    %half = arith.constant 0.5 : f64
    %mass = arith.divf %one, %fr : f64
    %zero = arith.constant 0.0 : f64
    %v2v = arith.mulf %vi, %vi : vector<3xf64>
    %v2 = vector.reduction <add>, %v2v, %zero : vector<3xf64> into f64
    %mv2 = arith.mulf %mass, %v2 : f64
    %kinetic = arith.mulf %half, %mv2 : f64
    %lo = arith.constant 0 : index
    %st = arith.constant 1 : index
    %sum = scf.for %j = %lo to %nb step %st iter_args(%p = %zero) -> (f64) {
      %xj = sim.read @X[%j] : vector<3xf64>
      %d = arith.subf %xj, %xi : vector<3xf64>
      %d2v = arith.mulf %d, %d : vector<3xf64>
      %d2 = vector.reduction <add>, %d2v, %eps2 : vector<3xf64> into f64
      %rinv = math.rsqrt %d2 : f64
      %p1 = arith.addf %p, %rinv : f64
      scf.yield %p1 : f64
    }
    %m2 = arith.mulf %mass, %mass : f64
    %pm = arith.mulf %m2, %sum : f64
    %halfp = arith.mulf %half, %pm : f64
    %e = arith.subf %kinetic, %halfp : f64
    sim.yield %e : f64
  }
  sim.total @MomentumX : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : vector<3xf64>
    %vx = vector.extract %v[0] : f64 from vector<3xf64>
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %p = arith.divf %vx, %fr : f64
    sim.yield %p : f64
  }

  sim.schedule [@Kick, @Drift, @Force]
  sim.observe [@X, @V]
}
