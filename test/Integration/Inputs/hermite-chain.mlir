// Local time steps through a Hermite interpolation (strategy lts,
// docs/Model.md "What a read returns"): three spring chains, each a
// component that writes its positions and their derivative (its
// velocities) and reads its neighbours' positions, interpolated with
// #sim.hermite through the velocities, which the same component keeps at
// the same two time levels. @X (f64, wrap) reads i-1..i+1, @P
// (vector<2xf32>, clamp) i-2..i+1, @Z (f32, zero) i-40..i+40, wider than a
// level block (32 items). @Probe relaxes towards @X, which it reads between
// T and T + m, as hip does.
//
// num_steps by @pattern, as in local-steps.mlir: 0, blocks of 24 items ask
// 8, 4, 2, 1 in turn (each chain shifted); 1, every item 1 (all fine: lts
// is simple); 2, every item 8 (all coarse: lts is hip); 3, one stiff item
// (77) in a soft range. @Probe takes 3 base steps, 1 under pattern 1.
sim.simulation @hermite_chain range(200) dt(5.0e-2 : f32) max_steps(8) {
  sim.param @pattern = 0 : i32

  sim.buffer @V : f64 boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s = arith.constant 1.3e-1 : f64
    %a = arith.mulf %f, %s : f64
    %u = math.sin %a : f64
    sim.yield %u : f64
  }
  sim.buffer @Q : vector<2xf32> boundary(clamp) init {
  ^bb0(%i: index):
    %z = arith.constant dense<[1.0e-1, -2.0e-1]> : vector<2xf32>
    sim.yield %z : vector<2xf32>
  }
  sim.buffer @P : vector<2xf32> interp(#sim.hermite<@Q>) boundary(clamp) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 7.0e-2 : f32
    %a = arith.mulf %f, %s : f32
    %c = math.cos %a : f32
    %d = math.sin %a : f32
    %p = vector.from_elements %c, %d : vector<2xf32>
    sim.yield %p : vector<2xf32>
  }
  sim.buffer @W : f32 boundary(zero) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @Z : f32 interp(#sim.hermite<@W>) boundary(zero) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %c7 = arith.constant 7 : i32
    %r = arith.remsi %i32, %c7 : i32
    %f = arith.sitofp %r : i32 to f32
    sim.yield %f : f32
  }
  sim.buffer @Y : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  // Springs to both neighbours (wrap), symplectic Euler.
  sim.component @Ring writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %off = arith.constant 0 : i32
    %j = arith.addi %i32, %off : i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %j, %c24 : i32
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
  }
  evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %x = sim.read @X[%i] : f64
    %xl = sim.read @X[%l] : f64
    %xr = sim.read @X[%r] : f64
    %v = sim.read @V[%i] : f64
    %s = arith.addf %xl, %xr : f64
    %two = arith.constant 2.0 : f64
    %x2 = arith.mulf %two, %x : f64
    %a = arith.subf %s, %x2 : f64
    %nf = arith.sitofp %n : i32 to f64
    %dtd = arith.extf %dt : f32 to f64
    %h = arith.mulf %nf, %dtd : f64
    %v1 = math.fma %h, %a, %v : f64
    %x1 = math.fma %h, %v1, %x : f64
    sim.yield %x1, %v1 : f64, f64
  }

  // A plane chain (clamp) over i-2..i+1.
  sim.component @Plane writes(@P, @Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %off = arith.constant 11 : i32
    %j = arith.addi %i32, %off : i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %j, %c24 : i32
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
  }
  evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %l = arith.subi %i, %c2 : index
    %r = arith.addi %i, %c1 : index
    %p = sim.read @P[%i] : vector<2xf32>
    %pl = sim.read @P[%l] : vector<2xf32>
    %pr = sim.read @P[%r] : vector<2xf32>
    %q = sim.read @Q[%i] : vector<2xf32>
    %s = arith.addf %pl, %pr : vector<2xf32>
    %two = arith.constant dense<2.0> : vector<2xf32>
    %p2 = arith.mulf %two, %p : vector<2xf32>
    %a = arith.subf %s, %p2 : vector<2xf32>
    %k = arith.constant dense<5.0e-1> : vector<2xf32>
    %ka = arith.mulf %k, %a : vector<2xf32>
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %hb = vector.broadcast %h : f32 to vector<2xf32>
    %q1 = math.fma %hb, %ka, %q : vector<2xf32>
    %p1 = math.fma %hb, %q1, %p : vector<2xf32>
    sim.yield %p1, %q1 : vector<2xf32>, vector<2xf32>
  }

  // A long-range chain (zero past the ends): springs to the items 40 away.
  sim.component @Far writes(@Z, @W) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %i32 = arith.index_cast %i : index to i32
    %off = arith.constant 5 : i32
    %j = arith.addi %i32, %off : i32
    %c24 = arith.constant 24 : i32
    %c4 = arith.constant 4 : i32
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %c77 = arith.constant 77 : i32
    %c2 = arith.constant 2 : i32
    %c3 = arith.constant 3 : i32
    %blk = arith.divsi %j, %c24 : i32
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
  }
  evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c40 = arith.constant 40 : index
    %l = arith.subi %i, %c40 : index
    %r = arith.addi %i, %c40 : index
    %z = sim.read @Z[%i] : f32
    %zl = sim.read @Z[%l] : f32
    %zr = sim.read @Z[%r] : f32
    %w = sim.read @W[%i] : f32
    %s = arith.addf %zl, %zr : f32
    %two = arith.constant 2.0 : f32
    %z2 = arith.mulf %two, %z : f32
    %a = arith.subf %s, %z2 : f32
    %k = arith.constant 2.5e-1 : f32
    %ka = arith.mulf %k, %a : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %w1 = math.fma %h, %ka, %w : f32
    %z1 = math.fma %h, %w1, %z : f32
    sim.yield %z1, %w1 : f32, f32
  }

  // Follows @X at its neighbour, between T and T + m (Hermite from the
  // snapshot at T and the values at T + m).
  sim.component @Probe writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %pattern = sim.get_param @pattern : i32
    %one = arith.constant 1 : i32
    %three = arith.constant 3 : i32
    %fine = arith.cmpi eq, %pattern, %one : i32
    %n = arith.select %fine, %one, %three : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %x = sim.read @X[%r] : f64
    %y = sim.read @Y[%i] : f64
    %d = arith.subf %x, %y : f64
    %nf = arith.sitofp %n : i32 to f64
    %dtd = arith.extf %dt : f32 to f64
    %h = arith.mulf %nf, %dtd : f64
    %y1 = math.fma %h, %d, %y : f64
    sim.yield %y1 : f64
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : f64
    %vv = arith.mulf %v, %v : f64
    sim.yield %vv : f64
  }
  sim.schedule [@Ring, @Plane, @Far, @Probe]
  sim.observe [@X, @P, @Z, @Y]
}
