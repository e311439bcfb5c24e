// A stencil whose num_steps reads its own buffer through a gather: item
// i's step is 1 where @U[(5 i) mod range] > 0.99, else 8. num_steps runs
// at T under lts, so the gather does not keep the blocks from local time
// steps (it made the component grid_sync under lts too). For
// lts-estimate-gather.test.
sim.simulation @estimate_gather range(200) dt(5.0e-2 : f64) max_steps(8) {
  sim.buffer @U : f64 boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 9.0e-2 : f64
    %y = arith.mulf %x, %s : f64
    %c = math.sin %y : f64
    sim.yield %c : f64
  }
  sim.component @E writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c5 = arith.constant 5 : index
    %rg = sim.get_param @range : i64
    %rgi = arith.index_cast %rg : i64 to index
    %j0 = arith.muli %i, %c5 : index
    %j = arith.remui %j0, %rgi : index
    %u = sim.read @U[%j] : f64
    %th = arith.constant 0.99 : f64
    %big = arith.cmpf ogt, %u, %th : f64
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %big, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ul = sim.read @U[%il] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %k = arith.constant 0.5 : f64
    %d = arith.subf %ul, %u : f64
    %u1 = math.fma %h, %d, %u : f64
    sim.yield %u1 : f64
  }
  sim.observe [@U]
}
