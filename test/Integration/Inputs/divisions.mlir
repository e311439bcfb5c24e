// Integer divisions and remainders by divisors that are not constants: the
// CPU kernels' lanes compute them in f64 where that is exact (32-bit
// operands; 64-bit and index ones within 2^53 of zero, checked per chunk of
// lanes) and with integer division otherwise (--sim-vectorize-lanes), which
// must give the reference executor's bits. The dividend's kind changes
// every 64 items (whole chunks of lanes): a 64-bit hash (out of range), the
// largest in-range values and their negatives, and values just past 2^53.
// Lane k of @R folds quotient and remainder of case k into 52 bits, exact
// in f64. @W reads its neighbours through a wrap (an index remainder).
sim.simulation @divisions range(4099) dt(1.0 : f64) max_steps(1) {
  sim.param @divisor = -7 : i64
  sim.param @divisor32 = 1000003 : i32

  sim.buffer @R : vector<5xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<5xf64>
    sim.yield %z : vector<5xf64>
  }
  sim.buffer @W : f64 boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    sim.yield %f : f64
  }
  sim.component @Divide writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %item = arith.index_castui %i : index to i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %c3 = arith.constant 3 : i64
    %c6 = arith.constant 6 : i64
    %c7 = arith.constant 7 : i64
    %c13 = arith.constant 13 : i64
    %c64 = arith.constant 64 : i64
    %c1000 = arith.constant 1000 : i64
    %c40 = arith.constant 40 : i64
    %mask52 = arith.constant 4503599627370495 : i64
    %golden = arith.constant -7046029254386353131 : i64
    %limit = arith.constant 9007199254740991 : i64
    %two53 = arith.constant 9007199254740992 : i64
    // The dividend: its kind changes every 64 items.
    %run = arith.divui %item, %c64 : i64
    %kind = arith.remui %run, %c3 : i64
    %x0 = arith.muli %item, %golden : i64
    %c29 = arith.constant 29 : i64
    %s0 = arith.shrui %x0, %c29 : i64
    %hash = arith.xori %x0, %s0 : i64
    %top = arith.subi %limit, %item : i64
    %bottom = arith.subi %c0, %top : i64
    %past = arith.addi %two53, %item : i64
    %odd = arith.andi %run, %c1 : i64
    %is_odd = arith.cmpi ne, %odd, %c0 : i64
    %in_range = arith.select %is_odd, %bottom, %top : i64
    %is0 = arith.cmpi eq, %kind, %c0 : i64
    %is1 = arith.cmpi eq, %kind, %c1 : i64
    %x1 = arith.select %is1, %in_range, %past : i64
    %x = arith.select %is0, %hash, %x1 : i64
    // Divisors: a parameter, one per item (never 0), large ones.
    %p = sim.get_param @divisor : i64
    %m13 = arith.remui %item, %c13 : i64
    %v0 = arith.subi %m13, %c6 : i64
    %is_zero = arith.cmpi eq, %v0, %c0 : i64
    %v = arith.select %is_zero, %c7, %v0 : i64
    %m1000 = arith.remui %item, %c1000 : i64
    %m1 = arith.addi %m1000, %c1 : i64
    %big = arith.shli %m1, %c40 : i64
    // Case 0: signed by the parameter; 1: signed by the item's; 2: unsigned
    // by a large one.
    %q0 = arith.divsi %x, %p : i64
    %r0 = arith.remsi %x, %p : i64
    %q1 = arith.divsi %x, %v : i64
    %r1 = arith.remsi %x, %v : i64
    %q2 = arith.divui %x, %big : i64
    %r2 = arith.remui %x, %big : i64
    // Cases 3 and 4: 32 bits, signed by the item's, unsigned by the
    // parameter.
    %x32 = arith.trunci %hash : i64 to i32
    %v32 = arith.trunci %v : i64 to i32
    %p32 = sim.get_param @divisor32 : i32
    %q3 = arith.divsi %x32, %v32 : i32
    %r3 = arith.remsi %x32, %v32 : i32
    %q4 = arith.divui %x32, %p32 : i32
    %r4 = arith.remui %x32, %p32 : i32
    %q3w = arith.extsi %q3 : i32 to i64
    %r3w = arith.extsi %r3 : i32 to i64
    %q4w = arith.extui %q4 : i32 to i64
    %r4w = arith.extui %r4 : i32 to i64
    // Fold quotient and remainder into 52 bits.
    %a0 = arith.muli %q0, %golden : i64
    %b0 = arith.addi %a0, %r0 : i64
    %f0i = arith.andi %b0, %mask52 : i64
    %a1 = arith.muli %q1, %golden : i64
    %b1 = arith.addi %a1, %r1 : i64
    %f1i = arith.andi %b1, %mask52 : i64
    %a2 = arith.muli %q2, %golden : i64
    %b2 = arith.addi %a2, %r2 : i64
    %f2i = arith.andi %b2, %mask52 : i64
    %a3 = arith.muli %q3w, %golden : i64
    %b3 = arith.addi %a3, %r3w : i64
    %f3i = arith.andi %b3, %mask52 : i64
    %a4 = arith.muli %q4w, %golden : i64
    %b4 = arith.addi %a4, %r4w : i64
    %f4i = arith.andi %b4, %mask52 : i64
    %f0 = arith.uitofp %f0i : i64 to f64
    %f1 = arith.uitofp %f1i : i64 to f64
    %f2 = arith.uitofp %f2i : i64 to f64
    %f3 = arith.uitofp %f3i : i64 to f64
    %f4 = arith.uitofp %f4i : i64 to f64
    %r = vector.from_elements %f0, %f1, %f2, %f3, %f4 : vector<5xf64>
    sim.yield %r : vector<5xf64>
  }
  sim.component @Neighbours writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c3 = arith.constant 3 : index
    %c5 = arith.constant 5 : index
    %below = arith.subi %i, %c3 : index
    %above = arith.addi %i, %c5 : index
    %l = sim.read @W[%below] : f64
    %u = sim.read @W[%above] : f64
    %scale = arith.constant 4099.0 : f64
    %ls = arith.mulf %l, %scale : f64
    %s = arith.addf %ls, %u : f64
    sim.yield %s : f64
  }
  sim.schedule [@Divide, @Neighbours]
  sim.observe [@R, @W]
}
