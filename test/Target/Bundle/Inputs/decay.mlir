// A small scene without math functions: its PTX needs no libdevice.
sim.simulation @decay range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.param @rate = 5.0e-1 : f32
  sim.param @steps = 2 : i32
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.component @Decay writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %steps = sim.get_param @steps : i32
    sim.yield %steps : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %rate = sim.get_param @rate : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %rh = arith.mulf %rate, %h : f32
    %dx = arith.mulf %rh, %x : f32
    %x1 = arith.subf %x, %dx : f32
    sim.yield %x1 : f32
  }
  sim.observe [@X]
}
