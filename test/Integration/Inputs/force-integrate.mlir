// A chain of particles written the common way, as two components: @Force
// computes each particle's spring force from its neighbours' positions, and
// @Integrate steps the particle with it (symplectic Euler). The bonds in
// [range/3, range/2) are 100x stiffer, so their particles take 1 base step
// where the others take up to 16; a stretched bond also shortens its
// particles' steps (a state-dependent estimate in @Force). @Force reads @X
// through the back edge, so under hip its num_steps bounds the big step of
// the whole chain; under lts the two form an item pair (docs/Model.md, "Item
// pairs") and every block of 32 particles takes its own step. Range 1000
// (no multiple of a block), free ends (boundary clamp). @pattern 1 makes
// every num_steps 1 (lts then steps as simple does), 2 makes every
// num_steps 16 (every block at one level: lts steps as hip does). For
// item-pairs.test.
sim.simulation @force_integrate range(1000) dt(5.0e-2 : f64) max_steps(16) {
  sim.param @stiff = 1.0e2 : f64
  sim.param @pattern = 0 : i32

  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %range = sim.get_param @range : i64
    %fr = arith.sitofp %range : i64 to f64
    %q = arith.constant 2.5e-1 : f64
    %centre = arith.mulf %q, %fr : f64
    %d = arith.subf %fi, %centre : f64
    %w = arith.constant 1.5e1 : f64
    %z = arith.divf %d, %w : f64
    %z2 = arith.mulf %z, %z : f64
    %nz2 = arith.negf %z2 : f64
    %g = math.exp %nz2 : f64
    %amp = arith.constant 5.0e-1 : f64
    %x = arith.mulf %amp, %g : f64
    sim.yield %x : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @F : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Force writes(@F) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %x0 = sim.read @X[%i] : f64
    %xr = sim.read @X[%ir] : f64
    %i64 = arith.index_cast %i : index to i64
    %range = sim.get_param @range : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %lo = arith.divsi %range, %c3 : i64
    %hi = arith.divsi %range, %c2 : i64
    %one64 = arith.constant 1 : i64
    %il64 = arith.subi %i64, %one64 : i64
    %a = arith.cmpi sge, %i64, %lo : i64
    %b = arith.cmpi slt, %il64, %hi : i64
    %stiff = arith.andi %a, %b : i1
    %de = arith.subf %xr, %x0 : f64
    %dw = arith.subf %x0, %xl : f64
    %ae = math.absf %de : f64
    %aw = math.absf %dw : f64
    %dmax = arith.maximumf %ae, %aw : f64
    %lim = arith.constant 3.0e-2 : f64
    %stretched = arith.cmpf ogt, %dmax, %lim : f64
    %n1 = arith.constant 1 : i32
    %n4 = arith.constant 4 : i32
    %n16 = arith.constant 16 : i32
    %soft = arith.select %stretched, %n4, %n16 : i32
    %n = arith.select %stiff, %n1, %soft : i32
    %pattern = sim.get_param @pattern : i32
    %c1p = arith.constant 1 : i32
    %c2p = arith.constant 2 : i32
    %p1 = arith.cmpi eq, %pattern, %c1p : i32
    %p2 = arith.cmpi eq, %pattern, %c2p : i32
    %np1 = arith.select %p1, %n1, %n : i32
    %np = arith.select %p2, %n16, %np1 : i32
    sim.yield %np : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %x0 = sim.read @X[%i] : f64
    %xr = sim.read @X[%ir] : f64
    // Bond i (to i + 1) and bond i - 1, each stiff inside [range/3, range/2).
    %i64 = arith.index_cast %i : index to i64
    %range = sim.get_param @range : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %lo = arith.divsi %range, %c3 : i64
    %hi = arith.divsi %range, %c2 : i64
    %one64 = arith.constant 1 : i64
    %il64 = arith.subi %i64, %one64 : i64
    %one = arith.constant 1.0 : f64
    %k = sim.get_param @stiff : f64
    %ea = arith.cmpi sge, %i64, %lo : i64
    %eb = arith.cmpi slt, %i64, %hi : i64
    %ein = arith.andi %ea, %eb : i1
    %ke = arith.select %ein, %k, %one : f64
    %wa = arith.cmpi sge, %il64, %lo : i64
    %wb = arith.cmpi slt, %il64, %hi : i64
    %win = arith.andi %wa, %wb : i1
    %kw = arith.select %win, %k, %one : f64
    %de = arith.subf %xr, %x0 : f64
    %dw = arith.subf %x0, %xl : f64
    %fe = arith.mulf %ke, %de : f64
    %fw = arith.mulf %kw, %dw : f64
    %f = arith.subf %fe, %fw : f64
    sim.yield %f : f64
  }

  sim.component @Integrate writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    // The particle's own bound: its bonds' stiffness.
    %i64 = arith.index_cast %i : index to i64
    %range = sim.get_param @range : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %lo = arith.divsi %range, %c3 : i64
    %hi = arith.divsi %range, %c2 : i64
    %one64 = arith.constant 1 : i64
    %il64 = arith.subi %i64, %one64 : i64
    %a = arith.cmpi sge, %i64, %lo : i64
    %b = arith.cmpi slt, %il64, %hi : i64
    %stiff = arith.andi %a, %b : i1
    %n1 = arith.constant 1 : i32
    %n16 = arith.constant 16 : i32
    %n = arith.select %stiff, %n1, %n16 : i32
    %pattern = sim.get_param @pattern : i32
    %c2p = arith.constant 2 : i32
    %p1 = arith.cmpi eq, %pattern, %n1 : i32
    %p2 = arith.cmpi eq, %pattern, %c2p : i32
    %np1 = arith.select %p1, %n1, %n : i32
    %np = arith.select %p2, %n16, %np1 : i32
    sim.yield %np : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : f64
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %v1 = math.fma %h, %f, %v : f64
    %x1 = math.fma %h, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %x0 = sim.read @X[%i] : f64
    %xr = sim.read @X[%ir] : f64
    %v = sim.read @V[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %range = sim.get_param @range : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %lo = arith.divsi %range, %c3 : i64
    %hi = arith.divsi %range, %c2 : i64
    %one = arith.constant 1.0 : f64
    %k = sim.get_param @stiff : f64
    %ea = arith.cmpi sge, %i64, %lo : i64
    %eb = arith.cmpi slt, %i64, %hi : i64
    %ein = arith.andi %ea, %eb : i1
    %ke = arith.select %ein, %k, %one : f64
    %d = arith.subf %xr, %x0 : f64
    %d2 = arith.mulf %d, %d : f64
    %pe = arith.mulf %ke, %d2 : f64
    %v2 = arith.mulf %v, %v : f64
    %e2 = arith.addf %pe, %v2 : f64
    %half = arith.constant 5.0e-1 : f64
    %e = arith.mulf %half, %e2 : f64
    sim.yield %e : f64
  }
  sim.schedule [@Force, @Integrate]
  sim.observe [@X, @V]
}
