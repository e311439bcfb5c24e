// A reaction-diffusion front (f32) whose stiff region follows the front:
// num_steps depends on the state and on the time. Range 1000 (no multiple of
// a 32-item block), boundary(zero), an asymmetric window i-2..i+1, cubic
// interpolation. Written the way a user would, for user-scenes-lts.test.
sim.simulation @front range(1000) dt(1.0e-4 : f32) max_steps(16) {
  sim.param @D = 1.0e-5 : f32
  sim.param @rate = 50.0 : f32

  sim.buffer @U : f32 interp(#sim.cubic) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 100 : index
    %lt = arith.cmpi ult, %i, %c : index
    %one = arith.constant 1.0 : f32
    %z = arith.constant 0.0 : f32
    %u = arith.select %lt, %one, %z : f32
    sim.yield %u : f32
  }

  sim.component @React writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %u = sim.read @U[%i] : f32
    %one = arith.constant 1.0 : f32
    %om = arith.subf %one, %u : f32
    %p = arith.mulf %u, %om : f32
    %four = arith.constant 4.0 : f32
    %s = arith.mulf %p, %four : f32
    // Near the front (u(1-u) large) take 1 step, far from it 16.
    %f16 = arith.constant 16.0 : f32
    %w = arith.mulf %s, %f16 : f32
    %k = arith.subf %f16, %w : f32
    %kc = arith.maximumf %k, %one : f32
    %n = arith.fptosi %kc : f32 to i32
    %t32 = arith.trunci %t : i64 to i32
    %c7 = arith.constant 7 : i32
    %r = arith.remsi %t32, %c7 : i32
    %zero = arith.constant 0 : i32
    %odd = arith.cmpi eq, %r, %zero : i32
    %c3 = arith.constant 3 : i32
    %n2 = arith.subi %n, %c3 : i32
    %c1 = arith.constant 1 : i32
    %n3 = arith.maxsi %n2, %c1 : i32
    %nn = arith.select %odd, %n3, %n : i32
    sim.yield %nn : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %il2 = arith.subi %i, %c2 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %ull = sim.read @U[%il2] : f32
    %ul = sim.read @U[%il] : f32
    %u0 = sim.read @U[%i] : f32
    %ur = sim.read @U[%ir] : f32
    // A one-sided second difference mixed with the centred one.
    %a = arith.addf %ul, %ur : f32
    %two = arith.constant 2.0 : f32
    %b = arith.mulf %two, %u0 : f32
    %lap = arith.subf %a, %b : f32
    %q = arith.subf %ull, %ul : f32
    %eps = arith.constant 0.125 : f32
    %qe = arith.mulf %q, %eps : f32
    %lap2 = arith.addf %lap, %qe : f32
    %D = sim.get_param @D : f32
    %h2 = arith.constant 1.0e6 : f32
    %dl = arith.mulf %D, %h2 : f32
    %diff = arith.mulf %dl, %lap2 : f32
    %one = arith.constant 1.0 : f32
    %om = arith.subf %one, %u0 : f32
    %p = arith.mulf %u0, %om : f32
    %r = sim.get_param @rate : f32
    %re = arith.mulf %r, %p : f32
    %rhs = arith.addf %diff, %re : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %rhs, %u0 : f32
    sim.yield %u1 : f32
  }

  sim.total @Mass : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f32
    %d = arith.extf %u : f32 to f64
    sim.yield %d : f64
  }
  sim.observe [@U]
}
