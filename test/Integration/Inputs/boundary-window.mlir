// Window reads at i-3..i+3 over a range of 10 under each boundary rule.
//
// @Ramp writes @A (clamp), @B (wrap) and @C (zero), each (i + 1) + t * dt at
// time t (it adds n * dt per evaluation; reads only its own items). It
// sub-steps 1 + i % 3 base steps at a time unless @force is 1. @Window reads
// all three at i-3..i+3, interpolated (linear, exact for a ramp), and writes
// the sum of (k + 4) * X[i + k] into @WA, @WB, @WC; it sub-steps 1 + i % 2.
// Nothing reads through the back edge, so hip takes max_steps (4) base steps
// (the last big step capped by the end of the run).
sim.simulation @boundary_window range(10) dt(1.0e-1 : f32) max_steps(4) {
  sim.param @force = 0 : i32

  sim.buffer @A : f32 boundary(clamp) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %one = arith.constant 1.0 : f32
    %a = arith.addf %f, %one : f32
    sim.yield %a : f32
  }
  sim.buffer @B : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %one = arith.constant 1.0 : f32
    %a = arith.addf %f, %one : f32
    sim.yield %a : f32
  }
  sim.buffer @C : f32 boundary(zero) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %one = arith.constant 1.0 : f32
    %a = arith.addf %f, %one : f32
    sim.yield %a : f32
  }
  sim.buffer @WA : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @WB : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @WC : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Ramp writes(@A, @B, @C) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %r = arith.remsi %i32, %c3 : i32
    %n = arith.addi %r, %c1 : i32
    %c0 = arith.constant 0 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    %b = sim.read @B[%i] : f32
    %c = sim.read @C[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %a1 = arith.addf %a, %h : f32
    %b1 = arith.addf %b, %h : f32
    %c1 = arith.addf %c, %h : f32
    sim.yield %a1, %b1, %c1 : f32, f32, f32
  }

  sim.component @Window writes(@WA, @WB, @WC) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %r = arith.remsi %i32, %c2 : i32
    %n = arith.addi %r, %c1 : i32
    %c0 = arith.constant 0 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -3 : index
    %hi = arith.constant 4 : index
    %step = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %four = arith.constant 4.0 : f32
    %sa, %sb, %sc = scf.for %k = %lo to %hi step %step
        iter_args(%xa = %zero, %xb = %zero, %xc = %zero) -> (f32, f32, f32) {
      %j = arith.addi %i, %k : index
      %k32 = arith.index_cast %k : index to i32
      %kf = arith.sitofp %k32 : i32 to f32
      %w = arith.addf %kf, %four : f32
      %a = sim.read @A[%j] : f32
      %b = sim.read @B[%j] : f32
      %c = sim.read @C[%j] : f32
      %wa = arith.mulf %w, %a : f32
      %wb = arith.mulf %w, %b : f32
      %wc = arith.mulf %w, %c : f32
      %na = arith.addf %xa, %wa : f32
      %nb = arith.addf %xb, %wb : f32
      %nc = arith.addf %xc, %wc : f32
      scf.yield %na, %nb, %nc : f32, f32, f32
    }
    sim.yield %sa, %sb, %sc : f32, f32, f32
  }

  sim.schedule [@Ramp, @Window]
  sim.observe [@WA, @WB, @WC]
}
