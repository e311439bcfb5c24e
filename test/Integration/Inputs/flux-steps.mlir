// A flux pair under lts (docs/Model.md, "Conservation"): @Flux writes two
// #sim.flux buffers (boundary zero) from @Cells' state (window i-1..i+2, so
// an interface reads blocks beyond its two readers, some of them coarser
// and in the middle of their sub-step); @Cells reads @F at i-1..i and @G
// at i-2..i+1 (interface readers in up to two blocks) and updates two
// buffers; @Observe reads @U after the pair (interpolated, from its
// snapshot).
//
// num_steps by @pattern, for both components of the pair: 0, blocks of 24
// items (@Cells) and of 20 interfaces (@Flux, shifted) ask 8, 4, 2, 1 in
// turn; 1, every item 1 (all fine: the pair is simple's); 2, every item 8
// (all coarse: lts is hip); 3, one stiff interface (77) in a soft range;
// 4, stiff interfaces only at the ends of ranges 101 and 200 (0-1, 99-100,
// 198-199) in a soft range, where an interface's readers follow the
// fluxes' boundary rule (the cells stay soft); 5, stiff interfaces 0-1
// only (under wrap their readers -2..-1 are the last items).
sim.simulation @flux_steps range(200) dt(5.0e-2 : f32) max_steps(8) {
  sim.param @pattern = 0 : i32

  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.5e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @V : f32 interp(#sim.cubic) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %c5 = arith.constant 5 : i32
    %r = arith.remsi %i32, %c5 : i32
    %f = arith.sitofp %r : i32 to f32
    sim.yield %f : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @G : f32 interp(#sim.flux) boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.schedule [@Flux]

  sim.component @Flux writes(@F, @G) num_steps {
  ^bb0(%j: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %j32 = arith.index_cast %j : index to i32
    %c10 = arith.constant 10 : i32
    %c20 = arith.constant 20 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %shifted = arith.addi %j32, %c10 : i32
    %blk = arith.divsi %shifted, %c20 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %stiff = arith.cmpi eq, %j32, %c77 : i32
    %s3 = arith.select %stiff, %one, %eight : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %c99 = arith.constant 99 : i32
    %c101 = arith.constant 101 : i32
    %c198 = arith.constant 198 : i32
    %first = arith.cmpi slt, %j32, %c2 : i32
    %from99 = arith.cmpi sge, %j32, %c99 : i32
    %below101 = arith.cmpi slt, %j32, %c101 : i32
    %middle = arith.andi %from99, %below101 : i1
    %last = arith.cmpi sge, %j32, %c198 : i32
    %ends0 = arith.ori %first, %middle : i1
    %ends = arith.ori %ends0, %last : i1
    %s4 = arith.select %ends, %one, %eight : i32
    %s5 = arith.select %first, %one, %eight : i32
    %c4p = arith.constant 4 : i32
    %p4 = arith.cmpi eq, %pattern, %c4p : i32
    %c5p = arith.constant 5 : i32
    %p5 = arith.cmpi eq, %pattern, %c5p : i32
    %x00 = arith.select %p5, %s5, %s0 : i32
    %x0 = arith.select %p4, %s4, %x00 : i32
    %x1 = arith.select %p3, %s3, %x0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %jl = arith.subi %j, %c1 : index
    %jr = arith.addi %j, %c1 : index
    %jrr = arith.addi %j, %c2 : index
    %ul = sim.read @U[%jl] : f32
    %u0 = sim.read @U[%j] : f32
    %u1 = sim.read @U[%jr] : f32
    %u2 = sim.read @U[%jrr] : f32
    %v0 = sim.read @V[%j] : f32
    %v1 = sim.read @V[%jr] : f32
    // A fourth-order-like gradient and a plain difference.
    %d01 = arith.subf %u1, %u0 : f32
    %dlr = arith.subf %u2, %ul : f32
    %w = arith.constant 1.25e-1 : f32
    %c = arith.mulf %w, %dlr : f32
    %f = arith.addf %d01, %c : f32
    %dv = arith.subf %v1, %v0 : f32
    %h = arith.constant 5.0e-1 : f32
    %g = arith.mulf %h, %dv : f32
    sim.yield %f, %g : f32, f32
  }

  sim.component @Cells writes(@U, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %i32, %c24 : i32
    %m = arith.remsi %blk, %c4 : i32
    %s0 = arith.shrsi %eight, %m : i32
    %p1 = arith.cmpi eq, %pattern, %one : i32
    %p2 = arith.cmpi eq, %pattern, %c2 : i32
    %p3 = arith.cmpi eq, %pattern, %c3 : i32
    %c4p = arith.constant 4 : i32
    %p4 = arith.cmpi eq, %pattern, %c4p : i32
    %c5p = arith.constant 5 : i32
    %p5 = arith.cmpi eq, %pattern, %c5p : i32
    %p45 = arith.ori %p4, %p5 : i1
    %p34 = arith.ori %p3, %p45 : i1
    %x1 = arith.select %p34, %eight, %s0 : i32
    %x2 = arith.select %p2, %eight, %x1 : i32
    %n = arith.select %p1, %one, %x2 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %il = arith.subi %i, %c1 : index
    %ill = arith.subi %i, %c2 : index
    %ir = arith.addi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %gw = sim.read @G[%ill] : f32
    %ge = sim.read @G[%ir] : f32
    %u = sim.read @U[%i] : f32
    %v = sim.read @V[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %step = arith.mulf %nf, %dt : f32
    %k = arith.constant 2.0e-1 : f32
    %df = arith.subf %fe, %fw : f32
    %dg = arith.subf %ge, %gw : f32
    %ku = arith.mulf %k, %step : f32
    %u1 = math.fma %ku, %df, %u : f32
    %v1 = math.fma %ku, %dg, %v : f32
    sim.yield %u1, %v1 : f32, f32
  }

  sim.component @Observe writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %u = sim.read @U[%ir] : f32
    %w = sim.read @W[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %step = arith.mulf %nf, %dt : f32
    %s = math.fma %step, %u, %w : f32
    sim.yield %s : f32
  }

  sim.total @SumU : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f32
    %d = arith.extf %u : f32 to f64
    sim.yield %d : f64
  }

  sim.observe [@U, @V, @W]
}
