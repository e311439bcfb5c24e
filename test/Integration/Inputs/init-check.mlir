// Balls falling at speed 1 onto the ground at y = 0, where they stop, and
// their shadows at half their height. Item i starts at y = 0.01 i, except
// item 3, which starts @below the ground: its init says -@below, but @Fall
// puts it on the ground in its first evaluation, even with n = 0. @Shadow
// reads @Y after @Fall, so under hip it interpolates @Y from that init in
// the first big step, and the shadow of item 3 goes where the ball never
// was. sim-run's init check finds it (test/Integration/init-check.test).
sim.simulation @drop range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.param @below = 0.0 : f32

  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %cm = arith.constant 1.0e-2 : f32
    %y = arith.mulf %f, %cm : f32
    %below = sim.get_param @below : f32
    %under = arith.negf %below : f32
    %c3 = arith.constant 3 : index
    %is3 = arith.cmpi eq, %i, %c3 : index
    %y0 = arith.select %is3, %under, %y : f32
    sim.yield %y0 : f32
  }
  // Consistent: half of the initial height, whatever it is.
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %y = sim.read @Y[%i] : f32
    %half = arith.constant 5.0e-1 : f32
    %s = arith.mulf %y, %half : f32
    sim.yield %s : f32
  }

  sim.component @Fall writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %y = sim.read @Y[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %y1 = arith.subf %y, %h : f32
    %ground = arith.constant 0.0 : f32
    %y2 = arith.maximumf %y1, %ground : f32
    sim.yield %y2 : f32
  }
  sim.component @Shadow writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %y = sim.read @Y[%i] : f32
    %half = arith.constant 5.0e-1 : f32
    %s = arith.mulf %y, %half : f32
    sim.yield %s : f32
  }
  sim.observe [@S]
}
