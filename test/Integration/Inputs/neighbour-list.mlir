// A ring of 1024 particles bonded through a neighbour list (f64): every
// particle reads the positions of the four partners its constant @Nbr
// lists (i-1, i+1, i-2-(i mod 3), i+2+(i mod 2): irregular, as a list built
// from positions is), and the body clamps each entry to i-4..i+4, the
// reach the list is built with (arith.maxsi, arith.minsi). The dependency
// analysis bounds the clamped read as the window i-4..i+4, so under lts
// the blocks of 32 particles take local time steps. Particles 256..383 are
// 16x lighter and ask for @fine steps (1), the others for @coarse (16).
// Symplectic Euler: v += s f / m, x += s v, f the sum of the partners'
// displacements x_j - x_i. The total is the momentum.
sim.simulation @neighbour_list range(1024) dt(1.0e-3 : f64) max_steps(16) {
  sim.param @light = 6.25e-2 : f64
  sim.param @fine = 1 : i64
  sim.param @coarse = 16 : i64
  sim.buffer @Nbr : vector<4xf64> constant init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %c1 = arith.constant 1 : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %r2 = arith.remsi %i64, %c2 : i64
    %r3 = arith.remsi %i64, %c3 : i64
    %a = arith.subi %i64, %c1 : i64
    %b = arith.addi %i64, %c1 : i64
    %c0 = arith.subi %i64, %c2 : i64
    %c = arith.subi %c0, %r3 : i64
    %d0 = arith.addi %i64, %c2 : i64
    %d = arith.addi %d0, %r2 : i64
    %fa = arith.sitofp %a : i64 to f64
    %fb = arith.sitofp %b : i64 to f64
    %fc = arith.sitofp %c : i64 to f64
    %fd = arith.sitofp %d : i64 to f64
    %v0 = arith.constant dense<0.0> : vector<4xf64>
    %v1 = vector.insert %fa, %v0[0] : f64 into vector<4xf64>
    %v2 = vector.insert %fb, %v1[1] : f64 into vector<4xf64>
    %v3 = vector.insert %fc, %v2[2] : f64 into vector<4xf64>
    %v4 = vector.insert %fd, %v3[3] : f64 into vector<4xf64>
    sim.yield %v4 : vector<4xf64>
  }
  sim.buffer @X : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 3.0e-2 : f64
    %a = arith.mulf %f, %c : f64
    %x = math.sin %a : f64
    sim.yield %x : f64
  }
  sim.buffer @V : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Move writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 256 : index
    %hi = arith.constant 384 : index
    %a = arith.cmpi sge, %i, %lo : index
    %b = arith.cmpi slt, %i, %hi : index
    %in = arith.andi %a, %b : i1
    %fine = sim.get_param @fine : i64
    %coarse = sim.get_param @coarse : i64
    %n64 = arith.select %in, %fine, %coarse : i64
    %n = arith.trunci %n64 : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %nb = sim.read @Nbr[%i] : vector<4xf64>
    %x0 = sim.read @X[%i] : f64
    %v0 = sim.read @V[%i] : f64
    %c4 = arith.constant 4 : index
    %below = arith.subi %i, %c4 : index
    %above = arith.addi %i, %c4 : index
    %p0 = vector.extract %nb[0] : f64 from vector<4xf64>
    %p0i = arith.fptosi %p0 : f64 to i64
    %g0 = arith.index_cast %p0i : i64 to index
    %l0 = arith.maxsi %g0, %below : index
    %j0 = arith.minsi %l0, %above : index
    %xn0 = sim.read @X[%j0] : f64
    %e0 = arith.subf %xn0, %x0 : f64
    %p1 = vector.extract %nb[1] : f64 from vector<4xf64>
    %p1i = arith.fptosi %p1 : f64 to i64
    %g1 = arith.index_cast %p1i : i64 to index
    %l1 = arith.maxsi %g1, %below : index
    %j1 = arith.minsi %l1, %above : index
    %xn1 = sim.read @X[%j1] : f64
    %e1 = arith.subf %xn1, %x0 : f64
    %p2 = vector.extract %nb[2] : f64 from vector<4xf64>
    %p2i = arith.fptosi %p2 : f64 to i64
    %g2 = arith.index_cast %p2i : i64 to index
    %l2 = arith.maxsi %g2, %below : index
    %j2 = arith.minsi %l2, %above : index
    %xn2 = sim.read @X[%j2] : f64
    %e2 = arith.subf %xn2, %x0 : f64
    %p3 = vector.extract %nb[3] : f64 from vector<4xf64>
    %p3i = arith.fptosi %p3 : f64 to i64
    %g3 = arith.index_cast %p3i : i64 to index
    %l3 = arith.maxsi %g3, %below : index
    %j3 = arith.minsi %l3, %above : index
    %xn3 = sim.read @X[%j3] : f64
    %e3 = arith.subf %xn3, %x0 : f64
    %s01 = arith.addf %e0, %e1 : f64
    %s23 = arith.addf %e2, %e3 : f64
    %f = arith.addf %s01, %s23 : f64
    %lo = arith.constant 256 : index
    %hi = arith.constant 384 : index
    %a = arith.cmpi sge, %i, %lo : index
    %b = arith.cmpi slt, %i, %hi : index
    %in = arith.andi %a, %b : i1
    %light = sim.get_param @light : f64
    %heavy = arith.constant 1.0 : f64
    %m = arith.select %in, %light, %heavy : f64
    %acc = arith.divf %f, %m : f64
    %nf = arith.sitofp %n : i32 to f64
    %s = arith.mulf %nf, %dt : f64
    %v1 = math.fma %s, %acc, %v0 : f64
    %x1 = math.fma %s, %v1, %x0 : f64
    sim.yield %x1, %v1 : f64, f64
  }
  sim.total @Momentum : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : f64
    %lo = arith.constant 256 : index
    %hi = arith.constant 384 : index
    %a = arith.cmpi sge, %i, %lo : index
    %b = arith.cmpi slt, %i, %hi : index
    %in = arith.andi %a, %b : i1
    %light = sim.get_param @light : f64
    %heavy = arith.constant 1.0 : f64
    %m = arith.select %in, %light, %heavy : f64
    %p = arith.mulf %m, %v : f64
    sim.yield %p : f64
  }
  sim.observe [@X, @V]
}
