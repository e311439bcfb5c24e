// RUN: sim-opt %s --sim-front-end --sim-lower-to-cpu=group-size=0 --verify-diagnostics -o /dev/null

// A group size below 1 is refused at the scene it would lower (it was at
// the module, which has no location in a file: "file:0:0").

// expected-error @below {{--sim-lower-to-cpu needs a positive group size, not 0}}
sim.simulation @scene range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Keep writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
