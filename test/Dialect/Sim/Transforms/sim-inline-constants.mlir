// RUN: sim-opt %s --split-input-file --pass-pipeline='builtin.module(sim.simulation(sim-inline-constants))' | FileCheck %s

// A window read of a clamp constant: its init at max(0, min(j, range - 1)),
// and the buffer is gone.

// CHECK-LABEL: sim.simulation @clamp
// CHECK-NOT: sim.buffer @K
// CHECK: sim.component @C
// CHECK: %[[J:.*]] = arith.subi %i, %{{.*}} : index
// CHECK: %[[R:.*]] = sim.get_param @range : i64
// CHECK: %[[J64:.*]] = arith.index_cast %[[J]] : index to i64
// CHECK: %[[LAST:.*]] = arith.subi %[[R]], %{{.*}} : i64
// CHECK: %[[LO:.*]] = arith.maxsi %[[J64]], %{{.*}} : i64
// CHECK: %[[M:.*]] = arith.minsi %[[LO]], %[[LAST]] : i64
// CHECK: %[[MI:.*]] = arith.index_cast %[[M]] : i64 to index
// CHECK: %[[MI64:.*]] = arith.index_cast %[[MI]] : index to i64
// CHECK: %[[K:.*]] = arith.sitofp %[[MI64]] : i64 to f32
// CHECK-NOT: arith.select
// CHECK: %[[U:.*]] = sim.read @U[%i] : f32
// CHECK: arith.addf %[[K]], %[[U]] : f32
sim.simulation @clamp range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    sim.yield %f : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %k = sim.read @K[%l] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %k, %u : f32
    sim.yield %s : f32
  }
  sim.observe [@U]
}

// -----

// wrap: the item modulo range, made non-negative. @K's init reads @Base at
// its own item, which the mapping already put inside the range: @Base's
// copy takes the mapped item as it is.

// CHECK-LABEL: sim.simulation @wrap
// CHECK: %[[R:.*]] = sim.get_param @range : i64
// CHECK: %[[J64:.*]] = arith.index_cast %{{.*}} : index to i64
// CHECK: %[[REM:.*]] = arith.remsi %[[J64]], %[[R]] : i64
// CHECK: %[[NEG:.*]] = arith.cmpi slt, %[[REM]], %{{.*}} : i64
// CHECK: %[[UP:.*]] = arith.addi %[[REM]], %[[R]] : i64
// CHECK: %[[M:.*]] = arith.select %[[NEG]], %[[UP]], %[[REM]] : i64
// CHECK: %[[MI:.*]] = arith.index_cast %[[M]] : i64 to index
// CHECK-NOT: arith.remsi
// CHECK-NOT: arith.minsi
// CHECK: %[[B64:.*]] = arith.index_cast %[[MI]] : index to i64
// CHECK: %[[B:.*]] = arith.sitofp %[[B64]] : i64 to f32
// CHECK: %[[K:.*]] = arith.addf %[[B]], %{{.*}} : f32
// CHECK: sim.yield %[[K]] : f32
sim.simulation @wrap range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @Base : f32 constant init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    sim.yield %f : f32
  }
  sim.buffer @K : f32 constant boundary(wrap) init {
  ^bb0(%i: index):
    %b = sim.read @Base[%i] : f32
    %c = arith.constant 2.5 : f32
    %k = arith.addf %b, %c : f32
    sim.yield %k : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c3 = arith.constant 3 : index
    %r = arith.addi %i, %c3 : index
    %k = sim.read @K[%r] : f32
    sim.yield %k : f32
  }
  sim.observe [@U]
}

// -----

// zero: the init at the clamped item, then a zero element where the item
// is outside the range (a vector element here).

// CHECK-LABEL: sim.simulation @zero_vector
// CHECK: %[[J64:.*]] = arith.index_cast %{{.*}} : index to i64
// CHECK: %[[M:.*]] = arith.minsi
// CHECK: %[[IN:.*]] = arith.cmpi eq, %[[J64]], %[[M]] : i64
// CHECK: %[[V:.*]] = arith.constant dense<[1.000000e+00, 2.000000e+00]> : vector<2xf64>
// CHECK: %[[Z:.*]] = arith.constant dense<0.000000e+00> : vector<2xf64>
// CHECK: %[[K:.*]] = arith.select %[[IN]], %[[V]], %[[Z]] : vector<2xf64>
// CHECK: sim.yield %[[K]] : vector<2xf64>
sim.simulation @zero_vector range(64) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @K : vector<2xf64> constant boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant dense<[1.0, 2.0]> : vector<2xf64>
    sim.yield %c : vector<2xf64>
  }
  sim.buffer @U : vector<2xf64> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf64>
    sim.yield %c : vector<2xf64>
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %k = sim.read @K[%r] : vector<2xf64>
    sim.yield %k : vector<2xf64>
  }
  sim.observe [@U]
}

// -----

// Reads inside a copied init see initial states: @K's read of @U becomes
// @U's init, and @W's read of @K at its own item needs no boundary rule
// again. Reads in num_steps, total, exact and another buffer's init are
// replaced the same way; all of them read at the body's own item %i, so no
// boundary rule is computed at all.

// CHECK-LABEL: sim.simulation @initial_states
// CHECK-NOT: sim.buffer @K
// CHECK-NOT: sim.buffer @W
// CHECK-NOT: sim.get_param @range
// CHECK: sim.buffer @V : f32 init {
// CHECK-NEXT: ^bb0(%i: index):
// CHECK-NEXT: %[[V0:.*]] = arith.constant 3.000000e+00 : f32
// CHECK-NEXT: sim.yield %[[V0]] : f32
// CHECK-NEXT: } exact {
// CHECK-NEXT: ^bb0(%i: index, %t: f64):
// CHECK-NEXT: %[[E0:.*]] = arith.constant 3.000000e+00 : f32
// CHECK-NEXT: sim.yield %[[E0]] : f32
// CHECK: sim.component @C writes(@U, @V) num_steps {
// CHECK-NEXT: ^bb0(%i: index, %t: i64):
// CHECK-NEXT: %[[N0:.*]] = arith.constant 3.000000e+00 : f32
// CHECK-NEXT: arith.fptosi %[[N0]] : f32 to i32
// CHECK: } evaluate {
// CHECK-NEXT: ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
// CHECK-NEXT: %[[U0:.*]] = arith.constant 3.000000e+00 : f32
// CHECK-NEXT: %[[W:.*]] = arith.mulf %[[U0]], %[[U0]] : f32
// CHECK-NEXT: %[[U:.*]] = sim.read @U[%i] : f32
// CHECK-NEXT: sim.yield %[[U]], %[[W]] : f32, f32
// CHECK: sim.total @Sum : f32 {
// CHECK-NOT: sim.read @W
// CHECK: sim.read @U[%i]
// CHECK-NOT: sim.get_param @range
sim.simulation @initial_states range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @W : f32 constant init {
  ^bb0(%i: index):
    %k = sim.read @K[%i] : f32
    %s = arith.mulf %k, %k : f32
    sim.yield %s : f32
  }
  sim.buffer @K : f32 constant init {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 3.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %k = sim.read @K[%i] : f32
    sim.yield %k : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %k = sim.read @K[%i] : f32
    sim.yield %k : f32
  }
  sim.component @C writes(@U, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %k = sim.read @K[%i] : f32
    %n = arith.fptosi %k : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %w = sim.read @W[%i] : f32
    %u = sim.read @U[%i] : f32
    sim.yield %u, %w : f32, f32
  }
  sim.total @Sum : f32 {
  ^bb0(%i: index):
    %w = sim.read @W[%i] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %u, %w : f32
    sim.yield %s : f32
  }
  sim.observe [@V]
}

// -----

// Nothing constant: the simulation is left as it is.

// CHECK-LABEL: sim.simulation @none
// CHECK: sim.buffer @U : f32 init
// CHECK: sim.read @U[%i]
sim.simulation @none range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.observe [@U]
}
