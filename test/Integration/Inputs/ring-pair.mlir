// An item pair of 2-D particles on a ring (vector<2xf64>, boundary wrap):
// @Force reads the positions at i-2..i+2 and writes a force and a scalar
// (@P) that @Step reads at its own item; @Monitor, after the pair, reads
// the positions through a window. Stiff items (1 base step) every 50, a
// state-dependent estimate elsewhere. INTERP is substituted by
// item-pairs.test: nothing (linear) or interp(none), which only lts can
// read (its pair reads @P as it is; hip interpolates it).
sim.simulation @ring_pair range(300) dt(2.0e-2 : f64) max_steps(8) {
  sim.param @k = 3.0e1 : f64
  sim.buffer @X : vector<2xf64> interp(#sim.cubic) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 1.0e-1 : f64
    %a = arith.mulf %f, %s : f64
    %x = math.sin %a : f64
    %y = math.cos %a : f64
    %v = vector.from_elements %x, %y : vector<2xf64>
    sim.yield %v : vector<2xf64>
  }
  sim.buffer @V : vector<2xf64> boundary(wrap) init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<2xf64>
    sim.yield %z : vector<2xf64>
  }
  sim.buffer @F : vector<2xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<2xf64>
    sim.yield %z : vector<2xf64>
  }
  sim.buffer @P : f64 INTERP init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @M : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.component @Force writes(@F, @P) num_steps {
  ^bb0(%i: index, %t: i64):
    %v = sim.read @V[%i] : vector<2xf64>
    %v0 = vector.extract %v[0] : f64 from vector<2xf64>
    %a = math.absf %v0 : f64
    %c = arith.constant 2.0e1 : f64
    %s = arith.mulf %a, %c : f64
    %one = arith.constant 1.0 : f64
    %d = arith.addf %s, %one : f64
    %e = arith.constant 8.0 : f64
    %q = arith.divf %e, %d : f64
    %n = arith.fptosi %q : f64 to i32
    %i64 = arith.index_cast %i : index to i64
    %c50 = arith.constant 50 : i64
    %r = arith.remsi %i64, %c50 : i64
    %c7 = arith.constant 7 : i64
    %stiff = arith.cmpi slt, %r, %c7 : i64
    %n1 = arith.constant 1 : i32
    %nn = arith.select %stiff, %n1, %n : i32
    sim.yield %nn : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %im2 = arith.subi %i, %c2 : index
    %im1 = arith.subi %i, %c1 : index
    %ip1 = arith.addi %i, %c1 : index
    %ip2 = arith.addi %i, %c2 : index
    %a = sim.read @X[%im2] : vector<2xf64>
    %b = sim.read @X[%im1] : vector<2xf64>
    %x = sim.read @X[%i] : vector<2xf64>
    %c = sim.read @X[%ip1] : vector<2xf64>
    %d = sim.read @X[%ip2] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %s1 = arith.addf %b, %c : vector<2xf64>
    %s2 = arith.addf %a, %d : vector<2xf64>
    %two = arith.constant dense<2.0> : vector<2xf64>
    %x2 = arith.mulf %x, %two : vector<2xf64>
    %l1 = arith.subf %s1, %x2 : vector<2xf64>
    %l2 = arith.subf %s2, %x2 : vector<2xf64>
    %q = arith.constant dense<2.5e-1> : vector<2xf64>
    %l2q = arith.mulf %l2, %q : vector<2xf64>
    %l = arith.addf %l1, %l2q : vector<2xf64>
    %k = sim.get_param @k : f64
    %kv = vector.broadcast %k : f64 to vector<2xf64>
    %f0 = arith.mulf %l, %kv : vector<2xf64>
    %damp = arith.constant dense<1.0e-2> : vector<2xf64>
    %fd = arith.mulf %v, %damp : vector<2xf64>
    %f = arith.subf %f0, %fd : vector<2xf64>
    %p = vector.reduction <add>, %l1 : vector<2xf64> into f64
    sim.yield %f, %p : vector<2xf64>, f64
  }
  sim.component @Step writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %c50 = arith.constant 50 : i64
    %r = arith.remsi %i64, %c50 : i64
    %c7 = arith.constant 7 : i64
    %stiff = arith.cmpi slt, %r, %c7 : i64
    %n1 = arith.constant 1 : i32
    %n8 = arith.constant 8 : i32
    %nn = arith.select %stiff, %n1, %n8 : i32
    sim.yield %nn : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %f = sim.read @F[%i] : vector<2xf64>
    %p = sim.read @P[%i] : f64
    %x = sim.read @X[%i] : vector<2xf64>
    %v = sim.read @V[%i] : vector<2xf64>
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %hv = vector.broadcast %h : f64 to vector<2xf64>
    %small = arith.constant 1.0e-3 : f64
    %ps = arith.mulf %p, %small : f64
    %pv = vector.broadcast %ps : f64 to vector<2xf64>
    %fp = arith.addf %f, %pv : vector<2xf64>
    %v1 = vector.fma %hv, %fp, %v : vector<2xf64>
    %x1 = vector.fma %hv, %v1, %x : vector<2xf64>
    sim.yield %x1, %v1 : vector<2xf64>, vector<2xf64>
  }
  sim.component @Monitor writes(@M) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c3 = arith.constant 3 : index
    %j = arith.addi %i, %c3 : index
    %x = sim.read @X[%j] : vector<2xf64>
    %s = vector.reduction <add>, %x : vector<2xf64> into f64
    sim.yield %s : f64
  }
  sim.total @Kinetic : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : vector<2xf64>
    %v2 = arith.mulf %v, %v : vector<2xf64>
    %s = vector.reduction <add>, %v2 : vector<2xf64> into f64
    sim.yield %s : f64
  }
  sim.schedule [@Force, @Step, @Monitor]
  sim.observe [@X, @M]
}
