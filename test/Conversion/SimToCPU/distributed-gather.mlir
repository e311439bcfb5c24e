// A distributed plan's replicated buffer (a gather reads it): every rank
// holds all of it, so the kernels address it as on one process (item i at
// element i, halves `range` apart, the boundary rule on every read of
// another item) while the buffers with ghost items keep the block's
// addressing; its writer's launch records the exchange of the half it
// writes (an all-gather of every rank's block of the target half).
//
// RUN: sim-opt %s --sim-front-end="strategy=simple distributed=true" --sim-lower-to-cpu 2>/dev/null | FileCheck %s

sim.simulation @pairs range(100) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Move writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.component @Pick writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c7 = arith.constant 7 : index
    %j = arith.muli %i, %c7 : index
    %x = sim.read @X[%j] : f32
    %y = sim.read @Y[%i] : f32
    %s = arith.addf %x, %y : f32
    sim.yield %s : f32
  }
  sim.schedule [@Move, @Pick]
  sim.observe [@Y]
}

// @Move writes the source half's item of @X at parity * range + item: no
// first item, no halo.
// CHECK-LABEL: func.func @evaluate_Move(
// CHECK-SAME:      %{{.*}}: memref<?xi64>, %[[X:[a-z0-9]*]]: memref<?xf32>, %[[RANGE:[a-z0-9]*]]: i64,
// CHECK:         %[[RANGEI:.*]] = arith.index_cast %[[RANGE]] : i64 to index
// CHECK:         %[[HALF:.*]] = arith.muli %{{.*}}, %[[RANGEI]] : index
// CHECK:         %[[AT:.*]] = arith.addi %[[HALF]], %[[ITEM:.*]] : index
// CHECK:         memref.load %[[X]][%[[AT]]]
// CHECK:         memref.store %{{.*}}, %[[X]]
//
// @Pick's gather of @X takes the boundary rule over the whole range (clamp),
// its own @Y the block's element.
// CHECK-LABEL: func.func @evaluate_Pick(
// CHECK:         arith.muli %{{.*}}, %c7
// CHECK:         arith.maxsi
// CHECK:         arith.minsi
// CHECK:         memref.load
//
// CHECK-LABEL: simplan.plan @pairs
// CHECK-SAME:      distributed halo(0) {
// CHECK:         simplan.buffer @X : f32 stride(4) replicated
// CHECK:         simplan.buffer @Y : f32 stride(4) observed{{$}}
// CHECK:         simplan.launch @pairs_kernels::@init_X items {{.*}} exchange [@X]
// CHECK:         simplan.launch @pairs_kernels::@evaluate_Move items {{.*}} for @Move exchange_targets [@X]
// CHECK:         simplan.launch @pairs_kernels::@evaluate_Pick items {{.*}} for @Pick{{$}}
