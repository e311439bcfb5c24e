// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory="strategy=hip-cache group-size=1024" --verify-diagnostics | FileCheck %s

// hip-cache keeps a group's caches in shared memory, (group + halo)
// elements each: no GPU gives a group more than 227 KiB. A window of 800
// around a group of 1024 vector<16xf64> values (128 bytes each) would take
// 233472 bytes: no cache, a remark, reads from global memory as under hip.

// CHECK-LABEL: sim.simulation @wide_cache
// CHECK:       sim.component @Max
// CHECK-NOT:   caches
// CHECK-SAME:  evaluate
sim.simulation @wide_cache range(4096) dt(1.0e-3 : f64) max_steps(4) {
  sim.buffer @W : vector<16xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<1.0> : vector<16xf64>
    sim.yield %z : vector<16xf64>
  }
  sim.buffer @M : vector<16xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<16xf64>
    sim.yield %z : vector<16xf64>
  }
  sim.component @Grow writes(@W) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 4 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %w = sim.read @W[%i] : vector<16xf64>
    sim.yield %w : vector<16xf64>
  }
  // expected-remark @+1 {{under hip-cache @Max keeps no cache of @W: it would take 233472 bytes of shared memory in a group of 1024, more than the 232448 any GPU gives a group; its reads interpolate from global memory as under hip (a smaller group size or a narrower window lets it cache)}}
  sim.component @Max writes(@M) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %lo = arith.constant -400 : index
    %hi = arith.constant 401 : index
    %st = arith.constant 1 : index
    %z = arith.constant dense<0.0> : vector<16xf64>
    %m = scf.for %k = %lo to %hi step %st iter_args(%acc = %z) -> (vector<16xf64>) {
      %j = arith.addi %i, %k : index
      %w = sim.read @W[%j] : vector<16xf64>
      %nx = arith.maximumf %acc, %w : vector<16xf64>
      scf.yield %nx : vector<16xf64>
    }
    sim.yield %m : vector<16xf64>
  }
  sim.schedule [@Grow, @Max]
  sim.observe [@M]
}

// -----

// A window of 600 fits: (1024 + 600) * 128 = 207872 bytes.
// CHECK-LABEL: sim.simulation @narrower_cache
// CHECK:       sim.component @Max
// CHECK-SAME:  caches = [#sim.cache<@W, -300, 300>]
sim.simulation @narrower_cache range(4096) dt(1.0e-3 : f64) max_steps(4) {
  sim.buffer @W : vector<16xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<1.0> : vector<16xf64>
    sim.yield %z : vector<16xf64>
  }
  sim.buffer @M : vector<16xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<16xf64>
    sim.yield %z : vector<16xf64>
  }
  sim.component @Grow writes(@W) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 4 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %w = sim.read @W[%i] : vector<16xf64>
    sim.yield %w : vector<16xf64>
  }
  sim.component @Max writes(@M) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %lo = arith.constant -300 : index
    %hi = arith.constant 301 : index
    %st = arith.constant 1 : index
    %z = arith.constant dense<0.0> : vector<16xf64>
    %m = scf.for %k = %lo to %hi step %st iter_args(%acc = %z) -> (vector<16xf64>) {
      %j = arith.addi %i, %k : index
      %w = sim.read @W[%j] : vector<16xf64>
      %nx = arith.maximumf %acc, %w : vector<16xf64>
      scf.yield %nx : vector<16xf64>
    }
    sim.yield %m : vector<16xf64>
  }
  sim.schedule [@Grow, @Max]
  sim.observe [@M]
}
