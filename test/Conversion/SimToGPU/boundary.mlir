// Reads outside [0, range) follow the read buffer's boundary rule, the same
// on every backend; a read at the own item needs no rule.
//
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu | FileCheck %s

sim.simulation @edges range(10) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @C : f32 boundary(clamp) init {
  ^bb0(%i: index):
    %v = arith.constant 1.0 : f32
    sim.yield %v : f32
  }
  sim.buffer @W : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %v = arith.constant 2.0 : f32
    sim.yield %v : f32
  }
  sim.buffer @Z : vector<4xf32> boundary(zero) init {
  ^bb0(%i: index):
    %v = arith.constant dense<3.0> : vector<4xf32>
    sim.yield %v : vector<4xf32>
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %v = arith.constant 0.0 : f32
    sim.yield %v : f32
  }
  sim.component @Sum writes(@S) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c2 = arith.constant 2 : index
    %j = arith.addi %i, %c2 : index
    %c = sim.read @C[%j] : f32
    %w = sim.read @W[%j] : f32
    %z = sim.read @Z[%j] : vector<4xf32>
    %s = sim.read @S[%i] : f32
    %e = vector.extract %z[0] : f32 from vector<4xf32>
    %a = arith.addf %c, %w : f32
    %b = arith.addf %a, %e : f32
    %r = arith.addf %b, %s : f32
    sim.yield %r : f32
  }
  sim.component @KeepC writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = sim.read @C[%i] : f32
    sim.yield %c : f32
  }
  sim.component @KeepW writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %w = sim.read @W[%i] : f32
    sim.yield %w : f32
  }
  sim.component @KeepZ writes(@Z) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %z = sim.read @Z[%i] : vector<4xf32>
    sim.yield %z : vector<4xf32>
  }
  sim.schedule [@KeepC, @KeepW, @KeepZ, @Sum]
  sim.observe [@S]
}

// CHECK-LABEL: gpu.func @evaluate_Sum(
// CHECK-SAME:      %{{[^:]*}}: memref<?xi64>, %[[C:[^:]*]]: memref<?xf32>, %[[W:[^:]*]]: memref<?xf32>, %[[Z:[^:]*]]: memref<?xvector<4xf32>>, %[[S:[^:]*]]: memref<?xf32>, %[[RANGE:[^:]*]]: i64) kernel
// CHECK:         %[[N:.*]] = arith.index_cast %[[RANGE]] : i64 to index
// CHECK:         %[[J:.*]] = arith.addi %[[I:.*]], %c2{{(_[0-9]+)?}} : index
//                clamp
// CHECK:         %[[LAST:.*]] = arith.subi %[[N]], %c1
// CHECK:         %[[LOW:.*]] = arith.maxsi %[[J]], %c0
// CHECK:         %[[CJ:.*]] = arith.minsi %[[LOW]], %[[LAST]]
// CHECK:         memref.load %[[C]][%{{.*}}]
//                wrap: a remainder only outside the range
// CHECK:         %[[INSIDE:.*]] = arith.cmpi ult, %[[J]], %[[N]]
// CHECK-NEXT:    %[[WJ:.*]] = scf.if %[[INSIDE]] -> (index) {
// CHECK-NEXT:      scf.yield %[[J]] : index
// CHECK-NEXT:    } else {
// CHECK-NEXT:      %[[REM:.*]] = arith.remsi %[[J]], %[[N]]
// CHECK-NEXT:      %[[NEG:.*]] = arith.cmpi slt, %[[REM]], %c0
// CHECK-NEXT:      %[[UP:.*]] = arith.addi %[[REM]], %[[N]]
// CHECK-NEXT:      %[[WRAPPED:.*]] = arith.select %[[NEG]], %[[UP]], %[[REM]]
// CHECK-NEXT:      scf.yield %[[WRAPPED]] : index
// CHECK-NEXT:    }
// CHECK-NEXT:    %[[WAT:.*]] = arith.addi %{{.*}}, %[[WJ]] : index
// CHECK-NEXT:    memref.load %[[W]][%[[WAT]]]
//                zero: one unsigned compare, a safe index, then the zero
// CHECK:         %[[IN:.*]] = arith.cmpi ult, %[[J]], %[[N]]
// CHECK:         arith.select %[[IN]], %[[J]], %c0
// CHECK:         %[[ZV:.*]] = memref.load %[[Z]][%{{.*}}] : memref<?xvector<4xf32>>
// CHECK:         %[[ZERO:.*]] = arith.constant dense<0.000000e+00> : vector<4xf32>
// CHECK:         arith.select %[[IN]], %[[ZV]], %[[ZERO]] : vector<4xf32>
//                own item: no rule
// CHECK:         %[[OWN:.*]] = arith.addi %{{.*}}, %[[I]] : index
// CHECK-NEXT:    memref.load %[[S]][%[[OWN]]]
