// A chain of particles written as a kick and a drift (leapfrog): @Kick
// updates each particle's velocity @V from its neighbours' positions @X
// (through the back edge) and its own @V; @Drift moves each particle by
// its own new velocity. Under lts the two form no pair: @Kick keeps state
// of its own that @Drift reads only at its own items (docs/Model.md, "Item
// pairs"; the remark says how to write them as one), so lts plans what hip
// plans. @pattern places
// the stiff springs: 0 a stiff segment in the middle, 1 every spring
// stiff (every block at one level), 2 a stiff spring at each end of the
// range, 3 none stiff.
sim.simulation @kick_drift range(200) dt(1.0e-2 : f64) max_steps(8) {
  sim.param @pattern = 0 : i64
  sim.buffer @X : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 0.3 : f64
    %a = arith.mulf %x, %s : f64
    %w = math.sin %a : f64
    %e = arith.constant 0.1 : f64
    %d = arith.mulf %w, %e : f64
    %p = arith.addf %x, %d : f64
    sim.yield %p : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Kick writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %pattern = sim.get_param @pattern : i64
    %range = sim.get_param @range : i64
    %c0 = arith.constant 0 : i64
    %c1 = arith.constant 1 : i64
    %c2 = arith.constant 2 : i64
    %c3 = arith.constant 3 : i64
    %q = arith.divsi %range, %c3 : i64
    %q2 = arith.muli %q, %c2 : i64
    %m0 = arith.cmpi sge, %i64, %q : i64
    %m1 = arith.cmpi slt, %i64, %q2 : i64
    %middle = arith.andi %m0, %m1 : i1
    %last = arith.subi %range, %c1 : i64
    %e0 = arith.cmpi eq, %i64, %c0 : i64
    %e1 = arith.cmpi eq, %i64, %last : i64
    %ends = arith.ori %e0, %e1 : i1
    %p0 = arith.cmpi eq, %pattern, %c0 : i64
    %p1 = arith.cmpi eq, %pattern, %c1 : i64
    %p2 = arith.cmpi eq, %pattern, %c2 : i64
    %s0 = arith.andi %p0, %middle : i1
    %s2 = arith.andi %p2, %ends : i1
    %s02 = arith.ori %s0, %s2 : i1
    %stiff = arith.ori %s02, %p1 : i1
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %stiff, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %xl = sim.read @X[%il] : f64
    %x0 = sim.read @X[%i] : f64
    %xr = sim.read @X[%ir] : f64
    %v = sim.read @V[%i] : f64
    %sum = arith.addf %xl, %xr : f64
    %two = arith.constant 2.0 : f64
    %x2 = arith.mulf %two, %x0 : f64
    %f = arith.subf %sum, %x2 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %v1 = math.fma %h, %f, %v : f64
    sim.yield %v1 : f64
  }
  sim.component @Drift writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %eight = arith.constant 8 : i32
    sim.yield %eight : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %v = sim.read @V[%i] : f64
    %x = sim.read @X[%i] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %x1 = math.fma %h, %v, %x : f64
    sim.yield %x1 : f64
  }
  sim.schedule [@Kick, @Drift]
  sim.observe [@X, @V]
}
