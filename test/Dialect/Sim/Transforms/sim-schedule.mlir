// RUN: sim-opt %s --split-input-file --sim-schedule | FileCheck %s

// The shape of the paper's Fig. 5: C0 reads B3 through the back edge, so
// naming C0 as the first component determines the whole order.

// CHECK-LABEL: sim.simulation @fig5_shape
// CHECK: sim.component @C4
// CHECK:   sim.read @B3[%{{.*}}] interpolate
// CHECK: sim.component @C2
// CHECK:   sim.read @B1[%{{.*}}] interpolate
// CHECK: sim.component @C0
// CHECK:   } evaluate {
// CHECK:   sim.read @B0[%{{.*}}] own
// CHECK:   sim.read @B3[%{{.*}}] back_edge
// CHECK: sim.component @C3
// CHECK:   sim.read @B2[%{{.*}}] interpolate
// CHECK: sim.component @C1
// CHECK:   sim.read @B0[%{{.*}}] interpolate
// CHECK: sim.schedule [@C0, @C1, @C2, @C3, @C4] bounded_by [@C0]
sim.simulation @fig5_shape range(16) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B2 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B3 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B4 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // Declared out of order on purpose: the order comes from the dependencies.
  sim.component @C4 writes(@B4) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B3[%i] : f32
    sim.yield %v : f32
  }
  sim.component @C2 writes(@B2) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B1[%i] : f32
    sim.yield %v : f32
  }
  sim.component @C0 writes(@B0) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %self = sim.read @B0[%i] : f32
    %v = sim.read @B3[%i] : f32
    %s = arith.addf %self, %v : f32
    sim.yield %s : f32
  }
  sim.component @C3 writes(@B3) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B2[%i] : f32
    sim.yield %v : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B0[%i] : f32
    sim.yield %v : f32
  }
  sim.schedule [@C0]
  sim.observe [@B4]
}

// -----

// Without any cycle no first component needs naming: the pass creates the
// schedule, and nothing bounds the hip step but max_steps.

// CHECK-LABEL: sim.simulation @acyclic_chain
// CHECK: sim.read @A[%{{.*}}] interpolate
// CHECK: sim.schedule [@Source, @Sink]{{$}}
sim.simulation @acyclic_chain range(16) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @A : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @B : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.component @Sink writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f64
    sim.yield %a : f64
  }
  sim.component @Source writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c = arith.constant 2.0 : f64
    sim.yield %c : f64
  }
  sim.observe [@B]
}

// -----

// A full user order that respects the dependencies is kept as given, and
// reads in num_steps get roles too.

// CHECK-LABEL: sim.simulation @user_order
// CHECK: sim.component @P writes(@X, @V) num_steps
// CHECK:   sim.read @F[%{{.*}}] back_edge
// CHECK: } evaluate {
// CHECK:   sim.read @X[%{{.*}}] own
// CHECK:   sim.read @V[%{{.*}}] own
// CHECK:   sim.read @F[%{{.*}}] back_edge
// CHECK: sim.component @Force
// CHECK:   sim.read @X[%{{.*}}] interpolate
// CHECK: sim.schedule [@P, @Force] bounded_by [@P]
sim.simulation @user_order range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @F : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @P writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %f = sim.read @F[%i] : f32
    %n = arith.fptosi %f : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %f = sim.read @F[%i] : f32
    %x1 = arith.addf %x, %v : f32
    %v1 = arith.addf %v, %f : f32
    sim.yield %x1, %v1 : f32, f32
  }
  sim.component @Force writes(@F) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@P, @Force]
  sim.observe [@X]
}

// -----

// The first component reads through the back edge but has no num_steps: it
// never bounds a step, so nothing but max_steps bounds the hip step and
// there is no bounded_by.

// CHECK-LABEL: sim.simulation @unbounded_entry
// CHECK: sim.read @B[%{{.*}}] back_edge
// CHECK: sim.schedule [@First, @Second]{{$}}
sim.simulation @unbounded_entry range(16) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @First writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %b = sim.read @B[%i] : f32
    sim.yield %b : f32
  }
  sim.component @Second writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.schedule [@First]
  sim.observe [@B]
}
