// pbd: a rope of particles with position-based dynamics (f64, 2D).
//
// Physics. range (256) unit-mass particles, initially at rest on a
// horizontal line with spacing @L0 (a rope of length 1), item 0 pinned at the
// origin, gravity @g = 9.81 downwards: the rope swings down like a pendulum.
// Each step is position-based dynamics (Mueller et al. 2007): predict
// p = x + h (v + h g), project the distance constraints |p_i - p_{i+1}| = L0
// with 4 Jacobi iterations (each moves a particle by @relax = 0.5 times the
// sum of its constraint corrections, split by inverse mass: 1/2 each, all of
// it when the neighbour is the pinned item), then v = (p - x) / h, x = p.
// PBD is not a discretisation of one ODE: the rope's stretch depends on the
// step and the iteration count (at dt / 8 the rope is much stiffer: rms-rel
// 1.3 away after 1000 base steps), so the reference is `simple` at the same
// base step (`sim-run --reference simple`; python/accuracy_study.py compares
// the dumps): it measures what the larger shared steps change.
//
// Components:
//   @Predict  (first) writes @P; reads @X[i] and @V[i] through the back edge.
//             num_steps = floor(@cfl L0 / (|v| dt)): no particle moves more
//             than @cfl segment lengths per step.
//   @Solve1 .. @Solve4 write @Q1 .. @Q4, one Jacobi iteration each, reading
//             the previous iterate at i-1..i+1 (a window).
//   @Update   writes @V and @X from @Q4[i] and its own @X.
// @Predict reads through the back edge and has num_steps, so hip and
// traditional both take the global minimum as the big step (the fastest
// particle sets one shared step); the other components take the whole big
// step in one evaluation. At rest every step is max_steps (8); once the rope
// falls the free end sets the step.
//
// Observed: @X.
sim.simulation @pbd range(256) dt(1.0e-3 : f64) max_steps(8) {
  // Rest length of a segment (the rope is 1 long at 256 items).
  sim.param @L0 = 3.921568627450980e-3 : f64
  // Jacobi relaxation of the constraint corrections.
  sim.param @relax = 5.0e-1 : f64
  // Gravity (downwards).
  sim.param @g = 9.81 : f64
  // num_steps = floor(@cfl L0 / (|v| dt)): no particle moves more than
  // @cfl segment lengths in a step.
  sim.param @cfl = 1.0 : f64

  sim.buffer @X : vector<2xf64> init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %fi = arith.sitofp %i64 : i64 to f64
    %L0 = sim.get_param @L0 : f64
    %x = arith.mulf %fi, %L0 : f64
    %zero = arith.constant 0.0 : f64
    %p = vector.from_elements %x, %zero : vector<2xf64>
    sim.yield %p : vector<2xf64>
  }
  sim.buffer @V : vector<2xf64> init {
  ^bb0(%i: index):
    %zv = arith.constant dense<0.0> : vector<2xf64>
    sim.yield %zv : vector<2xf64>
  }
  // Predicted positions.
  sim.buffer @P : vector<2xf64> init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }
  // Positions after constraint iteration 1.
  sim.buffer @Q1 : vector<2xf64> init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }
  // Positions after constraint iteration 2.
  sim.buffer @Q2 : vector<2xf64> init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }
  // Positions after constraint iteration 3.
  sim.buffer @Q3 : vector<2xf64> init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }
  // Positions after constraint iteration 4.
  sim.buffer @Q4 : vector<2xf64> init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }

  sim.component @Predict writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %v = sim.read @V[%i] : vector<2xf64>
    %v2v = arith.mulf %v, %v : vector<2xf64>
    %tiny = arith.constant 1.0e-30 : f64
    %v2 = vector.reduction <add>, %v2v, %tiny : vector<2xf64> into f64
    %s = math.sqrt %v2 : f64
    %cfl = sim.get_param @cfl : f64
    %L0 = sim.get_param @L0 : f64
    %dt = sim.get_param @dt : f64
    %num = arith.mulf %cfl, %L0 : f64
    %sd = arith.mulf %s, %dt : f64
    %q = arith.divf %num, %sd : f64
    %cap = arith.constant 1.0e6 : f64
    %qc = arith.minimumf %q, %cap : f64
    %n = arith.fptosi %qc : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    // Position and velocity at T (back edge).
    %x = sim.read @X[%i] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %g = sim.get_param @g : f64
    %ng = arith.negf %g : f64
    %zero = arith.constant 0.0 : f64
    %gv = vector.from_elements %zero, %ng : vector<2xf64>
    %hv = vector.broadcast %h : f64 to vector<2xf64>
    %v1 = vector.fma %hv, %gv, %v : vector<2xf64>
    %p = vector.fma %hv, %v1, %x : vector<2xf64>
    %i64 = arith.index_cast %i : index to i64
    %c0 = arith.constant 0 : i64
    %pinned = arith.cmpi eq, %i64, %c0 : i64
    %r = arith.select %pinned, %x, %p : vector<2xf64>
    sim.yield %r : vector<2xf64>
  }

  sim.component @Solve1 writes(@Q1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %range = sim.get_param @range : i64
    %i64 = arith.index_cast %i : index to i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %last = arith.subi %range, %c1 : i64
    %pinned = arith.cmpi eq, %i64, %c0 : i64
    %hasl = arith.cmpi sgt, %i64, %c0 : i64
    %hasr = arith.cmpi slt, %i64, %last : i64
    %m1 = arith.constant -1 : index
    %p1 = arith.constant 1 : index
    %il = arith.addi %i, %m1 : index
    %ir = arith.addi %i, %p1 : index
    %pi = sim.read @P[%i] : vector<2xf64>
    %pl = sim.read @P[%il] : vector<2xf64>
    %pr = sim.read @P[%ir] : vector<2xf64>
    %L0 = sim.get_param @L0 : f64
    %relax = sim.get_param @relax : f64
    %zero = arith.constant 0.0 : f64
    %tiny = arith.constant 1.0e-30 : f64
    %half = arith.constant 0.5 : f64
    %one = arith.constant 1.0 : f64
    %zv = arith.constant dense<0.0> : vector<2xf64>
    // Constraint |p_i - p_l| = L0 with the left neighbour (weight 1 when the
    // neighbour is the pinned item 0, else 1/2).
    %dl = arith.subf %pi, %pl : vector<2xf64>
    %dl2v = arith.mulf %dl, %dl : vector<2xf64>
    %dl2 = vector.reduction <add>, %dl2v, %tiny : vector<2xf64> into f64
    %ll = math.sqrt %dl2 : f64
    %el = arith.subf %ll, %L0 : f64
    %sl0 = arith.divf %el, %ll : f64
    %lpin = arith.cmpi eq, %i64, %c1 : i64
    %wl = arith.select %lpin, %one, %half : f64
    %sl1 = arith.mulf %sl0, %wl : f64
    %sl = arith.select %hasl, %sl1, %zero : f64
    %slv = vector.broadcast %sl : f64 to vector<2xf64>
    %cl = arith.mulf %slv, %dl : vector<2xf64>
    // ... and with the right neighbour.
    %dr = arith.subf %pi, %pr : vector<2xf64>
    %dr2v = arith.mulf %dr, %dr : vector<2xf64>
    %dr2 = vector.reduction <add>, %dr2v, %tiny : vector<2xf64> into f64
    %lr = math.sqrt %dr2 : f64
    %er = arith.subf %lr, %L0 : f64
    %sr0 = arith.divf %er, %lr : f64
    %sr1 = arith.mulf %sr0, %half : f64
    %sr = arith.select %hasr, %sr1, %zero : f64
    %srv = vector.broadcast %sr : f64 to vector<2xf64>
    %cr = arith.mulf %srv, %dr : vector<2xf64>
    %c = arith.addf %cl, %cr : vector<2xf64>
    %rv = vector.broadcast %relax : f64 to vector<2xf64>
    %corr = arith.mulf %rv, %c : vector<2xf64>
    %q0 = arith.subf %pi, %corr : vector<2xf64>
    %q = arith.select %pinned, %pi, %q0 : vector<2xf64>
    sim.yield %q : vector<2xf64>
  }

  sim.component @Solve2 writes(@Q2) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %range = sim.get_param @range : i64
    %i64 = arith.index_cast %i : index to i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %last = arith.subi %range, %c1 : i64
    %pinned = arith.cmpi eq, %i64, %c0 : i64
    %hasl = arith.cmpi sgt, %i64, %c0 : i64
    %hasr = arith.cmpi slt, %i64, %last : i64
    %m1 = arith.constant -1 : index
    %p1 = arith.constant 1 : index
    %il = arith.addi %i, %m1 : index
    %ir = arith.addi %i, %p1 : index
    %pi = sim.read @Q1[%i] : vector<2xf64>
    %pl = sim.read @Q1[%il] : vector<2xf64>
    %pr = sim.read @Q1[%ir] : vector<2xf64>
    %L0 = sim.get_param @L0 : f64
    %relax = sim.get_param @relax : f64
    %zero = arith.constant 0.0 : f64
    %tiny = arith.constant 1.0e-30 : f64
    %half = arith.constant 0.5 : f64
    %one = arith.constant 1.0 : f64
    %zv = arith.constant dense<0.0> : vector<2xf64>
    // Constraint |p_i - p_l| = L0 with the left neighbour (weight 1 when the
    // neighbour is the pinned item 0, else 1/2).
    %dl = arith.subf %pi, %pl : vector<2xf64>
    %dl2v = arith.mulf %dl, %dl : vector<2xf64>
    %dl2 = vector.reduction <add>, %dl2v, %tiny : vector<2xf64> into f64
    %ll = math.sqrt %dl2 : f64
    %el = arith.subf %ll, %L0 : f64
    %sl0 = arith.divf %el, %ll : f64
    %lpin = arith.cmpi eq, %i64, %c1 : i64
    %wl = arith.select %lpin, %one, %half : f64
    %sl1 = arith.mulf %sl0, %wl : f64
    %sl = arith.select %hasl, %sl1, %zero : f64
    %slv = vector.broadcast %sl : f64 to vector<2xf64>
    %cl = arith.mulf %slv, %dl : vector<2xf64>
    // ... and with the right neighbour.
    %dr = arith.subf %pi, %pr : vector<2xf64>
    %dr2v = arith.mulf %dr, %dr : vector<2xf64>
    %dr2 = vector.reduction <add>, %dr2v, %tiny : vector<2xf64> into f64
    %lr = math.sqrt %dr2 : f64
    %er = arith.subf %lr, %L0 : f64
    %sr0 = arith.divf %er, %lr : f64
    %sr1 = arith.mulf %sr0, %half : f64
    %sr = arith.select %hasr, %sr1, %zero : f64
    %srv = vector.broadcast %sr : f64 to vector<2xf64>
    %cr = arith.mulf %srv, %dr : vector<2xf64>
    %c = arith.addf %cl, %cr : vector<2xf64>
    %rv = vector.broadcast %relax : f64 to vector<2xf64>
    %corr = arith.mulf %rv, %c : vector<2xf64>
    %q0 = arith.subf %pi, %corr : vector<2xf64>
    %q = arith.select %pinned, %pi, %q0 : vector<2xf64>
    sim.yield %q : vector<2xf64>
  }

  sim.component @Solve3 writes(@Q3) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %range = sim.get_param @range : i64
    %i64 = arith.index_cast %i : index to i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %last = arith.subi %range, %c1 : i64
    %pinned = arith.cmpi eq, %i64, %c0 : i64
    %hasl = arith.cmpi sgt, %i64, %c0 : i64
    %hasr = arith.cmpi slt, %i64, %last : i64
    %m1 = arith.constant -1 : index
    %p1 = arith.constant 1 : index
    %il = arith.addi %i, %m1 : index
    %ir = arith.addi %i, %p1 : index
    %pi = sim.read @Q2[%i] : vector<2xf64>
    %pl = sim.read @Q2[%il] : vector<2xf64>
    %pr = sim.read @Q2[%ir] : vector<2xf64>
    %L0 = sim.get_param @L0 : f64
    %relax = sim.get_param @relax : f64
    %zero = arith.constant 0.0 : f64
    %tiny = arith.constant 1.0e-30 : f64
    %half = arith.constant 0.5 : f64
    %one = arith.constant 1.0 : f64
    %zv = arith.constant dense<0.0> : vector<2xf64>
    // Constraint |p_i - p_l| = L0 with the left neighbour (weight 1 when the
    // neighbour is the pinned item 0, else 1/2).
    %dl = arith.subf %pi, %pl : vector<2xf64>
    %dl2v = arith.mulf %dl, %dl : vector<2xf64>
    %dl2 = vector.reduction <add>, %dl2v, %tiny : vector<2xf64> into f64
    %ll = math.sqrt %dl2 : f64
    %el = arith.subf %ll, %L0 : f64
    %sl0 = arith.divf %el, %ll : f64
    %lpin = arith.cmpi eq, %i64, %c1 : i64
    %wl = arith.select %lpin, %one, %half : f64
    %sl1 = arith.mulf %sl0, %wl : f64
    %sl = arith.select %hasl, %sl1, %zero : f64
    %slv = vector.broadcast %sl : f64 to vector<2xf64>
    %cl = arith.mulf %slv, %dl : vector<2xf64>
    // ... and with the right neighbour.
    %dr = arith.subf %pi, %pr : vector<2xf64>
    %dr2v = arith.mulf %dr, %dr : vector<2xf64>
    %dr2 = vector.reduction <add>, %dr2v, %tiny : vector<2xf64> into f64
    %lr = math.sqrt %dr2 : f64
    %er = arith.subf %lr, %L0 : f64
    %sr0 = arith.divf %er, %lr : f64
    %sr1 = arith.mulf %sr0, %half : f64
    %sr = arith.select %hasr, %sr1, %zero : f64
    %srv = vector.broadcast %sr : f64 to vector<2xf64>
    %cr = arith.mulf %srv, %dr : vector<2xf64>
    %c = arith.addf %cl, %cr : vector<2xf64>
    %rv = vector.broadcast %relax : f64 to vector<2xf64>
    %corr = arith.mulf %rv, %c : vector<2xf64>
    %q0 = arith.subf %pi, %corr : vector<2xf64>
    %q = arith.select %pinned, %pi, %q0 : vector<2xf64>
    sim.yield %q : vector<2xf64>
  }

  sim.component @Solve4 writes(@Q4) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %range = sim.get_param @range : i64
    %i64 = arith.index_cast %i : index to i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %last = arith.subi %range, %c1 : i64
    %pinned = arith.cmpi eq, %i64, %c0 : i64
    %hasl = arith.cmpi sgt, %i64, %c0 : i64
    %hasr = arith.cmpi slt, %i64, %last : i64
    %m1 = arith.constant -1 : index
    %p1 = arith.constant 1 : index
    %il = arith.addi %i, %m1 : index
    %ir = arith.addi %i, %p1 : index
    %pi = sim.read @Q3[%i] : vector<2xf64>
    %pl = sim.read @Q3[%il] : vector<2xf64>
    %pr = sim.read @Q3[%ir] : vector<2xf64>
    %L0 = sim.get_param @L0 : f64
    %relax = sim.get_param @relax : f64
    %zero = arith.constant 0.0 : f64
    %tiny = arith.constant 1.0e-30 : f64
    %half = arith.constant 0.5 : f64
    %one = arith.constant 1.0 : f64
    %zv = arith.constant dense<0.0> : vector<2xf64>
    // Constraint |p_i - p_l| = L0 with the left neighbour (weight 1 when the
    // neighbour is the pinned item 0, else 1/2).
    %dl = arith.subf %pi, %pl : vector<2xf64>
    %dl2v = arith.mulf %dl, %dl : vector<2xf64>
    %dl2 = vector.reduction <add>, %dl2v, %tiny : vector<2xf64> into f64
    %ll = math.sqrt %dl2 : f64
    %el = arith.subf %ll, %L0 : f64
    %sl0 = arith.divf %el, %ll : f64
    %lpin = arith.cmpi eq, %i64, %c1 : i64
    %wl = arith.select %lpin, %one, %half : f64
    %sl1 = arith.mulf %sl0, %wl : f64
    %sl = arith.select %hasl, %sl1, %zero : f64
    %slv = vector.broadcast %sl : f64 to vector<2xf64>
    %cl = arith.mulf %slv, %dl : vector<2xf64>
    // ... and with the right neighbour.
    %dr = arith.subf %pi, %pr : vector<2xf64>
    %dr2v = arith.mulf %dr, %dr : vector<2xf64>
    %dr2 = vector.reduction <add>, %dr2v, %tiny : vector<2xf64> into f64
    %lr = math.sqrt %dr2 : f64
    %er = arith.subf %lr, %L0 : f64
    %sr0 = arith.divf %er, %lr : f64
    %sr1 = arith.mulf %sr0, %half : f64
    %sr = arith.select %hasr, %sr1, %zero : f64
    %srv = vector.broadcast %sr : f64 to vector<2xf64>
    %cr = arith.mulf %srv, %dr : vector<2xf64>
    %c = arith.addf %cl, %cr : vector<2xf64>
    %rv = vector.broadcast %relax : f64 to vector<2xf64>
    %corr = arith.mulf %rv, %c : vector<2xf64>
    %q0 = arith.subf %pi, %corr : vector<2xf64>
    %q = arith.select %pinned, %pi, %q0 : vector<2xf64>
    sim.yield %q : vector<2xf64>
  }

  sim.component @Update writes(@V, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : vector<2xf64>
    %q = sim.read @Q4[%i] : vector<2xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %d = arith.subf %q, %x : vector<2xf64>
    %hv = vector.broadcast %h : f64 to vector<2xf64>
    %v = arith.divf %d, %hv : vector<2xf64>
    sim.yield %v, %q : vector<2xf64>, vector<2xf64>
  }

  sim.schedule [@Predict]
  sim.observe [@X]
}
