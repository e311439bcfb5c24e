// A big step that grows during the run: @Gate reads @U through the back
// edge, so its num_steps bounds the big step, and it asks 2 base steps
// until t = 16, then 8. @Diffuse takes local time steps with levels that
// never change (invariant_levels: 1 at items 64..95, 8 elsewhere), so its
// kernels keep the levels of the first big step longer than one base
// step, which is 2 here: kept levels must not be capped at that step
// (local-steps.test). @Diffuse reads @G at a neighbour, so the two form
// no item pair (docs/Model.md, "Item pairs") and @Gate keeps bounding the
// big step under lts.
sim.simulation @growing range(200) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %v = math.sin %a : f32
    sim.yield %v : f32
  }
  sim.buffer @G : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @Gate writes(@G) num_steps {
  ^bb0(%i: index, %t: i64):
    %c16 = arith.constant 16 : i64
    %early = arith.cmpi slt, %t, %c16 : i64
    %two = arith.constant 2 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %early, %two, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %h = arith.constant 5.0e-1 : f32
    %g = arith.mulf %u, %h : f32
    sim.yield %g : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 64 : index
    %hi = arith.constant 96 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %stiff = arith.andi %a, %b : i1
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %stiff, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %ul = sim.read @U[%il] : f32
    %ur = sim.read @U[%ir] : f32
    %g = sim.read @G[%ir] : f32
    %s = arith.addf %ul, %ur : f32
    %two = arith.constant 2.0 : f32
    %u2 = arith.mulf %u, %two : f32
    %lap = arith.subf %s, %u2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 2.0e-1 : f32
    %kh = arith.mulf %k, %h : f32
    %d = arith.mulf %lap, %kh : f32
    %gh = arith.mulf %g, %h : f32
    %d2 = arith.subf %d, %gh : f32
    %r = arith.addf %u, %d2 : f32
    sim.yield %r : f32
  }
  sim.schedule [@Gate, @Diffuse]
  sim.observe [@U]
}
