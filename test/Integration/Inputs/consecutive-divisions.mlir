// Integer divisions and remainders of consecutive dividends (the item plus
// a parameter) by a divisor every item shares: the CPU kernels' lanes
// compute them from one scalar division per chunk where the divisor is at
// least the chunk's lanes and the lanes neither wrap nor (signed) go below
// zero, and divide lane by lane elsewhere (--sim-vectorize-lanes), which
// must give the reference executor's bits. Lane k of @R folds quotient and
// remainder of case k into 52 bits, exact in f64.
sim.simulation @consecutive_divisions range(4099) dt(1.0 : f64) max_steps(1) {
  sim.param @offset = 0 : i64
  sim.param @divisor = 100 : i64
  sim.param @offset32 = 0 : i32
  sim.param @divisor32 = 100 : i32

  sim.buffer @R : vector<8xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<8xf64>
    sim.yield %z : vector<8xf64>
  }
  sim.component @Divide writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %golden = arith.constant -7046029254386353131 : i64
    %mask52 = arith.constant 4503599627370495 : i64
    %offset = sim.get_param @offset : i64
    %d = sim.get_param @divisor : i64
    %item = arith.index_cast %i : index to i64
    %x = arith.addi %item, %offset : i64
    // 0, 1: signed and unsigned 64-bit, by the parameter.
    %q0 = arith.divsi %x, %d : i64
    %r0 = arith.remsi %x, %d : i64
    %q1 = arith.divui %x, %d : i64
    %r1 = arith.remui %x, %d : i64
    // 2, 3: index, the offset subtracted, signed and unsigned.
    %io = arith.index_cast %offset : i64 to index
    %id = arith.index_cast %d : i64 to index
    %xi = arith.subi %i, %io : index
    %q2i = arith.divsi %xi, %id : index
    %r2i = arith.remsi %xi, %id : index
    %q3i = arith.divui %xi, %id : index
    %r3i = arith.remui %xi, %id : index
    %q2 = arith.index_cast %q2i : index to i64
    %r2 = arith.index_cast %r2i : index to i64
    %q3 = arith.index_cast %q3i : index to i64
    %r3 = arith.index_cast %r3i : index to i64
    // 4, 5: 32 bits, signed and unsigned, by the 32-bit parameter.
    %o32 = sim.get_param @offset32 : i32
    %d32 = sim.get_param @divisor32 : i32
    %item32 = arith.index_cast %i : index to i32
    %x32 = arith.addi %item32, %o32 : i32
    %q4n = arith.divsi %x32, %d32 : i32
    %r4n = arith.remsi %x32, %d32 : i32
    %q5n = arith.divui %x32, %d32 : i32
    %r5n = arith.remui %x32, %d32 : i32
    %q4 = arith.extsi %q4n : i32 to i64
    %r4 = arith.extsi %r4n : i32 to i64
    %q5 = arith.extui %q5n : i32 to i64
    %r5 = arith.extui %r5n : i32 to i64
    // 6, 7: constants that are no power of two, signed and unsigned.
    %c37 = arith.constant 37 : i64
    %c1000 = arith.constant 1000 : i64
    %q6 = arith.divsi %x, %c37 : i64
    %r6 = arith.remsi %x, %c37 : i64
    %q7 = arith.divui %x, %c1000 : i64
    %r7 = arith.remui %x, %c1000 : i64
    %a0 = arith.muli %q0, %golden : i64
    %b0 = arith.addi %a0, %r0 : i64
    %f0i = arith.andi %b0, %mask52 : i64
    %a1 = arith.muli %q1, %golden : i64
    %b1 = arith.addi %a1, %r1 : i64
    %f1i = arith.andi %b1, %mask52 : i64
    %a2 = arith.muli %q2, %golden : i64
    %b2 = arith.addi %a2, %r2 : i64
    %f2i = arith.andi %b2, %mask52 : i64
    %a3 = arith.muli %q3, %golden : i64
    %b3 = arith.addi %a3, %r3 : i64
    %f3i = arith.andi %b3, %mask52 : i64
    %a4 = arith.muli %q4, %golden : i64
    %b4 = arith.addi %a4, %r4 : i64
    %f4i = arith.andi %b4, %mask52 : i64
    %a5 = arith.muli %q5, %golden : i64
    %b5 = arith.addi %a5, %r5 : i64
    %f5i = arith.andi %b5, %mask52 : i64
    %a6 = arith.muli %q6, %golden : i64
    %b6 = arith.addi %a6, %r6 : i64
    %f6i = arith.andi %b6, %mask52 : i64
    %a7 = arith.muli %q7, %golden : i64
    %b7 = arith.addi %a7, %r7 : i64
    %f7i = arith.andi %b7, %mask52 : i64
    %f0 = arith.uitofp %f0i : i64 to f64
    %f1 = arith.uitofp %f1i : i64 to f64
    %f2 = arith.uitofp %f2i : i64 to f64
    %f3 = arith.uitofp %f3i : i64 to f64
    %f4 = arith.uitofp %f4i : i64 to f64
    %f5 = arith.uitofp %f5i : i64 to f64
    %f6 = arith.uitofp %f6i : i64 to f64
    %f7 = arith.uitofp %f7i : i64 to f64
    %r = vector.from_elements %f0, %f1, %f2, %f3, %f4, %f5, %f6, %f7 : vector<8xf64>
    sim.yield %r : vector<8xf64>
  }
  sim.observe [@R]
}
