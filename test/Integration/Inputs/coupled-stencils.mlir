// Two coupled stencils, as a user writes them (coupled-stencils.test): U
// (boundary clamp) diffuses and is driven by V at its item; V (boundary
// zero) diffuses and reads U at i-2..i+2. The two depend on each other, so
// the scene names the first (sim.schedule). Both step counts depend on the
// state: @A's is 1 wherever U > 0.7, so the big step is 1 throughout and
// @B's grid-wide rounds (and lts slots) after its first sub-step have
// nothing to do.
sim.simulation @pair range(777) dt(1.0e-4 : f64) max_steps(32) {
  sim.param @k = 5.0e-7 : f64

  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 0.0125 : f64
    %x = arith.mulf %fi, %c : f64
    %s = math.sin %x : f64
    sim.yield %s : f64
  }
  sim.buffer @V : f64 interp(#sim.linear) boundary(zero) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 0.031 : f64
    %x = arith.mulf %fi, %c : f64
    %s = math.cos %x : f64
    sim.yield %s : f64
  }

  sim.component @A writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %u = sim.read @U[%i] : f64
    %th = arith.constant 0.7 : f64
    %big = arith.cmpf ogt, %u, %th : f64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %big, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %ul = sim.read @U[%il] : f64
    %u0 = sim.read @U[%i] : f64
    %ur = sim.read @U[%ir] : f64
    %v = sim.read @V[%i] : f64
    %s = arith.addf %ul, %ur : f64
    %two = arith.constant 2.0 : f64
    %d = arith.mulf %two, %u0 : f64
    %lap = arith.subf %s, %d : f64
    %k = sim.get_param @k : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %kh = arith.mulf %k, %h : f64
    %r0 = arith.mulf %kh, %lap : f64
    %c = arith.constant 1.0e-3 : f64
    %hv = arith.mulf %h, %v : f64
    %r1 = math.fma %c, %hv, %r0 : f64
    %u1 = arith.addf %u0, %r1 : f64
    sim.yield %u1 : f64
  }

  sim.component @B writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %u = sim.read @U[%i] : f64
    %th = arith.constant -0.5 : f64
    %small = arith.cmpf olt, %u, %th : f64
    %c2 = arith.constant 2 : i32
    %c16 = arith.constant 16 : i32
    %n = arith.select %small, %c2, %c16 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %il2 = arith.subi %i, %c2 : index
    %ir2 = arith.addi %i, %c2 : index
    %vl = sim.read @V[%il] : f64
    %v0 = sim.read @V[%i] : f64
    %vr = sim.read @V[%ir] : f64
    %ua = sim.read @U[%il2] : f64
    %ub = sim.read @U[%ir2] : f64
    %s = arith.addf %vl, %vr : f64
    %two = arith.constant 2.0 : f64
    %d = arith.mulf %two, %v0 : f64
    %lap = arith.subf %s, %d : f64
    %k = sim.get_param @k : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %kh = arith.mulf %k, %h : f64
    %r0 = arith.mulf %kh, %lap : f64
    %du = arith.subf %ub, %ua : f64
    %c = arith.constant 2.0e-3 : f64
    %hd = arith.mulf %h, %du : f64
    %r1 = math.fma %c, %hd, %r0 : f64
    %v1 = arith.addf %v0, %r1 : f64
    sim.yield %v1 : f64
  }

  sim.schedule [@A]
  sim.observe [@U, @V]
}
