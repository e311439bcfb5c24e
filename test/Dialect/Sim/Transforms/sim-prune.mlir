// RUN: sim-opt %s --split-input-file --sim-prune --verify-diagnostics | FileCheck %s

// @Debug and its buffer feed nothing observed; @Integrate is kept for @X but
// its @Energy output is not needed. @F is needed across the back edge, and
// @Mass only through @F.

// CHECK-LABEL: sim.simulation @scene
// CHECK-NOT: @Debug
// CHECK-NOT: sim.buffer @D
// CHECK-NOT: sim.buffer @Energy
// CHECK: sim.buffer @X
// CHECK: sim.buffer @F
// CHECK: sim.buffer @Mass
// CHECK: sim.component @Integrate writes(@X) evaluate
// CHECK-NOT: arith.mulf
// CHECK: sim.yield %{{.*}} : f32
// CHECK: sim.component @Force writes(@F)
// CHECK: sim.component @Weigh writes(@Mass)
// CHECK: sim.schedule [@Integrate, @Force]
// CHECK: sim.observe [@X]
sim.simulation @scene range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @Energy: no observed buffer depends on it}}
  sim.buffer @Energy : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @F : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Mass : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @D: no observed buffer depends on it}}
  sim.buffer @D : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@Integrate no longer writes @Energy: no observed buffer depends on it}}
  sim.component @Integrate writes(@X, @Energy) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %f = sim.read @F[%i] : f32
    %x1 = arith.addf %x, %f : f32
    %e = arith.mulf %x1, %x1 : f32
    sim.yield %x1, %e : f32, f32
  }
  sim.component @Force writes(@F) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %m = sim.read @Mass[%i] : f32
    %f = arith.mulf %x, %m : f32
    sim.yield %f : f32
  }
  sim.component @Weigh writes(@Mass) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %m = sim.read @Mass[%i] : f32
    sim.yield %m : f32
  }
  // expected-remark @+1 {{removed component @Debug: no observed buffer depends on it}}
  sim.component @Debug writes(@D) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %e = sim.read @Energy[%i] : f32
    %s = arith.addf %x, %e : f32
    sim.yield %s : f32
  }
  sim.schedule [@Integrate, @Force, @Debug]
  sim.observe [@X]
}

// -----

// The derivative buffer of a needed buffer's Hermite interpolation stays,
// and so does what a needed init body reads; a read only in num_steps keeps
// its buffer too.

// CHECK-LABEL: sim.simulation @keeps_aux
// CHECK: sim.buffer @X
// CHECK: sim.buffer @V
// CHECK: sim.buffer @Seed
// CHECK: sim.buffer @Limit
// CHECK: sim.component @Move writes(@X, @V)
// CHECK: sim.component @Seeder writes(@Seed)
// CHECK: sim.component @Limiter writes(@Limit)
sim.simulation @keeps_aux range(16) dt(1.0e-2 : f64) max_steps(2) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %s = sim.read @Seed[%i] : f64
    sim.yield %s : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @Seed : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @Limit : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 3.0 : f64
    sim.yield %c : f64
  }
  sim.component @Move writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %l = sim.read @Limit[%i] : f64
    %n = arith.fptosi %l : f64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %c = arith.constant 1.0 : f64
    sim.yield %x, %c : f64, f64
  }
  sim.component @Seeder writes(@Seed) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %s = sim.read @Seed[%i] : f64
    sim.yield %s : f64
  }
  sim.component @Limiter writes(@Limit) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %l = sim.read @Limit[%i] : f64
    sim.yield %l : f64
  }
  sim.observe [@X]
}

// -----

// An unused read of a buffer nothing observed needs: @Aux and its writer
// go, and the read goes with them (it would otherwise name a buffer that is
// gone). So do reads whose values only feed dead code, and a loop whose
// results nothing uses. Reads of needed buffers stay.

// CHECK-LABEL: sim.simulation @unused_reads
// CHECK-NOT:     @Aux
// CHECK-NOT:     @WriteAux
// CHECK:         sim.component @C writes(@X) evaluate {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index, %{{.*}}: i64, %{{.*}}: i32, %{{.*}}: f32):
// CHECK-NEXT:      %[[X:.*]] = sim.read @X[%[[I]]] : f32
// CHECK-NEXT:      sim.yield %[[X]] : f32
// CHECK-NEXT:    }
// CHECK-NOT:     @Aux
// CHECK:         sim.observe [@X]
sim.simulation @unused_reads range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @Aux: no observed buffer depends on it}}
  sim.buffer @Aux : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    // expected-remark @+1 {{removed this read of @Aux from @C: no observed buffer depends on its value}}
    %unused = sim.read @Aux[%i] : f32
    // expected-remark @+1 {{removed this read of @Aux from @C: no observed buffer depends on its value}}
    %a = sim.read @Aux[%i] : f32
    %dead = arith.addf %a, %a : f32
    %lo = arith.constant 0 : index
    %hi = arith.constant 3 : index
    %step = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    // expected-remark @+1 {{removed this read of @Aux from @C: no observed buffer depends on its value}}
    %outside = sim.read @Aux[%i] : f32
    %sum = scf.for %k = %lo to %hi step %step iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      // expected-remark @+1 {{removed this read of @Aux from @C: no observed buffer depends on its value}}
      %y = sim.read @Aux[%j] : f32
      %next = arith.addf %acc, %y : f32
      scf.yield %outside : f32
    }
    sim.yield %x : f32
  }
  // expected-remark @+1 {{removed component @WriteAux: no observed buffer depends on it}}
  sim.component @WriteAux writes(@Aux) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @Aux[%i] : f32
    sim.yield %a : f32
  }
  sim.observe [@X]
}

// -----

// The same when the component is kept for one buffer and drops another: the
// read that fed only the dropped value and the unused one both go.

// CHECK-LABEL: sim.simulation @unused_reads_and_dropped_write
// CHECK-NOT:     @Aux
// CHECK:         sim.component @C writes(@X) evaluate {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index, %{{.*}}: i64, %{{.*}}: i32, %{{.*}}: f32):
// CHECK-NEXT:      %[[X:.*]] = sim.read @X[%[[I]]] : f32
// CHECK-NEXT:      sim.yield %[[X]] : f32
// CHECK-NEXT:    }
sim.simulation @unused_reads_and_dropped_write range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @Debug: no observed buffer depends on it}}
  sim.buffer @Debug : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{removed buffer @Aux: no observed buffer depends on it}}
  sim.buffer @Aux : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-remark @+1 {{@C no longer writes @Debug: no observed buffer depends on it}}
  sim.component @C writes(@X, @Debug) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    // expected-remark @+1 {{removed this read of @Aux from @C: no observed buffer depends on its value}}
    %unused = sim.read @Aux[%i] : f32
    // expected-remark @+1 {{removed this read of @Debug from @C: no observed buffer depends on its value}}
    %d = sim.read @Debug[%i] : f32
    sim.yield %x, %d : f32, f32
  }
  // expected-remark @+1 {{removed component @WriteAux: no observed buffer depends on it}}
  sim.component @WriteAux writes(@Aux) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

// A read whose value an operation with an effect uses (a store into a
// scratch array that the yielded value is loaded from) counts, although the
// yielded value's slice does not reach it: @Aux and its writer stay.

// CHECK-LABEL: sim.simulation @read_through_memory
// CHECK:         sim.buffer @Aux
// CHECK:         sim.component @C writes(@X) evaluate {
// CHECK:           sim.read @Aux
// CHECK:           memref.store
// CHECK:         sim.component @WriteAux writes(@Aux)
sim.simulation @read_through_memory range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Aux : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %scratch = memref.alloc() : memref<1xf32>
    %c0 = arith.constant 0 : index
    %a = sim.read @Aux[%i] : f32
    memref.store %a, %scratch[%c0] : memref<1xf32>
    %x = memref.load %scratch[%c0] : memref<1xf32>
    sim.yield %x : f32
  }
  sim.component @WriteAux writes(@Aux) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @Aux[%i] : f32
    sim.yield %a : f32
  }
  sim.observe [@X]
}

// -----

// A removed component's num_steps goes with it: where it bounded the big
// step (here @Limit reads @A through the back edge), the pruned scene takes
// other big steps, and the remark says so.

// CHECK-LABEL: sim.simulation @bounding
// CHECK-NOT: @Limit
// CHECK: sim.component @C
sim.simulation @bounding range(40) dt(5.0e-2 : f32) max_steps(8) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  // expected-remark @+1 {{removed buffer @Q: no observed buffer depends on it}}
  sim.buffer @Q : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  // expected-remark @+1 {{removed component @Limit: no observed buffer depends on it; its num_steps, which bounds the big step under traditional (and under hip where it reads through the back edge), goes with it, so the big steps, and the values of outputs that sub-step, can differ from a run that observes @Q (observe a buffer it writes to keep it)}}
  sim.component @Limit writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %a = sim.read @A[%i] : f32
    %one = arith.constant 1 : i32
    sim.yield %one : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.component @C writes(@A) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 3 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Limit]
  sim.observe [@A]
}
