// A bounding component that holds some big steps at one base step and lets
// others grow (lts-unit-big-steps.test): @A reads @V through the back edge
// and its own @U (so it is no item pair), and its num_steps is 1 at every
// third base step and 8 elsewhere. @B is a stencil on a ring whose levels
// depend on the item alone (invariant_levels: its kept codes meet big steps
// of 1 and of 8), with a stiff stretch that takes every base step.
sim.simulation @unit range(700) dt(1.0e-3 : f64) max_steps(8) {
  sim.param @k = 2.0e-2 : f64

  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 0.021 : f64
    %x = arith.mulf %fi, %c : f64
    %s = math.sin %x : f64
    sim.yield %s : f64
  }
  sim.buffer @V : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 0.047 : f64
    %x = arith.mulf %fi, %c : f64
    %s = math.cos %x : f64
    sim.yield %s : f64
  }

  sim.component @A writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c3 = arith.constant 3 : i64
    %r = arith.remsi %t, %c3 : i64
    %c0 = arith.constant 0 : i64
    %held = arith.cmpi eq, %r, %c0 : i64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %held, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %d = arith.subf %v, %u : f64
    %r = arith.mulf %h, %d : f64
    %u1 = arith.addf %u, %r : f64
    sim.yield %u1 : f64
  }

  sim.component @B writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 300 : index
    %hi = arith.constant 345 : index
    %above = arith.cmpi uge, %i, %lo : index
    %below = arith.cmpi ult, %i, %hi : index
    %stiff = arith.andi %above, %below : i1
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %vl = sim.read @V[%il] : f64
    %v0 = sim.read @V[%i] : f64
    %vr = sim.read @V[%ir] : f64
    %u = sim.read @U[%i] : f64
    %s = arith.addf %vl, %vr : f64
    %two = arith.constant 2.0 : f64
    %d = arith.mulf %two, %v0 : f64
    %lap = arith.subf %s, %d : f64
    %k = sim.get_param @k : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %kh = arith.mulf %k, %h : f64
    %r0 = arith.mulf %kh, %lap : f64
    %c = arith.constant 0.5 : f64
    %hu = arith.mulf %h, %u : f64
    %r1 = math.fma %c, %hu, %r0 : f64
    %v1 = arith.addf %v0, %r1 : f64
    sim.yield %v1 : f64
  }

  sim.schedule [@A]
  sim.observe [@U, @V]
}
