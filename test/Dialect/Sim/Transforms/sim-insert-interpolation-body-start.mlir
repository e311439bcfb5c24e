// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory --sim-insert-interpolation 2>/dev/null | FileCheck %s --check-prefix=HIP
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=hip-cache --sim-insert-interpolation 2>/dev/null | FileCheck %s --check-prefix=CACHE

// A body whose first op is a read: the pass replaces (and erases) that read,
// so what it builds later at the body's start (the time values of a second
// scalar type, a second cache's fill) goes after what it built before, not
// before the erased read. Before, it was built against the freed op: the
// f64 fraction failed with "operation's operand is unlinked", and a fill
// landed inside another read's interpolation.

// HIP-LABEL: sim.simulation @reads_first
// HIP: sim.component @CB
// HIP: sim.big_step
// HIP: %[[F32:.*]] = arith.divf %{{.*}}, %{{.*}} : f32
// HIP: %[[F64:.*]] = arith.divf %{{.*}}, %{{.*}} : f64
// HIP: scf.if
// HIP: arith.mulf %[[F32]], %{{.*}} : f32
// HIP: scf.if
// HIP: arith.mulf %[[F64]], %{{.*}} : f64
sim.simulation @reads_first range(31) dt(1.0e-3 : f64) max_steps(8) {
  sim.buffer @A : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @V : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.component @CV writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @V[%i] : f64
    sim.yield %a : f64
  }
  sim.component @CB writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f32
    %v = sim.read @V[%i] : f64
    %g = arith.truncf %v : f64 to f32
    %s = arith.addf %a, %g : f32
    sim.yield %s : f32
  }
  sim.schedule [@CA, @CV, @CB]
  sim.observe [@B]
}

// -----

// hip-cache: @A's gather is interpolated in place (no cache), then @V's
// window reads fill a cache at the body's start, after the time values.

// CACHE-LABEL: sim.simulation @gather_then_cache
// CACHE: sim.component @CB
// CACHE: evaluate
// CACHE: sim.big_step
// CACHE: arith.divf
// CACHE-NOT: scf.if
// CACHE: sim.fill_cache @V window(0, 1)
sim.simulation @gather_then_cache range(64) dt(1.0e-3 : f32) max_steps(8) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.component @CA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.component @CV writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @V[%i] : f32
    sim.yield %a : f32
  }
  sim.component @CB writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    %c7 = arith.constant 7 : index
    %g = arith.muli %i, %c7 : index
    %a1 = sim.read @A[%g] : f32
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %v = sim.read @V[%j] : f32
    %v1 = sim.read @V[%i] : f32
    %s = arith.addf %a, %v : f32
    %s1 = arith.addf %a1, %v1 : f32
    %s2 = arith.addf %s, %s1 : f32
    sim.yield %s2 : f32
  }
  sim.schedule [@CA, @CV, @CB]
  sim.observe [@B]
}
