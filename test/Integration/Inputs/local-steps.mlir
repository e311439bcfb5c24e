// Local time steps (strategy lts, docs/Model.md): components that read their
// own buffers at other items, under every boundary rule, with windows inside
// a group and wider than one (group size 32 in the cross-check), next to a
// component whose own gather keeps it on grid-wide sub-steps.
//
// num_steps by @pattern: 0, blocks of 24 items ask 8, 4, 2, 1 in turn (level
// boundaries inside and between groups); 1, every item 1 (all fine: lts is
// simple); 2, every item 8 (all coarse: lts is hip); 3, one stiff item (77)
// in a soft range (the ratio limit spreads from it).
sim.simulation @local_steps range(200) dt(5.0e-2 : f32) max_steps(8) {
  sim.param @pattern = 0 : i32

  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.5e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @B : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 7.0e-2 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.cos %a : f32
    sim.yield %u : f32
  }
  sim.buffer @C : f32 interp(#sim.cubic) boundary(zero) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %c5 = arith.constant 5 : i32
    %r = arith.remsi %i32, %c5 : i32
    %f = arith.sitofp %r : i32 to f32
    sim.yield %f : f32
  }
  sim.buffer @D : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @E : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-2 : f32
    %a = arith.mulf %f, %s : f32
    sim.yield %a : f32
  }

  // Diffusion-like smoothing of A over i-2 .. i+1 (clamp).
  sim.component @Clamp writes(@A) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %i32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %x1 = arith.select %p3, %s3, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %l = arith.subi %i, %c2 : index
    %r = arith.addi %i, %c1 : index
    %a = sim.read @A[%i] : f32
    %al = sim.read @A[%l] : f32
    %ar = sim.read @A[%r] : f32
    %s = arith.addf %al, %ar : f32
    %two = arith.constant 2.0 : f32
    %a2 = arith.mulf %two, %a : f32
    %d = arith.subf %s, %a2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 2.0e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %a1 = math.fma %hk, %d, %a : f32
    sim.yield %a1 : f32
  }

  // Upwind transport of B (wrap), forced by A interpolated.
  sim.component @Wrap writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %i32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %x1 = arith.select %p3, %s3, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c3 = arith.constant 3 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c3 : index
    %b = sim.read @B[%i] : f32
    %bl = sim.read @B[%l] : f32
    %br = sim.read @B[%r] : f32
    %a = sim.read @A[%i] : f32
    %d0 = arith.subf %bl, %b : f32
    %d1 = arith.subf %br, %b : f32
    %q = arith.constant 2.5e-1 : f32
    %d2 = math.fma %q, %d1, %d0 : f32
    %d = arith.addf %d2, %a : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 3.0e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %b1 = math.fma %hk, %d, %b : f32
    sim.yield %b1 : f32
  }

  // C (zero boundary, cubic) relaxes towards its neighbours and a gather
  // of A (another component's buffer: local steps are unaffected).
  sim.component @Zero writes(@C) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %i32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %x1 = arith.select %p3, %s3, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c7 = arith.constant 7 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %range64 = sim.get_param @range : i64
    %range = arith.index_cast %range64 : i64 to index
    %j0 = arith.muli %i, %c7 : index
    %j = arith.remui %j0, %range : index
    %c = sim.read @C[%i] : f32
    %cl = sim.read @C[%l] : f32
    %cr = sim.read @C[%r] : f32
    %aj = sim.read @A[%j] : f32
    %s = arith.addf %cl, %cr : f32
    %s2 = arith.addf %s, %aj : f32
    %third = arith.constant 3.3333334e-1 : f32
    %mean = arith.mulf %s2, %third : f32
    %d = arith.subf %mean, %c : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %c1n = math.fma %h, %d, %c : f32
    sim.yield %c1n : f32
  }

  // D reads its own buffer through a gather: grid-wide sub-steps under lts
  // too, with a remark that says why.
  sim.component @Gathered writes(@D) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %i32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %x1 = arith.select %p3, %s3, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c5 = arith.constant 5 : index
    %range64 = sim.get_param @range : i64
    %range = arith.index_cast %range64 : i64 to index
    %j0 = arith.muli %i, %c5 : index
    %j = arith.remui %j0, %range : index
    %d = sim.read @D[%i] : f32
    %dj = sim.read @D[%j] : f32
    %c = sim.read @C[%i] : f32
    %x = arith.subf %dj, %d : f32
    %y = arith.addf %x, %c : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 1.0e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %d1 = math.fma %hk, %y, %d : f32
    sim.yield %d1 : f32
  }

  // E (wrap) reads 40 items away on both sides: wider than a group of 32.
  sim.component @Wide writes(@E) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %i32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %x1 = arith.select %p3, %s3, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c40 = arith.constant 40 : index
    %l = arith.subi %i, %c40 : index
    %r = arith.addi %i, %c40 : index
    %e = sim.read @E[%i] : f32
    %el = sim.read @E[%l] : f32
    %er = sim.read @E[%r] : f32
    %s = arith.addf %el, %er : f32
    %two = arith.constant 2.0 : f32
    %e2 = arith.mulf %two, %e : f32
    %d = arith.subf %s, %e2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 1.5e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %e1 = math.fma %hk, %d, %e : f32
    sim.yield %e1 : f32
  }

  sim.schedule [@Clamp, @Wrap, @Zero, @Gathered, @Wide]
  sim.observe [@A, @B, @C, @D, @E]
}
