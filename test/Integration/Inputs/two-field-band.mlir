// A gatherer before a two-field stencil: @Probe (first) gathers @A at a
// reflected index through the back edge; @Wave writes @A (cubic) and @B
// (linear) from a window i-3..i+2 of both, with a stiff band that moves
// with time; @Tail reads @A through a window and @B through a gather.
// Written the way a user would, for user-scenes-lts.test.
sim.simulation @mix range(300) dt(2.0e-4 : f64) max_steps(16) {
  sim.buffer @P : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @A : f64 interp(#sim.cubic) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 0.05 : f64
    %a = arith.mulf %f, %s : f64
    %v = math.sin %a : f64
    sim.yield %v : f64
  }
  sim.buffer @B : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @C : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Probe writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 16 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %r = arith.constant 299 : index
    %j = arith.subi %r, %i : index
    %a = sim.read @A[%j] : f64
    sim.yield %a : f64
  }
  sim.component @Wave writes(@A, @B) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %ip = arith.addi %i, %c1 : index
    %bp = sim.read @B[%ip] : f64
    %ab = math.absf %bp : f64
    %t32 = arith.trunci %t : i64 to i32
    %c300 = arith.constant 300 : i32
    %band0 = arith.remui %t32, %c300 : i32
    %i32 = arith.index_cast %i : index to i32
    %d = arith.subi %i32, %band0 : i32
    %c20 = arith.constant 20 : i32
    %in = arith.cmpi ult, %d, %c20 : i32
    %one = arith.constant 1 : i32
    %twelve = arith.constant 12 : i32
    %n0 = arith.select %in, %one, %twelve : i32
    %big = arith.constant 5.0 : f64
    %fast = arith.cmpf ogt, %ab, %big : f64
    %two = arith.constant 2 : i32
    %n = arith.select %fast, %two, %n0 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %c3 = arith.constant 3 : index
    %im3 = arith.subi %i, %c3 : index
    %im1 = arith.subi %i, %c1 : index
    %ip1 = arith.addi %i, %c1 : index
    %ip2 = arith.addi %i, %c2 : index
    %a3 = sim.read @A[%im3] : f64
    %a1 = sim.read @A[%im1] : f64
    %a0 = sim.read @A[%i] : f64
    %ap = sim.read @A[%ip1] : f64
    %b0 = sim.read @B[%i] : f64
    %bq = sim.read @B[%ip2] : f64
    %p = sim.read @P[%i] : f64
    %s = arith.addf %a1, %ap : f64
    %two = arith.constant 2.0 : f64
    %a2 = arith.mulf %two, %a0 : f64
    %lap = arith.subf %s, %a2 : f64
    %e = arith.constant 0.01 : f64
    %a3e = arith.mulf %a3, %e : f64
    %bqe = arith.mulf %bq, %e : f64
    %pe = arith.mulf %p, %e : f64
    %k = arith.constant 100.0 : f64
    %acc0 = arith.mulf %lap, %k : f64
    %acc1 = arith.addf %acc0, %a3e : f64
    %acc2 = arith.addf %acc1, %bqe : f64
    %acc = arith.subf %acc2, %pe : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %b1 = math.fma %h, %acc, %b0 : f64
    %a1n = math.fma %h, %b1, %a0 : f64
    sim.yield %a1n, %b1 : f64, f64
  }
  sim.component @Tail writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c4 = arith.constant 4 : index
    %ip = arith.addi %i, %c4 : index
    %a = sim.read @A[%ip] : f64
    %c7 = arith.constant 7 : index
    %j0 = arith.muli %i, %c7 : index
    %cr = arith.constant 300 : index
    %j = arith.remui %j0, %cr : index
    %b = sim.read @B[%j] : f64
    %s = arith.addf %a, %b : f64
    sim.yield %s : f64
  }
  sim.schedule [@Probe, @Wave, @Tail]
  sim.observe [@A, @B, @C, @P]
}
