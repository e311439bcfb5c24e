// A window far wider than the range (U[i + 2^40]) under lts: a block's
// neighbours are every block of the range, whatever the window (its
// stiff items, where |u| > 0.5, take 1 base step, the rest 1000).
sim.simulation @far_window range(64) dt(1.0e-2 : f64) max_steps(5) {
  sim.param @k = 1.0 : f64
  sim.buffer @U : f64 interp(#sim.linear) boundary(wrap) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %x = arith.sitofp %i64 : i64 to f64
    %c = arith.constant 15.0 : f64
    %d = arith.subf %x, %c : f64
    %w = arith.constant 4.0 : f64
    %z = arith.divf %d, %w : f64
    %z2 = arith.mulf %z, %z : f64
    %nz = arith.negf %z2 : f64
    %e = math.exp %nz : f64
    sim.yield %e : f64
  }
  sim.component @S writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %u = sim.read @U[%i] : f64
    %a = math.absf %u : f64
    %th = arith.constant 0.5 : f64
    %big = arith.cmpf ogt, %a, %th : f64
    %one = arith.constant 1 : i32
    %many = arith.constant 1000 : i32
    %n = arith.select %big, %one, %many : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %far = arith.constant 1099511627776 : index
    %j = arith.addi %i, %far : index
    %vf = sim.read @U[%j] : f64
    %c1 = arith.constant 1 : index
    %jl = arith.subi %i, %c1 : index
    %vl = sim.read @U[%jl] : f64
    %sum0 = arith.addf %vf, %vl : f64
    %sum = arith.addf %sum0, %vl : f64
    %u0 = sim.read @U[%i] : f64
    %three = arith.constant 3.0 : f64
    %u7 = arith.mulf %three, %u0 : f64
    %lap = arith.subf %sum, %u7 : f64
    %k = sim.get_param @k : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %kh = arith.mulf %k, %h : f64
    %u1 = math.fma %kh, %lap, %u0 : f64
    sim.yield %u1 : f64
  }
  sim.total @Sum : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f64
    sim.yield %u : f64
  }
  sim.observe [@U]
}
