// Under hip-cache, a component's recorded cache (#sim.cache in `caches`)
// becomes one sim.fill_cache at the start of evaluate, whose region is the
// interpolation at any item, and its reads of the buffer load the cache.
// num_steps reads at another local time and keeps the explicit arithmetic.
// Under hip nothing is cached.
//
// A cache load whose index the dependency analysis places inside the fill's
// window is marked in_window (the lowerings load it without a check); a
// gather's is not.
//
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=hip-cache | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=hip-cache | sim-opt --split-input-file | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-front-end=strategy=hip | FileCheck %s --check-prefix=HIP

sim.simulation @smooth range(10) dt(1.0e-1 : f32) max_steps(4) {
  sim.param @lead = 3 : i32
  sim.buffer @U : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Drive writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = sim.get_param @lead : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %s = sim.read @S[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %d = arith.mulf %h, %s : f32
    %next = arith.addf %u, %d : f32
    sim.yield %next : f32
  }
  sim.component @Smooth writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      %u = sim.read @U[%j] : f32
      %next = arith.addf %acc, %u : f32
      scf.yield %next : f32
    }
    %s = sim.read @S[%i] : f32
    %avg = arith.addf %sum, %s : f32
    sim.yield %avg : f32
  }
  sim.schedule [@Drive]
  sim.observe [@S]
}

// CHECK-LABEL: sim.component @Smooth
// CHECK-SAME:      caches = [#sim.cache<@U, -1, 1>]
// CHECK:         evaluate {
// CHECK:           %[[BEGIN:.*]], %[[SIZE:.*]] = sim.big_step
// CHECK:           %[[F:.*]] = arith.divf
// CHECK:           sim.fill_cache @U window(-1, 1) {
// CHECK-NEXT:      ^bb0(%[[K:.*]]: index):
// CHECK-NEXT:        scf.if
// CHECK-NEXT:          sim.load target @U[%[[K]]] : f32
// CHECK:             } else {
// CHECK:             } else {
// CHECK-NEXT:        %[[A:.*]] = sim.load source @U[%[[K]]] : f32
// CHECK-NEXT:        %[[B:.*]] = sim.load target @U[%[[K]]] : f32
// CHECK:             arith.subf %{{.*}}, %[[F]]
// CHECK:             sim.yield
// CHECK-NEXT:      }
// CHECK:           scf.for
// CHECK:             sim.load cache @U[%{{.*}}] in_window : f32
// CHECK-NOT:       sim.load source @U
// CHECK:           sim.load local @S

// HIP-NOT: sim.fill_cache
// HIP-NOT: sim.load cache

// -----

// A neighbour read through an index clamped around the item is inside the
// window whatever the unclamped index is; a read at a parameter's distance
// is a gather, checked against the cache at run time.
sim.simulation @clamped range(16) dt(1.0e-1 : f32) max_steps(4) {
  sim.param @lead = 3 : i64
  sim.buffer @U : f32 boundary(clamp) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Drive writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = arith.constant 4 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %next = arith.addf %u, %dt : f32
    sim.yield %next : f32
  }
  sim.component @Pull writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %one = arith.constant 1 : index
    %lead = sim.get_param @lead : i64
    %lead_index = arith.index_cast %lead : i64 to index
    %far = arith.addi %i, %lead_index : index
    %below = arith.subi %i, %one : index
    %above = arith.addi %i, %one : index
    %low = arith.maxsi %far, %below : index
    %partner = arith.minsi %low, %above : index
    %u_partner = sim.read @U[%partner] : f32
    %u_left = sim.read @U[%below] : f32
    %u_far = sim.read @U[%far] : f32
    %a = arith.addf %u_partner, %u_left : f32
    %b = arith.addf %a, %u_far : f32
    sim.yield %b : f32
  }
  sim.schedule [@Drive]
  sim.observe [@S]
}

// CHECK-LABEL: sim.component @Pull
// CHECK-SAME:      caches = [#sim.cache<@U, -1, 1>]
// CHECK:         sim.fill_cache @U window(-1, 1) {
// CHECK:         %[[FAR:.*]] = arith.addi %{{.*}}, %{{.*}} : index
// CHECK:         %[[PARTNER:.*]] = arith.minsi
// CHECK-NEXT:    sim.load cache @U[%[[PARTNER]]] in_window : f32
// CHECK-NEXT:    sim.load cache @U[%{{.*}}] in_window : f32
// CHECK-NEXT:    sim.load cache @U[%[[FAR]]] : f32
