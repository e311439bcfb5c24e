// RUN: sim-opt %s --sim-schedule --sim-substep-legality --sim-plan-memory --sim-report-memory -o /dev/null 2>/dev/null | FileCheck %s --check-prefix=HIP
// RUN: sim-opt %s --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip-cache --sim-report-memory="format=json group-size=128" -o /dev/null 2>/dev/null | FileCheck %s --check-prefix=JSON

// @U (f64, 8 bytes) and @dU get snapshots because @Diffuse (grid_sync, with
// num_steps) ping-pongs through memory and @Sample interpolates @U with Hermite; @W does not.
// 100 items: halves are 2 * 100 * bytes, a snapshot 100 * bytes.

// HIP-LABEL: memory plan of @needs_snapshot (strategy hip, 100 items)
// HIP-NEXT:  buffer       element          bytes/item         halves       snapshot          total
// HIP-NEXT:  @U           f64                       8           1600            800           2400
// HIP-NEXT:  @dU          f64                       8           1600            800           2400
// HIP-NEXT:  @W           vector<4xf32>            16           3200              0           3200
// HIP-NEXT:  planned device memory                              8000 (7.81 KiB)
// HIP-NEXT:  naive plan (3 copies of every buffer)             9600 (9.38 KiB)
// HIP-NEXT:  saved                                             1600 (16.7%)
// HIP-NEXT:  shared-memory caches: none

// Under hip-cache @Sample caches @U, which it reads at i..i+1: 128 threads
// plus a halo of 1, * 8 bytes.
// JSON:      "caches": [
// JSON-NEXT:   {
// JSON-NEXT:     "bytes_per_group": 1032,
// JSON-NEXT:     "component": "Sample"
// JSON-NEXT:   }
// JSON-NEXT: ],
// JSON-NEXT: "group_size": 128,
// JSON-NEXT: "largest_cache_bytes_per_group": 1032,
// JSON-NEXT: "naive_bytes": 9600,
// JSON-NEXT: "planned_bytes": 8000,
// JSON-NEXT: "range": 100,
// JSON-NEXT: "simulation": "needs_snapshot",
// JSON-NEXT: "strategy": "hip-cache"

sim.simulation @needs_snapshot range(100) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @U : f64 interp(#sim.hermite<@dU>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @dU : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @W : vector<4xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
  sim.component @Diffuse writes(@U, @dU) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %u = sim.read @U[%i] : f64
    %ul = sim.read @U[%l] : f64
    %d = arith.subf %ul, %u : f64
    sim.yield %ul, %d : f64, f64
  }
  sim.component @Sample writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %r = arith.addi %i, %c1 : index
    %u0 = sim.read @U[%i] : f64
    %u1 = sim.read @U[%r] : f64
    %u = arith.addf %u0, %u1 : f64
    %f = arith.truncf %u : f64 to f32
    %v = vector.broadcast %f : f32 to vector<4xf32>
    %w = sim.read @W[%i] : vector<4xf32>
    %s = arith.addf %v, %w : vector<4xf32>
    sim.yield %s : vector<4xf32>
  }
  sim.schedule [@Diffuse]
  sim.observe [@W]
}
