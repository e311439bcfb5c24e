// Each body becomes a per-item function; view reads and parameters become
// calls through the context's callbacks (docs/Reference.md), and the model
// text records what the executor needs to know.
//
// RUN: sim-opt %s --split-input-file --sim-reference-pipeline | FileCheck %s
// RUN: sim-opt %s --split-input-file --sim-reference-pipeline | sim-opt --split-input-file | FileCheck %s

// A thermostat: @Heater (first, reads @T through the back edge) and @Rod,
// which reads @Q in a window and its own @T. @Unused is pruned away.
sim.simulation @rod range(16) dt(1.0e-3 : f32) max_steps(4) {
  sim.param @k = 2.0 : f32
  sim.param @unused = 3 : i32
  sim.buffer @Q : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @T : vector<3xf64> boundary(wrap) init {
  ^bb0(%i: index):
    %q = sim.read @Q[%i] : f32
    %e = arith.extf %q : f32 to f64
    %v = vector.broadcast %e : f64 to vector<3xf64>
    sim.yield %v : vector<3xf64>
  } exact {
  ^bb0(%i: index, %t: f64):
    %v = vector.broadcast %t : f64 to vector<3xf64>
    sim.yield %v : vector<3xf64>
  }
  sim.buffer @Unused : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Heater writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %temp = sim.read @T[%i] : vector<3xf64>
    %range = sim.get_param @range : i64
    %n = arith.trunci %range : i64 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %temp = sim.read @T[%i] : vector<3xf64>
    %x = vector.extract %temp[0] : f64 from vector<3xf64>
    %q = arith.truncf %x : f64 to f32
    sim.yield %q : f32
  }
  sim.component @Rod writes(@T) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %one = arith.constant 1 : index
    %j = arith.addi %i, %one : index
    %q = sim.read @Q[%j] : f32
    %k = sim.get_param @k : f32
    %kq = arith.mulf %k, %q : f32
    %e = arith.extf %kq : f32 to f64
    %v = vector.broadcast %e : f64 to vector<3xf64>
    sim.yield %v : vector<3xf64>
  }
  sim.component @Waste writes(@Unused) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @Unused[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@Heater]
  sim.observe [@T]
}

// CHECK-LABEL: module @rod_reference attributes {sim.reference_model = "reference rod\0Aparam 0 k f32\0Aparam 1 unused i32\0Abuffer 0 Q f32 interp linear boundary clamp\0Abuffer 1 T vector<3xf64> interp linear boundary wrap observed exact\0Acomponent 0 Heater substep in_kernel num_steps writes Q reads T\0Acomponent 1 Rod substep in_kernel writes T reads Q\0Aschedule Heater Rod\0A"}
// CHECK-NOT: sim.
// CHECK: func.func @sim_ref_init_0(%{{.*}}: !llvm.ptr, %{{.*}}: i64, %{{.*}}: !llvm.ptr)
// CHECK: func.func @sim_ref_init_1(%[[CTX:.*]]: !llvm.ptr, %[[ITEM:.*]]: i64, %[[OUT:.*]]: !llvm.ptr)
// CHECK:   %[[SCRATCH:.*]] = llvm.alloca %{{.*}} x !llvm.array<128 x i8> {alignment = 16 : i64}
// CHECK:   %[[I:.*]] = arith.index_cast %[[ITEM]] : i64 to index
// CHECK:   %[[BUF:.*]] = arith.constant 0 : i32
// CHECK:   %[[J:.*]] = arith.index_cast %[[I]] : index to i64
// CHECK:   %[[READ_SLOT:.*]] = llvm.getelementptr %[[CTX]][1] : (!llvm.ptr) -> !llvm.ptr, !llvm.ptr
// CHECK:   %[[READ:.*]] = llvm.load %[[READ_SLOT]] : !llvm.ptr -> !llvm.ptr
// CHECK:   %[[EXEC_SLOT:.*]] = llvm.getelementptr %[[CTX]][0] : (!llvm.ptr) -> !llvm.ptr, !llvm.ptr
// CHECK:   %[[EXEC:.*]] = llvm.load %[[EXEC_SLOT]] : !llvm.ptr -> !llvm.ptr
// CHECK:   llvm.call %[[READ]](%[[EXEC]], %[[BUF]], %[[J]], %[[SCRATCH]]) : !llvm.ptr, (!llvm.ptr, i32, i64, !llvm.ptr) -> ()
// CHECK:   %[[Q:.*]] = llvm.load %[[SCRATCH]] {alignment = 4 : i64} : !llvm.ptr -> f32
// CHECK:   arith.extf %[[Q]]
// CHECK:   llvm.store %{{.*}}, %[[OUT]] {alignment = 8 : i64} : vector<3xf64>, !llvm.ptr
// CHECK:   return
// CHECK: func.func @sim_ref_exact_1(%{{.*}}: !llvm.ptr, %{{.*}}: i64, %[[TIME:.*]]: f64, %[[EOUT:.*]]: !llvm.ptr)
// CHECK:   vector.broadcast %[[TIME]] : f64 to vector<3xf64>
// CHECK:   llvm.store %{{.*}}, %[[EOUT]]
// CHECK: func.func @sim_ref_num_steps_0(%[[NCTX:.*]]: !llvm.ptr, %{{.*}}: i64, %{{.*}}: i64) -> i32
// CHECK:   arith.constant 1 : i32
// CHECK:   llvm.call
// CHECK:   llvm.load %{{.*}} {alignment = 8 : i64} : !llvm.ptr -> vector<3xf64>
// CHECK:   %[[RANGE_INDEX:.*]] = arith.constant -1 : i32
// CHECK:   %[[PARAM_SLOT:.*]] = llvm.getelementptr %[[NCTX]][2]
// CHECK:   %[[PARAM:.*]] = llvm.load %[[PARAM_SLOT]]
// CHECK:   llvm.call %[[PARAM]](%{{.*}}, %[[RANGE_INDEX]], %{{.*}}) : !llvm.ptr, (!llvm.ptr, i32, !llvm.ptr) -> ()
// CHECK:   %[[RANGE:.*]] = llvm.load %{{.*}} {alignment = 8 : i64} : !llvm.ptr -> i64
// CHECK:   %[[N:.*]] = arith.trunci %[[RANGE]]
// CHECK:   return %[[N]] : i32
// CHECK: func.func @sim_ref_evaluate_0(%{{.*}}: !llvm.ptr, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i32, %[[DT:.*]]: f64, %[[OUTS:.*]]: !llvm.ptr)
// CHECK:   arith.truncf %[[DT]] : f64 to f32
// CHECK:   %[[OUT0_SLOT:.*]] = llvm.getelementptr %[[OUTS]][0] : (!llvm.ptr) -> !llvm.ptr, !llvm.ptr
// CHECK:   %[[OUT0:.*]] = llvm.load %[[OUT0_SLOT]] : !llvm.ptr -> !llvm.ptr
// CHECK:   llvm.store %{{.*}}, %[[OUT0]] {alignment = 4 : i64} : f32, !llvm.ptr
// CHECK: func.func @sim_ref_evaluate_1(
// CHECK:   arith.constant 0 : i32
// CHECK:   llvm.call
// CHECK:   arith.constant 0 : i32
// CHECK:   llvm.call
// CHECK-NOT: func.func
// CHECK-NOT: sim_ref_num_steps_1

// -----

// A component whose own-neighbour read forces grid_sync, and a yield of a
// read value (the read's call replaces it in the return).
sim.simulation @diffuse range(16) dt(1.0e-3 : f64) max_steps(4) {
  sim.buffer @U : f64 interp(#sim.hermite<@V>) boundary(zero) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f64
    sim.yield %zero : f64
  }
  sim.buffer @V : f64 interp(none) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f64
    sim.yield %zero : f64
  }
  sim.component @Spread writes(@U, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %max = sim.get_param @max_steps : i32
    sim.yield %max : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %one = arith.constant 1 : index
    %j = arith.subi %i, %one : index
    %u = sim.read @U[%j] : f64
    %v = sim.read @V[%i] : f64
    sim.yield %u, %v : f64, f64
  }
  sim.observe [@U]
}

// CHECK-LABEL: module @diffuse_reference
// CHECK-SAME: buffer 0 U f64 interp hermite:V boundary zero observed\0Abuffer 1 V f64 interp none boundary clamp\0Acomponent 0 Spread substep grid_sync num_steps writes U V reads U V\0Aschedule Spread\0A
// CHECK: func.func @sim_ref_num_steps_0(
// CHECK:   arith.constant -3 : i32
// CHECK:   %[[MAX:.*]] = llvm.load %{{.*}} {alignment = 4 : i64} : !llvm.ptr -> i32
// CHECK:   return %[[MAX]] : i32
// CHECK: func.func @sim_ref_evaluate_0(%{{.*}}: !llvm.ptr, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i32, %[[DT:.*]]: f64, %[[OUTS:.*]]: !llvm.ptr)
// CHECK-NOT: arith.truncf
// CHECK:   %[[U:.*]] = llvm.load %{{.*}} : !llvm.ptr -> f64
// CHECK:   %[[V:.*]] = llvm.load %{{.*}} : !llvm.ptr -> f64
// CHECK:   llvm.getelementptr %[[OUTS]][0]
// CHECK:   llvm.store %[[U]]
// CHECK:   llvm.getelementptr %[[OUTS]][1]
// CHECK:   llvm.store %[[V]]
