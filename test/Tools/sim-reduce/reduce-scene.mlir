// sim-reduce shrinks a scene while a test script still calls it interesting:
// here while sim-opt remarks that @Scatter reads its own buffer through a
// gather. The sim dialect's reduction patterns remove @Heat with @V and
// @Source with @W (each alone would leave a scene that does not verify: a
// buffer without its writer), turn @Scatter's read of @V into a zero, its
// parameters into their values and the range into one block; the reduction
// tree then deletes what the bodies no longer need. A candidate whose
// sim.yield lost its operand must fail to verify, not crash the verifier.
//
// RUN: env SIM_OPT=sim-opt sim-reduce %s \
// RUN:   --reduction-tree='traversal-mode=0 test=%S/Inputs/gather-remark.sh' \
// RUN:   -o %t.mlir 2> %t.err
// RUN: FileCheck %s --input-file=%t.mlir
//
// The errors of the candidates that do not verify are not printed: a
// successful reduction is quiet.
// RUN: FileCheck %s --allow-empty --check-prefix=QUIET --input-file=%t.err
// QUIET-NOT: {{.}}
//
// A test script that calls the input itself uninteresting (exits with 0:
// the reverse of mlir-reduce's convention) gets a warning that says so,
// not a silent failure.
// RUN: not sim-reduce %s --reduction-tree='traversal-mode=0 test=/bin/true' \
// RUN:   -o %t.none.mlir 2>&1 | FileCheck %s --check-prefix=NONE
// RUN: not test -e %t.none.mlir
// NONE: sim-reduce: warning: the input is not interesting, so nothing was reduced: the test script exits with status 0 on it
//
// The reduced scene still makes the remark.
// RUN: sim-opt %t.mlir --sim-substep-legality -o %t.out 2>&1 \
// RUN:   | FileCheck %s --check-prefix=REMARK

// CHECK-LABEL: sim.simulation @scene range(32)
// CHECK-NOT:     sim.param
// CHECK-NOT:     @V
// CHECK-NOT:     @W
// CHECK-NOT:     @Heat
// CHECK:         sim.buffer @U
// CHECK:         sim.component @Scatter writes(@U)
// CHECK-NOT:       sim.get_param
// CHECK:           %[[STRIDE:.+]] = arith.constant 7 : index
// CHECK:           %[[SCALE:.+]] = arith.constant 5.000000e-01 : f32
// CHECK:           %[[J:.+]] = arith.muli %{{.*}}, %[[STRIDE]] : index
// CHECK:           %[[G:.+]] = sim.read @U[%[[J]]] : f32
// CHECK:           %[[ZERO:.+]] = arith.constant 0.000000e+00 : f32
// CHECK:           %[[SUM:.+]] = arith.addf %[[G]], %[[ZERO]] : f32
// CHECK:           arith.mulf %[[SUM]], %[[SCALE]] : f32
// CHECK-NOT:     sim.component
// CHECK:         sim.observe [@U]

// REMARK: remark: @Scatter needs a grid-wide barrier between sub-steps: its evaluate body reads @U, which it writes, through a gather

sim.simulation @scene range(64) dt(1.0e-2 : f32) max_steps(4) {
  sim.param @k = 5.0e-1 : f32
  sim.param @stride = 7 : i64
  sim.buffer @U : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @W : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 2.0 : f32
    sim.yield %c : f32
  }
  sim.component @Heat writes(@V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c4 = arith.constant 4 : i32
    sim.yield %c4 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %l = arith.subi %i, %c1 : index
    %r = arith.addi %i, %c1 : index
    %vl = sim.read @V[%l] : f32
    %v = sim.read @V[%i] : f32
    %vr = sim.read @V[%r] : f32
    %k = sim.get_param @k : f32
    %s = arith.addf %vl, %vr : f32
    %d = arith.mulf %k, %s : f32
    %x = arith.addf %v, %d : f32
    sim.yield %x : f32
  }
  sim.component @Scatter writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.get_param @stride : i64
    %c7 = arith.index_cast %s : i64 to index
    %k = sim.get_param @k : f32
    %j = arith.muli %i, %c7 : index
    %g = sim.read @U[%j] : f32
    %v = sim.read @V[%i] : f32
    %x0 = arith.addf %g, %v : f32
    %x = arith.mulf %x0, %k : f32
    sim.yield %x : f32
  }
  sim.component @Source writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %w = sim.read @W[%i] : f32
    %x = arith.mulf %u, %w : f32
    sim.yield %x : f32
  }
  sim.observe [@U, @V, @W]
}
