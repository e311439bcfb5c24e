// An interp(none) buffer read only through the back edge (its value at T),
// which hip and hip-cache accept: only interpolate reads of it are errors.
//
// @Kick (reads @M[i-1..i+1] through the back edge, 1 + i % 2 base steps:
// bounds the hip step) relaxes @K towards the mean of M; @Mom (1 + i % 3 base
// steps, in the thread group) relaxes @M, interp(none), towards cos(K[i])
// interpolated.
sim.simulation @none_backedge range(70) dt(5.0e-2 : f32) max_steps(4) {
  sim.param @force = 0 : i32

  sim.buffer @K : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    sim.yield %a : f32
  }
  sim.buffer @M : f32 interp(none) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Kick writes(@K) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c2 : i32
    %n = arith.addi %r, %c2 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %m = sim.read @M[%i] : f32
    %ml = sim.read @M[%l] : f32
    %mr = sim.read @M[%r] : f32
    %s0 = arith.addf %ml, %m : f32
    %s = arith.addf %s0, %mr : f32
    %third = arith.constant 0.333333343 : f32
    %mean = arith.mulf %s, %third : f32
    %k = sim.read @K[%i] : f32
    %d = arith.subf %mean, %k : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k1 = math.fma %h, %d, %k : f32
    sim.yield %k1 : f32
  }

  sim.component @Mom writes(@M) num_steps {
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
    %k = sim.read @K[%i] : f32
    %m = sim.read @M[%i] : f32
    %g = math.cos %k : f32
    %d = arith.subf %g, %m : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %m1 = math.fma %h, %d, %m : f32
    sim.yield %m1 : f32
  }

  sim.schedule [@Kick, @Mom]
  sim.observe [@K, @M]
}
