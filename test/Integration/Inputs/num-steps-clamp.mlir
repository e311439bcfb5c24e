// num_steps values out of range: 0, negative (down to INT32_MIN), more than
// max_steps (up to INT32_MAX). Values below 1 count as 1; a big step is
// capped by max_steps and by the end of the run; sub-steps by the end of the
// big step. Nothing may hang, and every run must end at exactly N.
//
// With @mode = 0: @Bound (reads @Y through the back edge, so it bounds the
// hip step) asks for 5, 1000 or INT32_MAX base steps, so hip takes
// max_steps (4); @Sub (in a thread group) asks for 0 in items 0..31, -7 in
// 32..63, 1000 in 64..95 and INT32_MIN in 96..119, so traditional takes 1;
// @Grid (reads its own neighbours: grid_sync) asks for 0 or 7.
// With @mode = 1 every num_steps is 1000 or INT32_MAX; with @force = 1, 1.
sim.simulation @num_steps_clamp range(120) dt(5.0e-2 : f32) max_steps(4) {
  sim.param @force = 0 : i32
  sim.param @mode = 0 : i32

  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %x = math.sin %a : f32
    sim.yield %x : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @G : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 2.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %x = math.cos %a : f32
    sim.yield %x : f32
  }

  sim.component @Bound writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %c5 = arith.constant 5 : i32
    %c1000 = arith.constant 1000 : i32
    %cmax = arith.constant 2147483647 : i32
    %r = arith.remsi %i32, %c3 : i32
    %is0 = arith.cmpi eq, %r, %c0 : i32
    %is1 = arith.cmpi eq, %r, %c1 : i32
    %n1 = arith.select %is1, %c1000, %cmax : i32
    %n = arith.select %is0, %c5, %n1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %d = arith.subf %y, %x : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %x1 = math.fma %h, %d, %x : f32
    sim.yield %x1 : f32
  }

  sim.component @Sub writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %mode = sim.get_param @mode : i32
    %i32 = arith.index_cast %i : index to i32
    %c32 = arith.constant 32 : i32
    %c1 = arith.constant 1 : i32
    %c2 = arith.constant 2 : i32
    %c0 = arith.constant 0 : i32
    %cm7 = arith.constant -7 : i32
    %c1000 = arith.constant 1000 : i32
    %cmin = arith.constant -2147483648 : i32
    %g = arith.divsi %i32, %c32 : i32
    %is0 = arith.cmpi eq, %g, %c0 : i32
    %is1 = arith.cmpi eq, %g, %c1 : i32
    %is2 = arith.cmpi eq, %g, %c2 : i32
    %n2 = arith.select %is2, %c1000, %cmin : i32
    %n1 = arith.select %is1, %cm7, %n2 : i32
    %n = arith.select %is0, %c0, %n1 : i32
    %big = arith.cmpi ne, %mode, %c0 : i32
    %nb = arith.select %big, %c1000, %n : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %nb : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %gx = math.cos %x : f32
    %d = arith.subf %gx, %y : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %y1 = math.fma %h, %d, %y : f32
    sim.yield %y1 : f32
  }

  sim.component @Grid writes(@G) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %mode = sim.get_param @mode : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %c7 = arith.constant 7 : i32
    %cmax = arith.constant 2147483647 : i32
    %r = arith.remsi %i32, %c2 : i32
    %odd = arith.cmpi ne, %r, %c0 : i32
    %n = arith.select %odd, %c7, %c0 : i32
    %big = arith.cmpi ne, %mode, %c0 : i32
    %nb = arith.select %big, %cmax, %n : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %nb : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %g = sim.read @G[%i] : f32
    %gl = sim.read @G[%l] : f32
    %y = sim.read @Y[%i] : f32
    %d0 = arith.subf %gl, %g : f32
    %d = arith.addf %d0, %y : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %g1 = math.fma %h, %d, %g : f32
    sim.yield %g1 : f32
  }

  sim.schedule [@Bound, @Sub, @Grid]
  sim.observe [@X, @Y, @G]
}
