// A 64 x 64 plate stored row by row (4096 cells), heat equation with a disk
// 50 times stiffer in the middle: one component reads its own neighbours
// at i - 64, i - 1, i + 1 and i + 64 (a window of -64..64 under clamp, the
// row and column edges masked by the scene itself), num_steps 1 in the disk
// and 16 outside. Written the way a user would, for user-scenes.test.
sim.simulation @plate range(4096) dt(2.0e-7 : f64) max_steps(32) {
  sim.param @k = 1.0 : f64
  sim.param @ratio = 50.0 : f64

  sim.buffer @T : f64 interp(#sim.linear) boundary(clamp) init {
  ^bb0(%i: index):
    %c64 = arith.constant 64 : index
    %row = arith.divui %i, %c64 : index
    %col = arith.remui %i, %c64 : index
    %r = arith.index_cast %row : index to i64
    %c = arith.index_cast %col : index to i64
    %rf = arith.sitofp %r : i64 to f64
    %cf = arith.sitofp %c : i64 to f64
    %s = arith.constant 0.1 : f64
    %a = arith.mulf %rf, %s : f64
    %b = arith.mulf %cf, %s : f64
    %sa = math.sin %a : f64
    %cb = math.cos %b : f64
    %v = arith.mulf %sa, %cb : f64
    sim.yield %v : f64
  }

  sim.component @Diffuse writes(@T) num_steps {
  ^bb0(%i: index, %t: i64):
    %c64 = arith.constant 64 : index
    %row = arith.divui %i, %c64 : index
    %col = arith.remui %i, %c64 : index
    %r = arith.index_cast %row : index to i64
    %c = arith.index_cast %col : index to i64
    %c32 = arith.constant 32 : i64
    %dr = arith.subi %r, %c32 : i64
    %dc = arith.subi %c, %c32 : i64
    %dr2 = arith.muli %dr, %dr : i64
    %dc2 = arith.muli %dc, %dc : i64
    %d2 = arith.addi %dr2, %dc2 : i64
    %c196 = arith.constant 196 : i64
    %inside = arith.cmpi sle, %d2, %c196 : i64
    %one = arith.constant 1 : i32
    %many = arith.constant 16 : i32
    %n = arith.select %inside, %one, %many : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c64 = arith.constant 64 : index
    %c63 = arith.constant 63 : index
    %c0 = arith.constant 0 : index
    %row = arith.divui %i, %c64 : index
    %col = arith.remui %i, %c64 : index
    %iw = arith.subi %i, %c1 : index
    %ie = arith.addi %i, %c1 : index
    %in = arith.subi %i, %c64 : index
    %is = arith.addi %i, %c64 : index
    %u0 = sim.read @T[%i] : f64
    %uw0 = sim.read @T[%iw] : f64
    %ue0 = sim.read @T[%ie] : f64
    %un0 = sim.read @T[%in] : f64
    %us0 = sim.read @T[%is] : f64
    %atw = arith.cmpi eq, %col, %c0 : index
    %ate = arith.cmpi eq, %col, %c63 : index
    %atn = arith.cmpi eq, %row, %c0 : index
    %ats = arith.cmpi eq, %row, %c63 : index
    %uw = arith.select %atw, %u0, %uw0 : f64
    %ue = arith.select %ate, %u0, %ue0 : f64
    %un = arith.select %atn, %u0, %un0 : f64
    %us = arith.select %ats, %u0, %us0 : f64
    %s1 = arith.addf %uw, %ue : f64
    %s2 = arith.addf %un, %us : f64
    %s = arith.addf %s1, %s2 : f64
    %four = arith.constant 4.0 : f64
    %c4u = arith.mulf %four, %u0 : f64
    %lap = arith.subf %s, %c4u : f64
    %r = arith.index_cast %row : index to i64
    %c = arith.index_cast %col : index to i64
    %c32 = arith.constant 32 : i64
    %dr = arith.subi %r, %c32 : i64
    %dc = arith.subi %c, %c32 : i64
    %dr2 = arith.muli %dr, %dr : i64
    %dc2 = arith.muli %dc, %dc : i64
    %d2 = arith.addi %dr2, %dc2 : i64
    %c196 = arith.constant 196 : i64
    %inside = arith.cmpi sle, %d2, %c196 : i64
    %kk = sim.get_param @k : f64
    %ratio = sim.get_param @ratio : f64
    %ks = arith.mulf %kk, %ratio : f64
    %kc = arith.select %inside, %ks, %kk : f64
    %h2inv = arith.constant 4096.0 : f64
    %rate0 = arith.mulf %kc, %lap : f64
    %rate = arith.mulf %rate0, %h2inv : f64
    %nf = arith.sitofp %n : i32 to f64
    %step = arith.mulf %nf, %dt : f64
    %u1 = math.fma %step, %rate, %u0 : f64
    sim.yield %u1 : f64
  }

  sim.total @Heat : f64 {
  ^bb0(%i: index):
    %u = sim.read @T[%i] : f64
    sim.yield %u : f64
  }
  sim.observe [@T]
}
