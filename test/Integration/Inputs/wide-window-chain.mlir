// A chain whose last component reads the first one's buffer through a wide
// window (i-8..i+8): under hip-cache a shared-memory cache with an 8-item
// halo on each side. The range (100) is no multiple of any group size.
//
// @Src (bounds the hip step: it reads @C through the back edge) relaxes @A
// towards cos(i / 7) - C / 4 in 2 + (i / 5) % 2 base steps (so hip
// takes 2); @Mid writes the
// mean of A[i-1..i+1] into @B; @Wide relaxes @C towards a weighted mean of
// A[i-8..i+8] and B[i-8..i+8] (boundary clamp), 1 + i % 2 base steps at a
// time. @force = 1 makes every num_steps 1.
sim.simulation @wide_window_chain range(100) dt(5.0e-2 : f32) max_steps(3) {
  sim.param @force = 0 : i32

  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 3.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Src writes(@A) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c5 = arith.constant 5 : i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %c2 = arith.constant 2 : i32
    %q = arith.divsi %i32, %c5 : i32
    %r = arith.remsi %q, %c2 : i32
    %n = arith.addi %r, %c2 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    %c = sim.read @C[%i] : f32
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %seventh = arith.constant 0.142857149 : f32
    %x = arith.mulf %f, %seventh : f32
    %cx = math.cos %x : f32
    %quarter = arith.constant 2.5e-1 : f32
    %cq = arith.mulf %c, %quarter : f32
    %goal = arith.subf %cx, %cq : f32
    %d = arith.subf %goal, %a : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %a1 = math.fma %h, %d, %a : f32
    sim.yield %a1 : f32
  }

  sim.component @Mid writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %a = sim.read @A[%i] : f32
    %al = sim.read @A[%l] : f32
    %ar = sim.read @A[%r] : f32
    %s0 = arith.addf %al, %a : f32
    %s = arith.addf %s0, %ar : f32
    %third = arith.constant 0.333333343 : f32
    %b = arith.mulf %s, %third : f32
    sim.yield %b : f32
  }

  sim.component @Wide writes(@C) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c2 : i32
    %n = arith.addi %r, %c1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -8 : index
    %hi = arith.constant 9 : index
    %step = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %nine = arith.constant 9.0 : f32
    %sum = scf.for %k = %lo to %hi step %step iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      %k32 = arith.index_cast %k : index to i32
      %kf = arith.sitofp %k32 : i32 to f32
      %ak = math.absf %kf : f32
      %w = arith.subf %nine, %ak : f32
      %a = sim.read @A[%j] : f32
      %b = sim.read @B[%j] : f32
      %ab = arith.addf %a, %b : f32
      %wab = arith.mulf %w, %ab : f32
      %next = arith.addf %acc, %wab : f32
      scf.yield %next : f32
    }
    %norm = arith.constant 6.17283933E-3 : f32
    %mean = arith.mulf %sum, %norm : f32
    %c = sim.read @C[%i] : f32
    %d = arith.subf %mean, %c : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %c1 = math.fma %h, %d, %c : f32
    sim.yield %c1 : f32
  }

  sim.schedule [@Src, @Mid, @Wide]
  sim.observe [@C]
}
