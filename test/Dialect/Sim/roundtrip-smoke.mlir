// RUN: sim-opt %s | sim-opt | FileCheck %s
// RUN: sim-opt %s --mlir-print-op-generic | sim-opt | FileCheck %s

// CHECK-LABEL: sim.simulation @decay range(1024)
sim.simulation @decay range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.param @k = 2.5 : f32
  sim.buffer @X : f32 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %x = math.cos %t : f64
    %y = arith.truncf %x : f64 to f32
    sim.yield %y : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.component @Decay writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] own : f32
    %k = sim.get_param @k : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %dx = arith.mulf %h, %x : f32
    %next = arith.subf %x, %dx : f32
    %T, %m = sim.big_step : i64, i64
    %l = sim.load local @X[%i] : f32
    sim.yield %next, %l : f32, f32
  }
  sim.schedule [@Decay]
  sim.observe [@X]
}
