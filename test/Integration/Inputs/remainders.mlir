// 64-bit unsigned remainders by constants, one item's worth per lane: the
// CPU kernels compute a remainder of a vector of i64 lanes by a constant
// below 2^16 from 32-bit remainders (--sim-vectorize-lanes), which must give
// the reference executor's bits. Lanes 0-3: a 64-bit hash of the item
// (splitmix64's finaliser: every bit pattern is as likely); lanes 4-7: the
// top of the range, 2^64 - 1 - i * (2^32 + 1), which has both 32-bit halves
// near their maximum. The remainders are below 2^16, exact in f32.
sim.simulation @remainders range(65536) dt(1.0 : f32) max_steps(1) {
  sim.buffer @R : vector<8xf32> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<8xf32>
    sim.yield %z : vector<8xf32>
  }
  sim.component @Remainders writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %item = arith.index_castui %i : index to i64
    %golden = arith.constant -7046029254386353131 : i64
    %m1 = arith.constant -4658895280553007687 : i64
    %m2 = arith.constant -7723592293110705685 : i64
    %c30 = arith.constant 30 : i64
    %c27 = arith.constant 27 : i64
    %c31 = arith.constant 31 : i64
    %x0 = arith.muli %item, %golden : i64
    %s0 = arith.shrui %x0, %c30 : i64
    %x1 = arith.xori %x0, %s0 : i64
    %x2 = arith.muli %x1, %m1 : i64
    %s2 = arith.shrui %x2, %c27 : i64
    %x3 = arith.xori %x2, %s2 : i64
    %x4 = arith.muli %x3, %m2 : i64
    %s4 = arith.shrui %x4, %c31 : i64
    %hash = arith.xori %x4, %s4 : i64
    %all_ones = arith.constant -1 : i64
    %both_halves = arith.constant 4294967297 : i64
    %step = arith.muli %item, %both_halves : i64
    %top = arith.subi %all_ones, %step : i64
    %c3 = arith.constant 3 : i64
    %c7 = arith.constant 7 : i64
    %c1000 = arith.constant 1000 : i64
    %c65535 = arith.constant 65535 : i64
    %h3 = arith.remui %hash, %c3 : i64
    %h7 = arith.remui %hash, %c7 : i64
    %h1000 = arith.remui %hash, %c1000 : i64
    %h65535 = arith.remui %hash, %c65535 : i64
    %t3 = arith.remui %top, %c3 : i64
    %t7 = arith.remui %top, %c7 : i64
    %t1000 = arith.remui %top, %c1000 : i64
    %t65535 = arith.remui %top, %c65535 : i64
    %f0 = arith.uitofp %h3 : i64 to f32
    %f1 = arith.uitofp %h7 : i64 to f32
    %f2 = arith.uitofp %h1000 : i64 to f32
    %f3 = arith.uitofp %h65535 : i64 to f32
    %f4 = arith.uitofp %t3 : i64 to f32
    %f5 = arith.uitofp %t7 : i64 to f32
    %f6 = arith.uitofp %t1000 : i64 to f32
    %f7 = arith.uitofp %t65535 : i64 to f32
    %r = vector.from_elements %f0, %f1, %f2, %f3, %f4, %f5, %f6, %f7 : vector<8xf32>
    sim.yield %r : vector<8xf32>
  }
  sim.schedule [@Remainders]
  sim.observe [@R]
}
