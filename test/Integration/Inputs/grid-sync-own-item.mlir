// grid-sync.mlir's @Advect (its own buffer read at i-1, so grid_sync with a
// snapshot of @U for its reader) and a later component that interpolates
// @U at its own item only: in a distributed run the snapshot stays on its
// rank (no snapshot_ghosts), while the sub-steps' halves still travel.
sim.simulation @grid_sync_own_item range(100) dt(5.0e-2 : f32) max_steps(4) {
  sim.param @ns = 2 : i32

  sim.buffer @U : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 2.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @Q : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Advect writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %ns = sim.get_param @ns : i32
    sim.yield %ns : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %left = arith.subi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %ul = sim.read @U[%left] : f32
    %d = arith.subf %ul, %u : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %d, %u : f32
    sim.yield %u1 : f32
  }

  sim.component @Follow writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %r = arith.remsi %i32, %c3 : i32
    %n = arith.addi %r, %c1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %q = sim.read @Q[%i] : f32
    %d = arith.subf %u, %q : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %q1 = math.fma %h, %d, %q : f32
    sim.yield %q1 : f32
  }

  sim.schedule [@Advect, @Follow]
  sim.observe [@U, @Q]
}
