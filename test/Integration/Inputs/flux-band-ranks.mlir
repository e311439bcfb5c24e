// A flux pair whose reader reads the interface after its item (@F[i+1]),
// with a band of stiff interfaces that moves with the time, for
// distributed-lts.test: where the band reaches the first interface of a
// rank, the block before it, on the rank below, must take the band's
// sub-step, although no item of that rank computes the interface's
// estimate. The fluxes have boundary(zero): nothing crosses the ends.
sim.simulation @flux_band_ranks range(200) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    // Interfaces t mod 200 .. t mod 200 + 4 ask for 2 base steps.
    %j32 = arith.index_cast %j : index to i32
    %t32 = arith.trunci %t : i64 to i32
    %c200 = arith.constant 200 : i32
    %start = arith.remui %t32, %c200 : i32
    %d = arith.subi %j32, %start : i32
    %c5 = arith.constant 5 : i32
    %in = arith.cmpi ult, %d, %c5 : i32
    %two = arith.constant 2 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %in, %two, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %u0 = sim.read @U[%j] : f32
    %u1 = sim.read @U[%jr] : f32
    %d = arith.subf %u1, %u0 : f32
    %k = arith.constant 5.0e-2 : f32
    %f = arith.mulf %d, %k : f32
    sim.yield %f : f32
  }
  sim.component @Cells writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %fl = sim.read @F[%il] : f32
    %f0 = sim.read @F[%i] : f32
    %fr = sim.read @F[%ir] : f32
    %u = sim.read @U[%i] : f32
    // The difference of the fluxes at both sides, and a correction from
    // the next interface.
    %div = arith.subf %f0, %fl : f32
    %corr = arith.subf %fr, %f0 : f32
    %q = arith.constant 2.5e-1 : f32
    %cq = arith.mulf %corr, %q : f32
    %s = arith.subf %div, %cq : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 4.0 : f32
    %hk = arith.mulf %h, %k : f32
    %u1 = math.fma %hk, %s, %u : f32
    sim.yield %u1 : f32
  }
  sim.schedule [@Flux, @Cells]
  sim.observe [@U]
}
