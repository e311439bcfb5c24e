// Upwind advection on a ring of 3000 cells (wrap: across the first and last
// rank; 3000 is no multiple of a 32-item level block), a region ten times
// faster at 1000..1399, and a probe that gathers the field at a scrambled
// index (7 i mod 3000). Written the way a user would, for user-scenes.test.
sim.simulation @ring range(3000) dt(1.0e-5 : f32) max_steps(16) {
  sim.param @speed = 2.0 : f32

  sim.buffer @Q : f32 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    %s = arith.constant 0.01 : f32
    %a = arith.mulf %f, %s : f32
    %v = math.sin %a : f32
    sim.yield %v : f32
  }

  sim.buffer @P : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Advect writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 1000 : index
    %hi = arith.constant 1400 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %fast = arith.andi %a, %b : i1
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %fast, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %q = sim.read @Q[%i] : f32
    %ql = sim.read @Q[%il] : f32
    %lo = arith.constant 1000 : index
    %hi = arith.constant 1400 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %fast = arith.andi %a, %b : i1
    %sp = sim.get_param @speed : f32
    %ten = arith.constant 10.0 : f32
    %spf = arith.mulf %sp, %ten : f32
    %v = arith.select %fast, %spf, %sp : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %inv = arith.constant 3000.0 : f32
    %c0 = arith.mulf %v, %h : f32
    %c = arith.mulf %c0, %inv : f32
    %d = arith.subf %q, %ql : f32
    %cd = arith.mulf %c, %d : f32
    %q1 = arith.subf %q, %cd : f32
    sim.yield %q1 : f32
  }

  sim.component @Probe writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %four = arith.constant 4 : i32
    sim.yield %four : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c7 = arith.constant 7 : index
    %cr = arith.constant 3000 : index
    %j0 = arith.muli %i, %c7 : index
    %j = arith.remui %j0, %cr : index
    %q = sim.read @Q[%j] : f32
    %p = sim.read @P[%i] : f32
    %half = arith.constant 0.5 : f32
    %s = arith.addf %p, %q : f32
    %p1 = arith.mulf %s, %half : f32
    sim.yield %p1 : f32
  }

  sim.total @Mass : f64 {
  ^bb0(%i: index):
    %q = sim.read @Q[%i] : f32
    %d = arith.extf %q : f32 to f64
    sim.yield %d : f64
  }
  sim.observe [@Q, @P]
}
