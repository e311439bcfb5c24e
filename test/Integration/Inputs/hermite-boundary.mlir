// A Hermite buffer @X whose derivative @V has another boundary rule, read
// outside the range between the ends of a big step (items 0 and 7 read
// items -1 and 8): the read is @X's item under @X's rule, and @V is read
// there (under zero: no item, the value 0). XRULE and VRULE are replaced
// by hermite-boundary.test.
sim.simulation @s range(8) dt(0.05 : f32) max_steps(4) {
  sim.buffer @V : f32 interp(none) boundary(VRULE) init {
  ^bb0(%i: index):
    %c = arith.constant -0.25 : f32
    sim.yield %c : f32
  }
  sim.buffer @X : f32 interp(#sim.hermite<@V>) boundary(XRULE) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    %c = arith.constant 0.1 : f32
    %x = arith.mulf %f, %c : f32
    sim.yield %x : f32
  }
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @Osc writes(@V, @X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %hv = arith.addf %h, %h : f32
    %nx = arith.negf %x : f32
    %v1 = math.fma %hv, %nx, %v : f32
    %x1 = math.fma %hv, %v1, %x : f32
    sim.yield %v1, %x1 : f32, f32
  }
  sim.component @Probe writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %one = arith.constant 1 : i32
    sim.yield %one : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %k = arith.addi %i, %c1 : index
    %x = sim.read @X[%j] : f32
    %y = sim.read @X[%k] : f32
    %p = sim.read @P[%i] : f32
    %c3 = arith.constant 3.0 : f32
    %y3 = arith.mulf %y, %c3 : f32
    %e = arith.addf %x, %y3 : f32
    %s = arith.addf %p, %e : f32
    sim.yield %s : f32
  }
  sim.schedule [@Osc, @Probe]
  sim.observe [@P]
}
