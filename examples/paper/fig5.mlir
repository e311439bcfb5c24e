// The component graph of the paper's Fig. 5 ("Adaptive Time Steps for
// Compute-Intensive Simulations on GPUs", Section 3): five components C0..C4
// and the buffers B0..B3 they communicate through.
//
//   C0 writes B0, reads B0 (own item) and B3 (the back edge: value at T)
//   C1 writes B1, reads B0
//   C2 writes B2, reads B1 (items i-1..i+1)
//   C3 writes B3, reads B2
//   C4 writes B4, reads B3
//
// The figure leaves C4's output implicit. Here every buffer has exactly one
// writer and every component writes at least one buffer, so C4 writes an
// extra buffer B4: the scene's output, and the only observed buffer.
//
// With C0 as the entry (sim.schedule [@C0]), C0's read of B3 is the back edge
// and the remaining reads form a chain, so the only possible order is
// C0, C1, C2, C3, C4 (the order the paper derives by topological sorting).
// The hip big step is bounded by C0 alone: it is the only component that
// reads through the back edge.
//
// Elements are f32 scalars; the bodies are deliberately simple arithmetic.
// Each num_steps is a constant in [1..3].

sim.simulation @fig5 range(1024) dt(1.0e-3 : f32) max_steps(3) {
  // Initial state: B0 = i / range, everything else 0.
  sim.buffer @B0 : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_castui %i : index to i64
    %x = arith.uitofp %i64 : i64 to f32
    %scale = arith.constant 9.765625e-04 : f32 // 1 / 1024
    %v = arith.mulf %x, %scale : f32
    sim.yield %v : f32
  }
  sim.buffer @B1 : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @B2 : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @B3 : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @B4 : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }

  // C0: relaxes its own state towards B3 at T (the back edge), with the
  // step h = n * dt: B0 <- B0 + h * (B3 - B0).
  sim.component @C0 writes(@B0) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %self = sim.read @B0[%i] : f32
    %back = sim.read @B3[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %diff = arith.subf %back, %self : f32
    %new = math.fma %h, %diff, %self : f32
    sim.yield %new : f32
  }

  // C1: B1 <- 0.5 * B0 + 0.25.
  sim.component @C1 writes(@B1) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 3 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %b0 = sim.read @B0[%i] : f32
    %half = arith.constant 0.5 : f32
    %quarter = arith.constant 0.25 : f32
    %new = math.fma %b0, %half, %quarter : f32
    sim.yield %new : f32
  }

  // C2: B2 <- mean of B1 over the items i-1, i, i+1 (a small window; reads
  // outside the range are clamped, the default boundary rule).
  sim.component @C2 writes(@B2) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c-1 = arith.constant -1 : index
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %zero = arith.constant 0.0 : f32
    %third = arith.constant 0.333333343 : f32
    %sum = scf.for %k = %c-1 to %c2 step %c1 iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      %b1 = sim.read @B1[%j] : f32
      %acc1 = arith.addf %acc, %b1 : f32
      scf.yield %acc1 : f32
    }
    %new = arith.mulf %sum, %third : f32
    sim.yield %new : f32
  }

  // C3: B3 <- B2 * B2 - 0.5 * n * dt.
  sim.component @C3 writes(@B3) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 3 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %b2 = sim.read @B2[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %half = arith.constant 0.5 : f32
    %sq = arith.mulf %b2, %b2 : f32
    %dh = arith.mulf %half, %h : f32
    %new = arith.subf %sq, %dh : f32
    sim.yield %new : f32
  }

  // C4: the output, B4 <- 1 - B3.
  sim.component @C4 writes(@B4) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %b3 = sim.read @B3[%i] : f32
    %one = arith.constant 1.0 : f32
    %new = arith.subf %one, %b3 : f32
    sim.yield %new : f32
  }

  sim.schedule [@C0]
  sim.observe [@B4]
}
