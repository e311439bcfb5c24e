// A diffusing temperature @T (a stencil with a stiff band at 200..259)
// heated by a source @S that a later component updates from @T, so that
// @Conduct reads @S through the back edge; a monitor without num_steps
// gathers @T at a reflected index. Written the way a user would, for
// user-scenes-lts.test.
sim.simulation @backedge range(517) dt(1.0e-6 : f64) max_steps(8) {
  sim.param @k = 1.0e-3 : f64

  sim.buffer @T : f64 interp(#sim.linear) boundary(clamp) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 0.02 : f64
    %a = arith.mulf %f, %s : f64
    %v = math.sin %a : f64
    sim.yield %v : f64
  }
  sim.buffer @S : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @M : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Conduct writes(@T) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 200 : index
    %hi = arith.constant 260 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %st = arith.andi %a, %b : i1
    %one = arith.constant 1 : i32
    %eight = arith.constant 8 : i32
    %n = arith.select %st, %one, %eight : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %tl = sim.read @T[%il] : f64
    %t0 = sim.read @T[%i] : f64
    %tr = sim.read @T[%ir] : f64
    %s = sim.read @S[%i] : f64
    %a = arith.addf %tl, %tr : f64
    %two = arith.constant 2.0 : f64
    %b = arith.mulf %two, %t0 : f64
    %lap = arith.subf %a, %b : f64
    %k = sim.get_param @k : f64
    %h2 = arith.constant 2.5e5 : f64
    %kh = arith.mulf %k, %h2 : f64
    %lo = arith.constant 200 : index
    %hi = arith.constant 260 : index
    %x = arith.cmpi uge, %i, %lo : index
    %y = arith.cmpi ult, %i, %hi : index
    %st = arith.andi %x, %y : i1
    %c100 = arith.constant 8.0 : f64
    %one = arith.constant 1.0 : f64
    %f = arith.select %st, %c100, %one : f64
    %khf = arith.mulf %kh, %f : f64
    %r0 = arith.mulf %khf, %lap : f64
    %r = arith.addf %r0, %s : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %t1 = math.fma %h, %r, %t0 : f64
    sim.yield %t1 : f64
  }

  sim.component @Source writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 4 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %tv = sim.read @T[%ir] : f64
    %s = sim.read @S[%i] : f64
    %g = arith.constant -0.5 : f64
    %d = arith.subf %tv, %s : f64
    %gd = arith.mulf %g, %d : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %s1 = math.fma %h, %gd, %s : f64
    sim.yield %s1 : f64
  }

  sim.component @Monitor writes(@M) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %r = arith.constant 516 : index
    %j = arith.subi %r, %i : index
    %tv = sim.read @T[%j] : f64
    sim.yield %tv : f64
  }
  sim.schedule [@Conduct, @Source, @Monitor]
  sim.observe [@T, @S, @M]
}
