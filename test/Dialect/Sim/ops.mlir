// RUN: sim-opt %s --split-input-file | sim-opt --split-input-file | FileCheck %s
// RUN: sim-opt %s --split-input-file --mlir-print-op-generic | sim-opt --split-input-file | FileCheck %s

// Round trip of every sim operation and every form of its syntax, in the
// custom and in the generic form. Each case is a complete, valid simulation.

// The simulation header with an f32 time step; an empty simulation is valid.
// CHECK-LABEL: sim.simulation @header_f32 range(65536) dt(1.000000e-03 : f32) max_steps(3) {
// CHECK-NEXT:  }
sim.simulation @header_f32 range(65536) dt(1.0e-3 : f32) max_steps(3) {
}

// -----

// A named top-level module is the top level: its simulations are valid.
// CHECK-LABEL: module @scenes {
// CHECK-NEXT:    sim.simulation @in_named_module range(16) dt(1.000000e+00 : f32) max_steps(1) {
module @scenes {
  sim.simulation @in_named_module range(16) dt(1.0 : f32) max_steps(1) {
  }
}

// -----

// An f64 time step, and a discardable attribute after the header.
// CHECK-LABEL: sim.simulation @header_f64 range(1) dt(2.500000e-01 : f64) max_steps(1) attributes {note = "x"} {
sim.simulation @header_f64 range(1) dt(0.25 : f64) max_steps(1) attributes {note = "x"} {
}

// -----

// Parameters of integer (signless and index) and float types.
// CHECK-LABEL: sim.simulation @params
// CHECK:         sim.param @L = 256 : i32
// CHECK:         sim.param @N = 7 : index
// CHECK:         sim.param @big = -5 : i64
// CHECK:         sim.param @flag = true
// CHECK:         sim.param @k = 2.500000e+01 : f32
// CHECK:         sim.param @eps = 1.000000e-09 : f64
sim.simulation @params range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 256 : i32
  sim.param @N = 7 : index
  sim.param @big = -5 : i64
  sim.param @flag = true
  sim.param @k = 2.5e+01 : f32
  sim.param @eps = 1.0e-9 : f64
}

// -----

// Every interpolation attribute, every boundary rule, and the defaults: no
// interp clause, and boundary(clamp), which is the default and is elided.
// CHECK-LABEL: sim.simulation @buffers
// CHECK:         sim.buffer @Lin : f32 interp(#sim.linear) init {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index):
// CHECK:           sim.yield %{{.*}} : f32
// CHECK:         sim.buffer @Cub : vector<4xf32> interp(#sim.cubic) boundary(wrap) init {
// CHECK:         sim.buffer @Her : f32 interp(#sim.hermite<@Dflt>) boundary(zero) init {
// CHECK:         sim.buffer @Dflt : f32 init {
// CHECK:         sim.buffer @Rev : f32 interp(#sim.cubic) boundary(zero) init {
// CHECK:         sim.buffer @Clamp : f64 init {
// CHECK:         sim.component @Step writes(@Lin, @Cub, @Her, @Dflt, @Rev, @Clamp) evaluate {
sim.simulation @buffers range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @Lin : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Cub : vector<4xf32> interp(#sim.cubic) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant dense<1.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
  sim.buffer @Her : f32 interp(#sim.hermite<@Dflt>) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 2.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Dflt : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 3.0 : f32
    sim.yield %c : f32
  }
  // The clauses in the other order print in the usual one.
  sim.buffer @Rev : f32 boundary(zero) interp(#sim.cubic) init {
  ^bb0(%i: index):
    %c = arith.constant 5.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Clamp : f64 boundary(clamp) init {
  ^bb0(%i: index):
    %c = arith.constant 4.0 : f64
    sim.yield %c : f64
  }
  sim.component @Step writes(@Lin, @Cub, @Her, @Dflt, @Rev, @Clamp) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @Lin[%i] : f32
    %b = sim.read @Cub[%i] : vector<4xf32>
    %c = sim.read @Her[%i] : f32
    %d = sim.read @Dflt[%i] : f32
    %r = sim.read @Rev[%i] : f32
    %e = sim.read @Clamp[%i] : f64
    sim.yield %a, %b, %c, %d, %r, %e : f32, vector<4xf32>, f32, f32, f32, f64
  }
}

// -----

// The optional exact body with its (index, f64) arguments, reads in init and
// exact bodies (initial states), and the snapshot unit attribute.
// CHECK-LABEL: sim.simulation @exact_and_init_reads
// CHECK:         sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) attributes {snapshot} init {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index):
// CHECK-NEXT:      %[[ONE:.*]] = arith.constant 1.000000e+00 : f64
// CHECK-NEXT:      sim.yield %[[ONE]] : f64
// CHECK-NEXT:    } exact {
// CHECK-NEXT:    ^bb0(%[[I2:.*]]: index, %[[T:.*]]: f64):
// CHECK-NEXT:      %[[COS:.*]] = math.cos %[[T]] : f64
// CHECK-NEXT:      %[[V:.*]] = sim.read @V[%[[I2]]] : f64
// CHECK-NEXT:      %[[SUM:.*]] = arith.addf %[[COS]], %[[V]] : f64
// CHECK-NEXT:      sim.yield %[[SUM]] : f64
// CHECK-NEXT:    }
// CHECK:         sim.buffer @V : f64 init {
// CHECK-NEXT:    ^bb0(%[[J:.*]]: index):
// CHECK-NEXT:      %[[X:.*]] = sim.read @X[%[[J]]] : f64
// CHECK-NEXT:      sim.yield %[[X]] : f64
// CHECK-NEXT:    }
sim.simulation @exact_and_init_reads range(16) dt(1.0e-2 : f64) max_steps(1) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) attributes {snapshot} init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %cos = math.cos %t : f64
    %v = sim.read @V[%i] : f64
    %sum = arith.addf %cos, %v : f64
    sim.yield %sum : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.component @Integrate writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    sim.yield %x, %v : f64, f64
  }
}

// -----

// A component with a num_steps body writing two buffers, an f64 time step
// and the analysis attributes in the attribute dictionary.
// CHECK-LABEL: sim.simulation @component_num_steps
// CHECK:         sim.component @Integrate writes(@X, @V) attributes {parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping in_kernel>} num_steps {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index, %[[T:.*]]: i64):
// CHECK-NEXT:      %[[C2:.*]] = arith.constant 2 : i32
// CHECK-NEXT:      sim.yield %[[C2]] : i32
// CHECK-NEXT:    } evaluate {
// CHECK-NEXT:    ^bb0(%[[I2:.*]]: index, %[[T2:.*]]: i64, %[[N:.*]]: i32, %[[DT:.*]]: f64):
// CHECK-NEXT:      %[[X:.*]] = sim.read @X[%[[I2]]] own : f64
// CHECK-NEXT:      %[[V:.*]] = sim.read @V[%[[I2]]] own : f64
// CHECK-NEXT:      %[[NF:.*]] = arith.sitofp %[[N]] : i32 to f64
// CHECK-NEXT:      %[[H:.*]] = arith.mulf %[[NF]], %[[DT]] : f64
// CHECK-NEXT:      %[[DX:.*]] = arith.mulf %[[H]], %[[V]] : f64
// CHECK-NEXT:      %[[X1:.*]] = arith.addf %[[X]], %[[DX]] : f64
// CHECK-NEXT:      sim.yield %[[X1]], %[[V]] : f64, f64
// CHECK-NEXT:    }
sim.simulation @component_num_steps range(16) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.component @Integrate writes(@X, @V) attributes {sub_stepping = #sim<sub_stepping in_kernel>, parity = #sim<parity copy_if_even>} num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] own : f64
    %v = sim.read @V[%i] own : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %dx = arith.mulf %h, %v : f64
    %x1 = arith.addf %x, %dx : f64
    sim.yield %x1, %v : f64, f64
  }
}

// -----

// Every read role, reads at another item, reads in num_steps, vector
// elements, and the other analysis attribute values.
// CHECK-LABEL: sim.simulation @read_roles
// CHECK:         sim.component @First writes(@A) attributes {parity = #sim<parity copy_if_even>, sub_stepping = #sim<sub_stepping grid_sync>} num_steps {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index, %[[T:.*]]: i64):
// CHECK-NEXT:      %[[B:.*]] = sim.read @B[%[[I]]] : vector<2xf32>
// CHECK:         } evaluate {
// CHECK-NEXT:    ^bb0(%[[I2:.*]]: index, %[[T2:.*]]: i64, %[[N:.*]]: i32, %[[DT:.*]]: f32):
// CHECK-NEXT:      %[[C1:.*]] = arith.constant 1 : index
// CHECK-NEXT:      %[[J:.*]] = arith.addi %[[I2]], %[[C1]] : index
// CHECK-NEXT:      %[[OWN:.*]] = sim.read @A[%[[J]]] own : vector<2xf32>
// CHECK-NEXT:      %[[BACK:.*]] = sim.read @B[%[[I2]]] back_edge : vector<2xf32>
// CHECK-NEXT:      %[[SUM:.*]] = arith.addf %[[OWN]], %[[BACK]] : vector<2xf32>
// CHECK-NEXT:      sim.yield %[[SUM]] : vector<2xf32>
// CHECK:         sim.component @Second writes(@B) evaluate {
// CHECK:           %[[A:.*]] = sim.read @A[%{{.*}}] interpolate : vector<2xf32>
// CHECK-NEXT:      sim.yield %[[A]] : vector<2xf32>
sim.simulation @read_roles range(32) dt(5.0e-1 : f32) max_steps(2) {
  sim.buffer @A : vector<2xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  sim.buffer @B : vector<2xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<1.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  sim.component @First writes(@A) attributes {sub_stepping = #sim<sub_stepping grid_sync>, parity = #sim<parity copy_if_even>} num_steps {
  ^bb0(%i: index, %t: i64):
    %b = sim.read @B[%i] : vector<2xf32>
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %own = sim.read @A[%j] own : vector<2xf32>
    %back = sim.read @B[%i] back_edge : vector<2xf32>
    %sum = arith.addf %own, %back : vector<2xf32>
    sim.yield %sum : vector<2xf32>
  }
  sim.component @Second writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] interpolate : vector<2xf32>
    sim.yield %a : vector<2xf32>
  }
}

// -----

// Every load version, big_step, and get_param of an integer and a float
// parameter, in num_steps and evaluate bodies.
// CHECK-LABEL: sim.simulation @loads_and_params
// CHECK:         sim.param @L = 4 : i32
// CHECK:         sim.param @k = 5.000000e-01 : f32
// CHECK:         sim.component @Reader writes(@R) num_steps {
// CHECK-NEXT:    ^bb0(%[[I:.*]]: index, %[[T:.*]]: i64):
// CHECK-NEXT:      %[[L:.*]] = sim.get_param @L : i32
// CHECK-NEXT:      %[[T0:.*]], %[[M0:.*]] = sim.big_step : i64, i64
// CHECK-NEXT:      %[[LOC:.*]] = sim.load local @R[%[[I]]] : f32
// CHECK-NEXT:      sim.yield %[[L]] : i32
// CHECK-NEXT:    } evaluate {
// CHECK-NEXT:    ^bb0(%[[I2:.*]]: index, %[[T2:.*]]: i64, %[[N:.*]]: i32, %[[DT:.*]]: f32):
// CHECK-NEXT:      %[[BEGIN:.*]], %[[SIZE:.*]] = sim.big_step : i64, i64
// CHECK-NEXT:      %[[SRC:.*]] = sim.load source @W[%[[I2]]] : f32
// CHECK-NEXT:      %[[SNAP:.*]] = sim.load snapshot @W[%[[I2]]] : f32
// CHECK-NEXT:      %[[TGT:.*]] = sim.load target @W[%[[I2]]] : f32
// CHECK-NEXT:      %[[OWN:.*]] = sim.load local @R[%[[I2]]] : f32
// CHECK-NEXT:      %[[K:.*]] = sim.get_param @k : f32
// CHECK-NEXT:      %[[S1:.*]] = arith.addf %[[SRC]], %[[SNAP]] : f32
// CHECK-NEXT:      %[[S2:.*]] = arith.addf %[[S1]], %[[TGT]] : f32
// CHECK-NEXT:      %[[S3:.*]] = arith.addf %[[S2]], %[[OWN]] : f32
// CHECK-NEXT:      %[[S4:.*]] = arith.mulf %[[S3]], %[[K]] : f32
// CHECK-NEXT:      sim.yield %[[S4]] : f32
// CHECK-NEXT:    }
sim.simulation @loads_and_params range(16) dt(1.0 : f32) max_steps(4) {
  sim.param @L = 4 : i32
  sim.param @k = 0.5 : f32
  sim.buffer @W : f32 attributes {snapshot} init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Writer writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %w = sim.read @W[%i] : f32
    sim.yield %w : f32
  }
  sim.component @Reader writes(@R) num_steps {
  ^bb0(%i: index, %t: i64):
    %L = sim.get_param @L : i32
    %T0, %m0 = sim.big_step : i64, i64
    %loc = sim.load local @R[%i] : f32
    sim.yield %L : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %T, %m = sim.big_step : i64, i64
    %src = sim.load source @W[%i] : f32
    %snap = sim.load snapshot @W[%i] : f32
    %tgt = sim.load target @W[%i] : f32
    %own = sim.load local @R[%i] : f32
    %k = sim.get_param @k : f32
    %s1 = arith.addf %src, %snap : f32
    %s2 = arith.addf %s1, %tgt : f32
    %s3 = arith.addf %s2, %own : f32
    %s4 = arith.mulf %s3, %k : f32
    sim.yield %s4 : f32
  }
}

// -----

// A schedule given as a prefix and an observe list.
// CHECK-LABEL: sim.simulation @schedule_prefix
// CHECK:         sim.schedule [@C0]{{$}}
// CHECK-NEXT:    sim.observe [@B0, @B1]
sim.simulation @schedule_prefix range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] : f32
    sim.yield %x : f32
  }
  sim.schedule [@C0]
  sim.observe [@B0, @B1]
}

// -----

// A full schedule with bounded_by, and an observe list given before the ops
// it names (the simulation body is a graph region).
// CHECK-LABEL: sim.simulation @schedule_bounded
// CHECK:         sim.observe [@B1]
// CHECK:         sim.schedule [@C0, @C1] bounded_by [@C0]
sim.simulation @schedule_bounded range(16) dt(1.0 : f32) max_steps(1) {
  sim.observe [@B1]
  sim.buffer @B0 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B1 : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C0 writes(@B0) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B1[%i] back_edge : f32
    sim.yield %x : f32
  }
  sim.component @C1 writes(@B1) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B0[%i] interpolate : f32
    sim.yield %x : f32
  }
  sim.schedule [@C0, @C1] bounded_by [@C0]
}

// -----

// Body operations nested in other regions of a body (scf), and the largest
// vector element.
// CHECK-LABEL: sim.simulation @nested_body_ops
// CHECK:         sim.buffer @B : vector<16xf64> init {
// CHECK:         sim.component @C writes(@B) evaluate {
// CHECK:           %[[R:.*]] = scf.execute_region -> vector<16xf64> {
// CHECK-NEXT:        %[[X:.*]] = sim.read @B[%{{.*}}] own : vector<16xf64>
// CHECK-NEXT:        scf.yield %[[X]] : vector<16xf64>
// CHECK-NEXT:      }
// CHECK-NEXT:      sim.yield %[[R]] : vector<16xf64>
sim.simulation @nested_body_ops range(4) dt(1.0 : f64) max_steps(1) {
  sim.buffer @B : vector<16xf64> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<16xf64>
    sim.yield %c : vector<16xf64>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %r = scf.execute_region -> vector<16xf64> {
      %x = sim.read @B[%i] own : vector<16xf64>
      scf.yield %x : vector<16xf64>
    }
    sim.yield %r : vector<16xf64>
  }
}

// -----

// Every strategy the memory plan records; hip-cache is printed in quotes.
// CHECK-LABEL: sim.simulation @strategy_simple
// CHECK-SAME:    attributes {strategy = #sim<strategy simple>}
// CHECK-LABEL: sim.simulation @strategy_traditional
// CHECK-SAME:    attributes {strategy = #sim<strategy traditional>}
// CHECK-LABEL: sim.simulation @strategy_hip
// CHECK-SAME:    attributes {strategy = #sim<strategy hip>}
// CHECK-LABEL: sim.simulation @strategy_hip_cache
// CHECK-SAME:    attributes {strategy = #sim<strategy "hip-cache">}
sim.simulation @strategy_simple range(4) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy simple>} {
}
sim.simulation @strategy_traditional range(4) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy traditional>} {
}
sim.simulation @strategy_hip range(4) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy hip>} {
}
sim.simulation @strategy_hip_cache range(4) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
}

// -----

// The simulation's own parameters read in every kind of body: range as i64,
// dt in the time step's type, max_steps as i32.
// CHECK-LABEL: sim.simulation @builtin_params
// CHECK:         sim.buffer @X : f64 init {
// CHECK:           sim.get_param @range : i64
// CHECK:           sim.get_param @dt : f64
// CHECK:         } exact {
// CHECK:           sim.get_param @max_steps : i32
// CHECK:         sim.component @C writes(@X) num_steps {
// CHECK:           sim.get_param @dt : f64
// CHECK:           sim.get_param @max_steps : i32
// CHECK:         } evaluate {
// CHECK:           sim.get_param @range : i64
sim.simulation @builtin_params range(16) dt(1.0e-2 : f64) max_steps(4) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %r = sim.get_param @range : i64
    %rf = arith.sitofp %r : i64 to f64
    %dt = sim.get_param @dt : f64
    %x = arith.mulf %rf, %dt : f64
    sim.yield %x : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %m = sim.get_param @max_steps : i32
    %mf = arith.sitofp %m : i32 to f64
    %x = arith.mulf %mf, %t : f64
    sim.yield %x : f64
  }
  sim.component @C writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %dt = sim.get_param @dt : f64
    %m = sim.get_param @max_steps : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %r = sim.get_param @range : i64
    %rf = arith.sitofp %r : i64 to f64
    sim.yield %rf : f64
  }
}

// -----

// A buffer whose value means nothing between step ends: interp(none), also
// when written as the attribute #sim.none.
// CHECK-LABEL: sim.simulation @not_interpolable
// CHECK:         sim.buffer @P : f32 interp(none) init {
// CHECK:         sim.buffer @Q : f32 interp(none) boundary(wrap) init {
sim.simulation @not_interpolable range(16) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @P : f32 interp(none) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Q : f32 interp(#sim.none) boundary(wrap) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@P, @Q) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : f32
    sim.yield %p, %p : f32, f32
  }
}

// -----

// The caches of a hip-cache plan.
// CHECK-LABEL: sim.simulation @caches
// CHECK:         sim.component @CB writes(@B) attributes {caches = [#sim.cache<@A, -4, 4>, #sim.cache<@C, 0, 1>]} evaluate {
sim.simulation @caches range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy "hip-cache">} {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @CA writes(@A, @C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x, %x : f32, f32
  }
  sim.component @CB writes(@B) attributes {caches = [#sim.cache<@A, -4, 4>, #sim.cache<@C, 0, 1>]} evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @A[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// Vector positions in range are valid in bodies: static, constant, or any
// other value (the verifier rejects only the poison index -1 and constants
// out of range; invalid-poison.mlir).
// CHECK-LABEL: sim.simulation @vector_positions
// CHECK:         vector.extract %{{.*}}[3] : f32 from vector<4xf32>
// CHECK:         vector.extract %{{.*}}[%{{.*}}] : f32 from vector<4xf32>
// CHECK:         vector.insert %{{.*}}, %{{.*}} [%{{.*}}] : f32 into vector<4xf32>
// CHECK:         vector.shuffle %{{.*}}, %{{.*}} [7, 0, 5, 2] : vector<4xf32>, vector<4xf32>
sim.simulation @vector_positions range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %c : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %last = vector.extract %v[3] : f32 from vector<4xf32>
    %c1 = arith.constant 1 : index
    %second = vector.extract %v[%c1] : f32 from vector<4xf32>
    %c4 = arith.constant 4 : index
    %lane = arith.remui %i, %c4 : index
    %w = vector.insert %last, %v[%lane] : f32 into vector<4xf32>
    %r = vector.shuffle %w, %v [7, 0, 5, 2] : vector<4xf32>, vector<4xf32>
    %s = vector.broadcast %second : f32 to vector<4xf32>
    %y = arith.addf %r, %s : vector<4xf32>
    sim.yield %y : vector<4xf32>
  }
}
