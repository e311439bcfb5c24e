// Init and exact bodies become kernels. Their reads see initial states: the
// read buffer's init body is inlined at the read item, under its boundary
// rule, so no init kernel depends on another.
//
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s

sim.simulation @osc range(64) dt(1.0e-2 : f64) max_steps(2) {
  sim.param @omega = 3.0 : f64
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f64
    sim.yield %x : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %x0 = sim.read @X[%j] : f64
    %w = sim.get_param @omega : f64
    %wt = arith.mulf %w, %t : f64
    %c = math.cos %wt : f64
    %x = arith.mulf %x0, %c : f64
    sim.yield %x : f64
  }
  sim.buffer @Y : f64 boundary(zero) init {
  ^bb0(%i: index):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %x = sim.read @X[%j] : f64
    sim.yield %x : f64
  }
  sim.component @Move writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.component @Copy writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.schedule [@Move]
  sim.observe [@X, @Y]
}

// CHECK-LABEL: gpu.func @init_X(
// CHECK-SAME:      %[[X:.*]]: memref<?xf64>, %{{.*}}: i64) kernel
// CHECK:         memref.store %{{.*}}, %[[X]][%[[I:.*]]] : memref<?xf64>

// @Y's init reads @X[i - 1] under @X's boundary rule (clamp): @X's init
// body runs at the clamped item; no load of @X.
// CHECK-LABEL: gpu.func @init_Y(
// CHECK-SAME:      %[[Y:[^:]*]]: memref<?xf64>, %{{.*}}: i64) kernel
// CHECK:         %[[J:.*]] = arith.subi %{{.*}}, %c1 : index
// CHECK:         %[[LOW:.*]] = arith.maxsi %[[J]], %c0
// CHECK:         %[[CLAMPED:.*]] = arith.minsi %[[LOW]], %{{.*}}
// CHECK:         %[[CAST:.*]] = arith.index_cast %[[CLAMPED]] : index to i32
// CHECK:         %[[VALUE:.*]] = arith.sitofp %[[CAST]] : i32 to f64
// CHECK:         memref.store %[[VALUE]], %[[Y]]

// The exact solution writes its own output at the launch's time.
// CHECK-LABEL: gpu.func @exact_X(
// CHECK-SAME:      %[[OUT:[^:]*]]: memref<?xf64>, %[[OMEGA:[^:]*]]: f64, %{{.*}}: i64, %[[TIME:[^:]*]]: f64) kernel
// CHECK:         %[[WT:.*]] = arith.mulf %[[OMEGA]], %[[TIME]] : f64
// CHECK:         math.cos %[[WT]]
// CHECK:         memref.store %{{.*}}, %[[OUT]]

// CHECK-LABEL: simplan.plan @osc strategy("hip") kernels(@osc_kernels) range(64) dt(1.000000e-02 : f64)
// CHECK:         simplan.buffer @X : f64 stride(8) observed exact
// CHECK:         simplan.buffer @Y : f64 stride(8) observed{{$}}
// CHECK:         simplan.phase exact {
// CHECK-NEXT:      simplan.launch @osc_kernels::@exact_X items [#simplan.arg<exact @X>, #simplan.arg<param @omega>, #simplan.arg<range>, #simplan.arg<time>]
