// Each body becomes a per-item function; view reads and parameters become
// calls through the context's callbacks (docs/Reference.md), and the
// sim.reference_model dictionary records what the executor needs to know.
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

// The model: parameters and buffers by scene name (the model's indices),
// components in schedule order with model buffer indices and how each takes
// a big step under every strategy (@Heater bounds the hip step).
// CHECK-LABEL: module @rod_reference attributes {sim.reference_model = {
// CHECK-SAME:    buffers = ["Q", "T"],
// CHECK-SAME:    components = [{name = "Heater", num_steps = true, reads = array<i64: 1>,
// CHECK-SAME:      stepping = {hip = {advance = #sim<advance whole_step>, estimates = true}, "hip-cache" = {advance = #sim<advance whole_step>, estimates = true}, lts = {advance = #sim<advance whole_step>, estimates = true}, simple = {advance = #sim<advance whole_step>, estimates = false}, traditional = {advance = #sim<advance whole_step>, estimates = true}},
// CHECK-SAME:      sub_stepping = #sim<sub_stepping in_kernel>, writes = array<i64: 0>},
// CHECK-SAME:    {name = "Rod", num_steps = false, reads = array<i64: 0>,
// CHECK-SAME:      stepping = {hip = {advance = #sim<advance whole_step>, estimates = false}, "hip-cache" = {advance = #sim<advance whole_step>, estimates = false}, lts = {advance = #sim<advance whole_step>, estimates = false}, simple = {advance = #sim<advance whole_step>, estimates = false}, traditional = {advance = #sim<advance whole_step>, estimates = false}},
// CHECK-SAME:      sub_stepping = #sim<sub_stepping in_kernel>, writes = array<i64: 1>}],
// CHECK-SAME:    params = ["k", "unused"],
// CHECK-SAME:    step_caps = {hip = 4 : i64, "hip-cache" = 4 : i64, lts = 4 : i64, simple = 1 : i64, traditional = 4 : i64}, totals = []}}
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

// grid_sync: grid-wide sub-steps under hip, hip-cache and lts (@U is
// Hermite-interpolated, so no local time steps).
// CHECK-LABEL: module @diffuse_reference attributes {sim.reference_model = {
// CHECK-SAME:    buffers = ["U", "V"],
// CHECK-SAME:    components = [{name = "Spread", num_steps = true, reads = array<i64: 0, 1>,
// CHECK-SAME:      stepping = {hip = {advance = #sim<advance grid_substeps>, estimates = false}, "hip-cache" = {advance = #sim<advance grid_substeps>, estimates = false}, lts = {advance = #sim<advance grid_substeps>, estimates = false}, simple = {advance = #sim<advance whole_step>, estimates = false}, traditional = {advance = #sim<advance whole_step>, estimates = true}},
// CHECK-SAME:      sub_stepping = #sim<sub_stepping grid_sync>, writes = array<i64: 0, 1>}],
// CHECK-SAME:    params = [],
// CHECK-SAME:    step_caps = {hip = 4 : i64, "hip-cache" = 4 : i64, lts = 4 : i64, simple = 1 : i64, traditional = 4 : i64}, totals = []}}
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

// -----

// In-kernel sub-steps under hip (nothing reads through the back edge, so
// nothing bounds the step), a total with the model buffers it reads, and
// names that are no identifiers.
sim.simulation @"two stage" range(16) dt(1.0e-3 : f32) max_steps(4) {
  sim.param @"gain 1" = 2.0 : f32
  sim.buffer @"X 0" : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @A writes(@"X 0") num_steps {
  ^bb0(%i: index, %t: i64):
    %two = arith.constant 2 : i32
    sim.yield %two : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @"X 0"[%i] : f32
    %g = sim.get_param @"gain 1" : f32
    %y = arith.mulf %x, %g : f32
    sim.yield %y : f32
  }
  sim.component @B writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %one = arith.constant 1 : i32
    sim.yield %one : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @"X 0"[%i] : f32
    sim.yield %x : f32
  }
  sim.total @"sum Y" : f64 {
  ^bb0(%i: index):
    %y = sim.read @Y[%i] : f32
    %x = sim.read @"X 0"[%i] : f32
    %s = arith.addf %y, %x : f32
    %e = arith.extf %s : f32 to f64
    sim.yield %e : f64
  }
  sim.schedule [@A, @B]
  sim.observe [@Y]
}

// CHECK-LABEL: module @"two stage_reference" attributes {sim.reference_model = {
// CHECK-SAME:    buffers = ["X 0", "Y"],
// CHECK-SAME:    components = [{name = "A", num_steps = true, reads = array<i64: 0>,
// CHECK-SAME:      stepping = {hip = {advance = #sim<advance group_substeps>, estimates = false}, "hip-cache" = {advance = #sim<advance group_substeps>, estimates = false}, lts = {advance = #sim<advance group_substeps>, estimates = false}, simple = {advance = #sim<advance whole_step>, estimates = false}, traditional = {advance = #sim<advance whole_step>, estimates = true}},
// CHECK-SAME:      sub_stepping = #sim<sub_stepping in_kernel>, writes = array<i64: 0>},
// CHECK-SAME:    {name = "B", num_steps = true, reads = array<i64: 0>,
// CHECK-SAME:      stepping = {hip = {advance = #sim<advance group_substeps>, estimates = false}, "hip-cache" = {advance = #sim<advance group_substeps>, estimates = false}, lts = {advance = #sim<advance group_substeps>, estimates = false}, simple = {advance = #sim<advance whole_step>, estimates = false}, traditional = {advance = #sim<advance whole_step>, estimates = true}},
// CHECK-SAME:      sub_stepping = #sim<sub_stepping in_kernel>, writes = array<i64: 1>}],
// CHECK-SAME:    params = ["gain 1"],
// CHECK-SAME:    totals = [{name = "sum Y", reads = array<i64: 1, 0>}]}}
// CHECK: func.func @sim_ref_total_0(
