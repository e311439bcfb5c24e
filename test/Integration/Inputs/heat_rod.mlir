// heat_rod: the rod of docs/Model.md with a heater on a timer (f32).
//
// @Heater sets the heat input @Q of each item from the rod's temperature @T
// of the previous step (a back edge), but only while the heater is on: 37
// base steps of every 74, by its local base step %t. It needs small steps
// where the rod is cold, so under traditional and hip the big steps follow
// the state and the time. @Rod relaxes @T towards the mean heat input
// around each item. @Energy, the heat in the rod, is the sum of @T.
//
// A run that is given the buffers of a later time but not the clock starts
// the timer over at base step 0 and ends with another energy; a restart
// from a checkpoint continues the timer (test/Integration/checkpoint.test).
sim.simulation @heat_rod range(512) dt(1.0e-3 : f32) max_steps(4) {
  // How fast the rod follows its heat input (per time unit).
  sim.param @k = 20.0 : f32

  sim.buffer @Q : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @T : f32 boundary(clamp) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    %scale = arith.constant 1.0e-3 : f32
    %t0 = arith.mulf %x, %scale : f32
    sim.yield %t0 : f32
  }

  sim.component @Heater writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %temp = sim.read @T[%i] : f32
    %cool = arith.constant 0.3 : f32
    %cold = arith.cmpf olt, %temp, %cool : f32
    %one = arith.constant 1 : i32
    %four = arith.constant 4 : i32
    %n = arith.select %cold, %one, %four : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %temp = sim.read @T[%i] : f32
    %c37 = arith.constant 37 : i64
    %c2 = arith.constant 2 : i64
    %c0 = arith.constant 0 : i64
    %period = arith.divsi %t, %c37 : i64
    %half = arith.remsi %period, %c2 : i64
    %on = arith.cmpi eq, %half, %c0 : i64
    %one = arith.constant 1.0 : f32
    %q = arith.subf %one, %temp : f32
    %zero = arith.constant 0.0 : f32
    %heat = arith.select %on, %q, %zero : f32
    sim.yield %heat : f32
  }

  sim.component @Rod writes(@T) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %step = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %j = %lo to %hi step %step iter_args(%acc = %zero) -> (f32) {
      %at = arith.addi %i, %j : index
      %q = sim.read @Q[%at] : f32
      %next = arith.addf %acc, %q : f32
      scf.yield %next : f32
    }
    %third = arith.constant 0.333333343 : f32
    %mean = arith.mulf %sum, %third : f32
    %temp = sim.read @T[%i] : f32
    %k = sim.get_param @k : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %kh = arith.mulf %k, %h : f32
    %diff = arith.subf %mean, %temp : f32
    %change = arith.mulf %kh, %diff : f32
    %next = arith.addf %temp, %change : f32
    sim.yield %next : f32
  }

  sim.total @Energy : f64 {
  ^bb0(%i: index):
    %temp = sim.read @T[%i] : f32
    %wide = arith.extf %temp : f32 to f64
    sim.yield %wide : f64
  }

  sim.schedule [@Heater, @Rod]
  sim.observe [@T]
}
