// One stiff item that moves: at base step t, item (t * @stride) mod range
// takes 1 base step and every other item 8, except at base steps 4, 9, 14, ...,
// where no item is stiff. Under hip and traditional the estimate of
// the next big step looks for the item at 1 starting where it found it last
// (clock slot 7, CPU only): that group holds no 1 any more, so the estimate
// must go round every group of every invocation to find the new one (and
// every group in the steps without one). For estimate-hint.test.
sim.simulation @moving_stiff_item range(1000) dt(1.0e-2 : f64) max_steps(8) {
  sim.param @stride = 379 : i64

  sim.buffer @U : f64 init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f64
    %s = arith.constant 1.0e-3 : f64
    %u = arith.mulf %f, %s : f64
    sim.yield %u : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f64
    sim.yield %z : f64
  }

  // Reads @V through the back edge: its num_steps bounds the big step.
  sim.component @Decay writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %stride = sim.get_param @stride : i64
    %range = sim.get_param @range : i64
    %p = arith.muli %t, %stride : i64
    %stiffItem = arith.remsi %p, %range : i64
    %c5 = arith.constant 5 : i64
    %phase = arith.remsi %t, %c5 : i64
    %c4 = arith.constant 4 : i64
    %quiet = arith.cmpi eq, %phase, %c4 : i64
    %here = arith.cmpi eq, %i64, %stiffItem : i64
    %true = arith.constant true
    %notQuiet = arith.xori %quiet, %true : i1
    %stiff = arith.andi %here, %notQuiet : i1
    %n1 = arith.constant 1 : i32
    %n8 = arith.constant 8 : i32
    %n = arith.select %stiff, %n1, %n8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %d = arith.mulf %h, %v : f64
    %u1 = arith.subf %u, %d : f64
    sim.yield %u1 : f64
  }

  sim.component @Relax writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %u = sim.read @U[%i] : f64
    %v = sim.read @V[%i] : f64
    %half = arith.constant 5.0e-1 : f64
    %s = arith.addf %u, %v : f64
    %w = arith.mulf %half, %s : f64
    sim.yield %w : f64
  }
  sim.schedule [@Decay, @Relax]
  sim.observe [@U, @V]
}
