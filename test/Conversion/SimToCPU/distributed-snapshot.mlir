// The snapshot of a grid_sync component's buffer (its value at T, which
// later components interpolate) travels between ranks only when a later
// component reads it at other items: --sim-plan-halos records
// `snapshot_ghosts` on the buffer, and the snapshot launch exchanges its
// ghost items. A reader at its own item only, or the writer reading its
// own halves at other items, needs no ghost of the snapshot.
//
// RUN: sim-opt %s --split-input-file --sim-front-end="strategy=hip distributed=true" | FileCheck %s --check-prefix=HALOS
// RUN: sim-opt %s --split-input-file --sim-front-end="strategy=hip distributed=true" --sim-lower-to-cpu | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-front-end="strategy=lts distributed=true" --sim-lower-to-cpu 2>/dev/null | FileCheck %s --check-prefix=LTS

// A later reader at i+1: the snapshot's ghosts travel after it is taken.
// HALOS-LABEL: sim.simulation @window_reader
// HALOS:         sim.buffer @U : f32 attributes {halo = array<i64: 1, 1>, snapshot, snapshot_ghosts} init
// CHECK-LABEL: simplan.plan @window_reader
// CHECK:         simplan.launch @window_reader_kernels::@snapshot_U items [{{.*}}] exchange_snapshots [@U]{{$}}
// CHECK:         simplan.launch @window_reader_kernels::@substep_Diffuse items {{.*}} exchange_sub_step [@U]{{$}}
// LTS-LABEL:   simplan.plan @window_reader
// LTS:           simplan.launch @window_reader_kernels::@snapshot_U items [{{.*}}] exchange_snapshots [@U]{{$}}
sim.simulation @window_reader range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %left = sim.read @U[%l] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %left, %u : f32
    sim.yield %s : f32
  }
  sim.component @Watch writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %u = sim.read @U[%r] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Diffuse, @Watch]
  sim.observe [@W]
}

// -----

// A later reader at its own item: the snapshot stays on its rank; the
// buffer's halves still travel for the writer's own reads.
// HALOS-LABEL: sim.simulation @own_item_reader
// HALOS:         sim.buffer @U : f32 attributes {halo = array<i64: 1, 0>, snapshot} init
// CHECK-LABEL: simplan.plan @own_item_reader
// CHECK:         simplan.launch @own_item_reader_kernels::@snapshot_U items [{{.*}}]{{$}}
// CHECK:         simplan.launch @own_item_reader_kernels::@substep_Diffuse items {{.*}} exchange_sub_step [@U]{{$}}
// LTS-LABEL:   simplan.plan @own_item_reader
// LTS:           simplan.launch @own_item_reader_kernels::@snapshot_U items [{{.*}}]{{$}}
sim.simulation @own_item_reader range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %left = sim.read @U[%l] : f32
    %u = sim.read @U[%i] : f32
    %s = arith.addf %left, %u : f32
    sim.yield %s : f32
  }
  sim.component @Watch writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    sim.yield %u : f32
  }
  sim.schedule [@Diffuse, @Watch]
  sim.observe [@W]
}
