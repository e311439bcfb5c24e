// constant-boundaries: three constant fields under clamp, wrap and zero,
// read at i-3..i+3 over a range of 37 (no multiple of a block) by a
// component whose num_steps reads one of them beyond the range. The same
// scene with the three fields written by components that keep them
// (constant-boundaries-written.mlir) reads them through the buffers'
// boundary rules; both must give the same bits under every strategy.
sim.simulation @constant_boundaries range(37) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @A : f64 constant init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 1.5 : f64
    %v = arith.mulf %f, %c : f64
    %s = math.sin %v : f64
    sim.yield %s : f64
  }
  sim.buffer @B : f64 constant boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 2.5 : f64
    %v = arith.mulf %f, %c : f64
    %s = math.sin %v : f64
    sim.yield %s : f64
  }
  sim.buffer @C : f64 constant boundary(zero) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 3.5 : f64
    %v = arith.mulf %f, %c : f64
    %s = math.sin %v : f64
    sim.yield %s : f64
  }
  sim.buffer @W : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Sum writes(@W) num_steps {
  ^bb0(%i: index, %t: i64):
    %c3 = arith.constant 3 : index
    %j = arith.addi %i, %c3 : index
    %c = sim.read @C[%j] : f64
    %z = arith.constant 0.0 : f64
    %out = arith.cmpf oeq, %c, %z : f64
    %one = arith.constant 1 : i32
    %three = arith.constant 3 : i32
    %n = arith.select %out, %one, %three : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %w0 = sim.read @W[%i] : f64
    %o1 = arith.constant 3 : index
    %j1 = arith.subi %i, %o1 : index
    %r1 = sim.read @A[%j1] : f64
    %a1 = arith.addf %w0, %r1 : f64
    %o2 = arith.constant 3 : index
    %j2 = arith.subi %i, %o2 : index
    %r2 = sim.read @B[%j2] : f64
    %a2 = arith.addf %a1, %r2 : f64
    %o3 = arith.constant 3 : index
    %j3 = arith.subi %i, %o3 : index
    %r3 = sim.read @C[%j3] : f64
    %a3 = arith.addf %a2, %r3 : f64
    %o4 = arith.constant 2 : index
    %j4 = arith.subi %i, %o4 : index
    %r4 = sim.read @A[%j4] : f64
    %a4 = arith.addf %a3, %r4 : f64
    %o5 = arith.constant 2 : index
    %j5 = arith.subi %i, %o5 : index
    %r5 = sim.read @B[%j5] : f64
    %a5 = arith.addf %a4, %r5 : f64
    %o6 = arith.constant 2 : index
    %j6 = arith.subi %i, %o6 : index
    %r6 = sim.read @C[%j6] : f64
    %a6 = arith.addf %a5, %r6 : f64
    %o7 = arith.constant 1 : index
    %j7 = arith.subi %i, %o7 : index
    %r7 = sim.read @A[%j7] : f64
    %a7 = arith.addf %a6, %r7 : f64
    %o8 = arith.constant 1 : index
    %j8 = arith.subi %i, %o8 : index
    %r8 = sim.read @B[%j8] : f64
    %a8 = arith.addf %a7, %r8 : f64
    %o9 = arith.constant 1 : index
    %j9 = arith.subi %i, %o9 : index
    %r9 = sim.read @C[%j9] : f64
    %a9 = arith.addf %a8, %r9 : f64
    %o10 = arith.constant 0 : index
    %j10 = arith.addi %i, %o10 : index
    %r10 = sim.read @A[%j10] : f64
    %a10 = arith.addf %a9, %r10 : f64
    %o11 = arith.constant 0 : index
    %j11 = arith.addi %i, %o11 : index
    %r11 = sim.read @B[%j11] : f64
    %a11 = arith.addf %a10, %r11 : f64
    %o12 = arith.constant 0 : index
    %j12 = arith.addi %i, %o12 : index
    %r12 = sim.read @C[%j12] : f64
    %a12 = arith.addf %a11, %r12 : f64
    %o13 = arith.constant 1 : index
    %j13 = arith.addi %i, %o13 : index
    %r13 = sim.read @A[%j13] : f64
    %a13 = arith.addf %a12, %r13 : f64
    %o14 = arith.constant 1 : index
    %j14 = arith.addi %i, %o14 : index
    %r14 = sim.read @B[%j14] : f64
    %a14 = arith.addf %a13, %r14 : f64
    %o15 = arith.constant 1 : index
    %j15 = arith.addi %i, %o15 : index
    %r15 = sim.read @C[%j15] : f64
    %a15 = arith.addf %a14, %r15 : f64
    %o16 = arith.constant 2 : index
    %j16 = arith.addi %i, %o16 : index
    %r16 = sim.read @A[%j16] : f64
    %a16 = arith.addf %a15, %r16 : f64
    %o17 = arith.constant 2 : index
    %j17 = arith.addi %i, %o17 : index
    %r17 = sim.read @B[%j17] : f64
    %a17 = arith.addf %a16, %r17 : f64
    %o18 = arith.constant 2 : index
    %j18 = arith.addi %i, %o18 : index
    %r18 = sim.read @C[%j18] : f64
    %a18 = arith.addf %a17, %r18 : f64
    %o19 = arith.constant 3 : index
    %j19 = arith.addi %i, %o19 : index
    %r19 = sim.read @A[%j19] : f64
    %a19 = arith.addf %a18, %r19 : f64
    %o20 = arith.constant 3 : index
    %j20 = arith.addi %i, %o20 : index
    %r20 = sim.read @B[%j20] : f64
    %a20 = arith.addf %a19, %r20 : f64
    %o21 = arith.constant 3 : index
    %j21 = arith.addi %i, %o21 : index
    %r21 = sim.read @C[%j21] : f64
    %a21 = arith.addf %a20, %r21 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %scaled = arith.mulf %a21, %h : f64
    %out = arith.addf %w0, %scaled : f64
    sim.yield %out : f64
  }
  sim.observe [@W]
}
