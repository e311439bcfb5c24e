// Local time steps whose finest num_steps is not a power of two (strategy
// lts, docs/Model.md "Levels"): every sub-step is the unit u, the smallest
// num_steps of the component's items (capped at m), times a power of two.
// Items in [@lo, @hi) ask @fine steps, the others @coarse; with both equal
// every block takes hip's grid-wide sub-steps (3, 3, 2 in a big step of 8).
// Two stencils: @Heat (clamp, i-1..i+1) and @Ring (wrap, i-2..i+2, cubic
// time levels, forced by @U interpolated between T and T + m).
sim.simulation @local_unit range(160) dt(5.0e-2 : f32) max_steps(8) {
  sim.param @fine = 3 : i32
  sim.param @coarse = 3 : i32
  sim.param @lo = 40 : i32
  sim.param @hi = 70 : i32

  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.3e-1 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.sin %a : f32
    sim.yield %u : f32
  }
  sim.buffer @R : f32 interp(#sim.cubic) boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 9.0e-2 : f32
    %a = arith.mulf %f, %s : f32
    %u = math.cos %a : f32
    sim.yield %u : f32
  }

  // Diffusion of U over i-1 .. i+1 (clamp).
  sim.component @Heat writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %fine = sim.get_param @fine : i32
    %coarse = sim.get_param @coarse : i32
    %lo = sim.get_param @lo : i32
    %hi = sim.get_param @hi : i32
    %i32 = arith.index_cast %i : index to i32
    %above = arith.cmpi sge, %i32, %lo : i32
    %below = arith.cmpi slt, %i32, %hi : i32
    %in = arith.andi %above, %below : i1
    %n = arith.select %in, %fine, %coarse : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : f32
    %ul = sim.read @U[%l] : f32
    %ur = sim.read @U[%r] : f32
    %s = arith.addf %ul, %ur : f32
    %two = arith.constant 2.0 : f32
    %u2 = arith.mulf %two, %u : f32
    %d = arith.subf %s, %u2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 1.5e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %u1 = math.fma %hk, %d, %u : f32
    sim.yield %u1 : f32
  }

  // Smoothing of R over i-2 .. i+2 (wrap), forced by U.
  sim.component @Ring writes(@R) num_steps {
  ^bb0(%i: index, %t: i64):
    %fine = sim.get_param @fine : i32
    %coarse = sim.get_param @coarse : i32
    %lo = sim.get_param @lo : i32
    %hi = sim.get_param @hi : i32
    %i32 = arith.index_cast %i : index to i32
    %c30 = arith.constant 30 : i32
    %shifted = arith.addi %i32, %c30 : i32
    %above = arith.cmpi sge, %shifted, %lo : i32
    %below = arith.cmpi slt, %shifted, %hi : i32
    %in = arith.andi %above, %below : i1
    %n = arith.select %in, %fine, %coarse : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c2 = arith.constant 2 : index
    %l = arith.subi %i, %c2 : index
    %r = arith.addi %i, %c2 : index
    %x = sim.read @R[%i] : f32
    %xl = sim.read @R[%l] : f32
    %xr = sim.read @R[%r] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %xl, %xr : f32
    %two = arith.constant 2.0 : f32
    %x2 = arith.mulf %two, %x : f32
    %d = arith.subf %s, %x2 : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %k = arith.constant 1.0e-1 : f32
    %hk = arith.mulf %h, %k : f32
    %f = arith.addf %d, %u : f32
    %x1 = math.fma %hk, %f, %x : f32
    sim.yield %x1 : f32
  }

  sim.schedule [@Heat, @Ring]
  sim.observe [@U, @R]
}
