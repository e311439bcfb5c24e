// One buffer, @S, read through the back edge by @First (value at T) and
// interpolated by @Last (value at its local time), and read at i-1..i+1 by
// both (boundary(zero)).
//
// @First relaxes @A towards the mean of S[i-1..i+1] (back edge), 2 + i % 2
// base steps: it bounds the hip step (2). @Mid relaxes @S towards sin(A) at its
// own item, 1 + i % 3 base steps. @Last relaxes @L towards the mean of
// S[i-1..i+1] (interpolated), 1 + (i / 4) % 3 base steps.
sim.simulation @backedge_and_interp range(50) dt(5.0e-2 : f32) max_steps(4) {
  sim.param @force = 0 : i32

  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    sim.yield %a : f32
  }
  sim.buffer @S : f32 interp(#sim.cubic) boundary(zero) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @L : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @First writes(@A) num_steps {
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
    %s = sim.read @S[%i] : f32
    %sl = sim.read @S[%l] : f32
    %sr = sim.read @S[%r] : f32
    %s0 = arith.addf %sl, %s : f32
    %s1 = arith.addf %s0, %sr : f32
    %third = arith.constant 0.333333343 : f32
    %mean = arith.mulf %s1, %third : f32
    %a = sim.read @A[%i] : f32
    %d = arith.subf %mean, %a : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %a1 = math.fma %h, %d, %a : f32
    sim.yield %a1 : f32
  }

  sim.component @Mid writes(@S) num_steps {
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
    %a = sim.read @A[%i] : f32
    %s = sim.read @S[%i] : f32
    %goal = math.sin %a : f32
    %d = arith.subf %goal, %s : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %s1 = math.fma %h, %d, %s : f32
    sim.yield %s1 : f32
  }

  sim.component @Last writes(@L) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c4 = arith.constant 4 : i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %q = arith.divsi %i32, %c4 : i32
    %r = arith.remsi %q, %c3 : i32
    %n = arith.addi %r, %c1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %s = sim.read @S[%i] : f32
    %sl = sim.read @S[%l] : f32
    %sr = sim.read @S[%r] : f32
    %s0 = arith.addf %sl, %s : f32
    %s1 = arith.addf %s0, %sr : f32
    %third = arith.constant 0.333333343 : f32
    %mean = arith.mulf %s1, %third : f32
    %x = sim.read @L[%i] : f32
    %d = arith.subf %mean, %x : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %x1 = math.fma %h, %d, %x : f32
    sim.yield %x1 : f32
  }

  sim.schedule [@First, @Mid, @Last]
  sim.observe [@A, @S, @L]
}
