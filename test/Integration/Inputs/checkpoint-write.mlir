// Six f64 buffers of 16384 items, of which only @X is observed: a
// checkpoint holds all six (768 KiB), --output's .npz @X at each output time
// (three in checkpoint-write-fails.test: 384 KiB), a dump file @X (128 KiB),
// so that a limit on the size of the files sim-run writes (RLIMIT_FSIZE)
// between them fails the checkpoint alone. @A to @E halve every base step;
// @X adds them up.
sim.simulation @ballast range(16384) dt(1.0e-2 : f64) max_steps(1) {
  sim.buffer @A : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 1.0 : f64
    sim.yield %v : f64
  }
  sim.buffer @B : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 2.0 : f64
    sim.yield %v : f64
  }
  sim.buffer @C : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 3.0 : f64
    sim.yield %v : f64
  }
  sim.buffer @D : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 4.0 : f64
    sim.yield %v : f64
  }
  sim.buffer @E : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 5.0 : f64
    sim.yield %v : f64
  }
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %v = arith.constant 0.0 : f64
    sim.yield %v : f64
  }

  sim.component @Decay writes(@A, @B, @C, @D, @E, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f64
    %b = sim.read @B[%i] : f64
    %c = sim.read @C[%i] : f64
    %d = sim.read @D[%i] : f64
    %e = sim.read @E[%i] : f64
    %x = sim.read @X[%i] : f64
    %k = arith.constant 0.5 : f64
    %a1 = arith.mulf %a, %k : f64
    %b1 = arith.mulf %b, %k : f64
    %c1 = arith.mulf %c, %k : f64
    %d1 = arith.mulf %d, %k : f64
    %e1 = arith.mulf %e, %k : f64
    %ab = arith.addf %a1, %b1 : f64
    %cd = arith.addf %c1, %d1 : f64
    %abcd = arith.addf %ab, %cd : f64
    %all = arith.addf %abcd, %e1 : f64
    %x1 = arith.addf %x, %all : f64
    sim.yield %a1, %b1, %c1, %d1, %e1, %x1 : f64, f64, f64, f64, f64, f64
  }

  sim.total @Sum : f64 {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }

  sim.observe [@X]
}
