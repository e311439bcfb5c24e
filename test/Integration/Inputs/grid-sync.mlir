// A component that reads its own buffer at i-1 (so it cannot sub-step inside
// a thread group: grid_sync, sub-steps uniform over the range, a snapshot of
// @U for its reader and a parity copy after an even number of sub-steps), and
// a later component that interpolates @U at i and i+1.
//
// @Advect: U' = U[i-1] - U[i] (upwind, boundary(wrap)); num_steps is @ns
// everywhere (3 items ask for one more), or 1 when @force is 1. @Follow: Q
// relaxes towards the mean of U[i], U[i+1] with 1 + i % 3 base steps per
// sub-step. Nothing reads through the back edge: hip takes max_steps (4).
sim.simulation @grid_sync range(100) dt(5.0e-2 : f32) max_steps(4) {
  sim.param @force = 0 : i32
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
    %force = sim.get_param @force : i32
    %ns = sim.get_param @ns : i32
    %i32 = arith.index_cast %i : index to i32
    %c32 = arith.constant 32 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c32 : i32
    %odd = arith.cmpi eq, %r, %c1 : i32
    %more = arith.addi %ns, %c1 : i32
    %n = arith.select %odd, %more, %ns : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
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
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c3 : i32
    %n = arith.addi %r, %c1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %right = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %ur = sim.read @U[%right] : f32
    %q = sim.read @Q[%i] : f32
    %s = arith.addf %u, %ur : f32
    %half = arith.constant 5.0e-1 : f32
    %mean = arith.mulf %s, %half : f32
    %d = arith.subf %mean, %q : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %q1 = math.fma %h, %d, %q : f32
    sim.yield %q1 : f32
  }

  sim.schedule [@Advect, @Follow]
  sim.observe [@U, @Q]
}
