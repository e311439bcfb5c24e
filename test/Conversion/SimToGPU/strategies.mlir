// The kernels and the plan of each strategy for one two-component scene:
// @Heater starts the step (it reads @T through the back edge and bounds the
// hip step), @Rod reads @Q interpolated through a window.
//
// RUN: sim-opt %s --sim-front-end=strategy=simple --sim-lower-to-gpu | FileCheck %s --check-prefix=SIMPLE
// RUN: sim-opt %s --sim-front-end=strategy=traditional --sim-lower-to-gpu | FileCheck %s --check-prefix=TRAD
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s --check-prefix=HIP
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | sim-opt | FileCheck %s --check-prefix=HIP
// RUN: sim-opt %s --sim-front-end=strategy=hip --sim-lower-to-gpu | FileCheck %s --check-prefix=NOSIM --implicit-check-not="sim."

sim.simulation @rod range(1024) dt(1.0e-3 : f32) max_steps(4) {
  sim.param @k = 2.0 : f32
  sim.buffer @Q : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @T : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.component @Heater writes(@Q) num_steps {
  ^bb0(%i: index, %t: i64):
    %temp = sim.read @T[%i] : f32
    %half = arith.constant 0.5 : f32
    %cold = arith.cmpf olt, %temp, %half : f32
    %one = arith.constant 1 : i32
    %four = arith.constant 4 : i32
    %n = arith.select %cold, %one, %four : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %temp = sim.read @T[%i] : f32
    %one = arith.constant 1.0 : f32
    %q = arith.subf %one, %temp : f32
    sim.yield %q : f32
  }
  sim.component @Rod writes(@T) num_steps {
  ^bb0(%i: index, %t: i64):
    %two = arith.constant 2 : i32
    sim.yield %two : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %q = sim.read @Q[%j] : f32
    %temp = sim.read @T[%i] : f32
    %k = sim.get_param @k : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %kh = arith.mulf %k, %h : f32
    %diff = arith.subf %q, %temp : f32
    %change = arith.mulf %kh, %diff : f32
    %next = arith.addf %temp, %change : f32
    sim.yield %next : f32
  }
  sim.schedule [@Heater]
  sim.observe [@T]
}

// NOSIM: gpu.module @rod_kernels

// simple: no estimates, m = 1 decided on the device, one evaluation per
// component reading the target half of @Q (already advanced this step).
// SIMPLE-LABEL: gpu.func @advance(
// SIMPLE:         memref.load %{{.*}}[%c3]
// SIMPLE:         arith.minsi %c1_i64{{[_0-9]*}}, %{{.*}} : i64
// SIMPLE-LABEL: gpu.func @evaluate_Rod(
// SIMPLE-SAME:      %[[CLOCK:[^:]*]]: memref<?xi64>, %[[Q:[^:]*]]: memref<?xf32>, %[[T:[^:]*]]: memref<?xf32>, %[[K:[^:]*]]: f32, %[[RANGE:[^:]*]]: i64, %[[DT:[^:]*]]: f32) kernel
// SIMPLE-SAME:      attributes {simplan.clock_slots = 15 : i64, simplan.shared = array<i64: 0, 0>}
// SIMPLE:         %[[M:.*]] = memref.load %[[CLOCK]][%c1]
// SIMPLE:         %[[P:.*]] = memref.load %[[CLOCK]][%c2]
// SIMPLE:         scf.if
// SIMPLE:           scf.for
// SIMPLE:             scf.if
// SIMPLE:               memref.load %[[Q]]
// SIMPLE:               memref.load %[[T]]
// SIMPLE:               memref.store %{{.*}}, %[[T]]
// SIMPLE-NOT:         gpu.barrier
// SIMPLE:         gpu.subgroup_reduce add %{{.*}} uniform
// SIMPLE:         memref.atomic_rmw addi %{{.*}}, %[[CLOCK]][%c9]
// simple: a step cap of 1; every component takes the whole step, none
// estimates.
// SIMPLE-LABEL: simplan.plan @rod strategy("simple") kernels(@rod_kernels) range(1024) dt(1.000000e-03 : f32) max_steps(4) step_cap(1) group_size(256) clock_slots(15) histogram(10) {
// SIMPLE:         simplan.param @k = 2.000000e+00 : f32
// SIMPLE:         simplan.buffer @Q : f32 stride(4)
// SIMPLE:         simplan.buffer @T : f32 stride(4) observed
// SIMPLE-NEXT:    simplan.component @Heater writes [@Q] evaluations(8) advance whole_step{{$}}
// SIMPLE-NEXT:    simplan.component @Rod writes [@T] evaluations(9) advance whole_step{{$}}
// SIMPLE:         simplan.phase init {
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@reset_clock single [#simplan.arg<clock>]
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@init_Q items [#simplan.arg<buffer @Q>, #simplan.arg<range>]
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@init_T items [#simplan.arg<buffer @T>, #simplan.arg<range>]
// SIMPLE-NEXT:    }
// SIMPLE:         simplan.phase step {
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@advance single [#simplan.arg<clock>]
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@evaluate_Heater items [#simplan.arg<clock>, #simplan.arg<buffer @Q>, #simplan.arg<buffer @T>, #simplan.arg<range>]
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@evaluate_Rod items [#simplan.arg<clock>, #simplan.arg<buffer @Q>, #simplan.arg<buffer @T>, #simplan.arg<param @k>, #simplan.arg<range>, #simplan.arg<dt>]
// SIMPLE-NEXT:    }
// SIMPLE:         simplan.phase finish {
// SIMPLE-NEXT:      simplan.launch @rod_kernels::@advance single [#simplan.arg<clock>]

// traditional: every component with num_steps estimates; the estimates
// reduce per warp, per group in workgroup memory and into the clock.
// TRAD-LABEL: gpu.func @estimate_Heater(
// TRAD-SAME:      workgroup(%[[GROUPMIN:.*]] : memref<1xi32, #gpu.address_space<workgroup>>) kernel
// TRAD:         scf.for
// TRAD:           arith.maxsi %{{.*}}, %c1_i32
// TRAD:         gpu.barrier
// TRAD:         %[[WARP:.*]] = gpu.subgroup_reduce minsi %{{.*}} uniform : (i32) -> i32
// TRAD:         memref.atomic_rmw mins %[[WARP]], %[[GROUPMIN]][%{{.*}}] : (i32, memref<1xi32, #gpu.address_space<workgroup>>) -> i32
// TRAD:         gpu.barrier
// TRAD:         memref.atomic_rmw mins %{{.*}}, %{{.*}}[%c4] : (i64, memref<?xi64>) -> i64
// TRAD-LABEL: gpu.func @estimate_Rod(
// advance decides m = min(estimate, cap, end - T) and counts a big step the
// end cut short (end - T positive and below the other two) in slot 6.
// TRAD-LABEL: gpu.func @advance(
// TRAD:         %[[END:.*]] = memref.load %{{.*}}[%c3]
// TRAD:         %[[LEFT:.*]] = arith.subi %[[END]], %{{.*}} : i64
// TRAD:         %[[ESTIMATE:.*]] = memref.load %{{.*}}[%c4]
// TRAD:         %[[BOUND:.*]] = arith.minsi %[[ESTIMATE]], %c4_i64 : i64
// TRAD:         %[[POSITIVE:.*]] = arith.cmpi sgt, %[[LEFT]], %c0_i64 : i64
// TRAD:         %[[SHORTER:.*]] = arith.cmpi slt, %[[LEFT]], %[[BOUND]] : i64
// TRAD:         %[[CUT:.*]] = arith.select %[[POSITIVE]], %[[SHORTER]], %[[POSITIVE]] : i1
// TRAD:         %[[CUTS:.*]] = memref.load %{{.*}}[%c6]
// TRAD:         %[[ONE:.*]] = arith.extui %[[CUT]] : i1 to i64
// TRAD:         %[[COUNT:.*]] = arith.addi %[[CUTS]], %[[ONE]] : i64
// TRAD:         memref.store %[[COUNT]], %{{.*}}[%c6]
// TRAD-LABEL: simplan.plan @rod strategy("traditional") {{.*}} max_steps(4) step_cap(4)
// TRAD:         simplan.component @Heater writes [@Q] evaluations(8) advance whole_step estimates{{$}}
// TRAD-NEXT:    simplan.component @Rod writes [@T] evaluations(9) advance whole_step estimates{{$}}
// TRAD:         simplan.phase step {
// TRAD-NEXT:      simplan.launch @rod_kernels::@estimate_Heater items
// TRAD-NEXT:      simplan.launch @rod_kernels::@estimate_Rod items
// TRAD-NEXT:      simplan.launch @rod_kernels::@advance single
// TRAD-NEXT:      simplan.launch @rod_kernels::@evaluate_Heater items
// TRAD-NEXT:      simplan.launch @rod_kernels::@evaluate_Rod items

// hip: only @Heater (bounded_by) estimates. It then takes the big step in
// one evaluation (its group minimum at T cannot be below m); @Rod runs
// Algorithm 2.
// HIP-LABEL: gpu.func @estimate_Heater(
// HIP-NOT:   gpu.func @estimate_Rod
// HIP-NOT:   gpu.func @substep_Heater
// HIP-LABEL: gpu.func @evaluate_Heater(
// HIP-LABEL: gpu.func @substep_Rod(
// HIP-SAME:      %[[CLOCK:[^:]*]]: memref<?xi64>, %[[Q:[^:]*]]: memref<?xf32>, %[[T:[^:]*]]: memref<?xf32>
// HIP-SAME:      workgroup(%[[SLOTS:.*]] : memref<3xi32, #gpu.address_space<workgroup>>) kernel
//                The own state lives in a private element (a register).
// HIP-DAG:     %[[OWN:.*]] = memref.alloca() : memref<1xf32>
// HIP-DAG:     %[[BEGIN:.*]] = memref.load %[[CLOCK]][%c0]
// HIP-DAG:     %[[SIZE:.*]] = memref.load %[[CLOCK]][%c1]
// HIP:         scf.if
// HIP:           gpu.barrier
// HIP:           %[[END:.*]] = arith.addi %[[BEGIN]], %[[SIZE]]
// HIP:           scf.for
//                  Own state at T into the register, once.
// HIP:             scf.if
// HIP-NEXT:          arith.addi
// HIP-NEXT:          %[[INITIAL:.*]] = memref.load %[[T]]
// HIP-NEXT:          memref.store %[[INITIAL]], %[[OWN]]
// HIP:             scf.while
// HIP:             ^bb0(%[[TIME:.*]]: i64):
// HIP:               %[[LEFT:.*]] = arith.subi %[[END]], %[[TIME]]
// HIP:               %[[LAST:.*]] = arith.cmpi eq, %[[LEFT]], %c1_i64
// HIP:               scf.if %[[LAST]] -> (i64) {
//                      One base step left (m = 1, or the last sub-step):
//                      no num_steps, no reduction.
// HIP-NEXT:            scf.yield %c1_i64 : i64
// HIP-NEXT:          } else {
// HIP:                 %[[WARP:.*]] = gpu.subgroup_reduce minsi %{{.*}} uniform : (i32) -> i32
// HIP:                 memref.atomic_rmw mins %[[WARP]], %[[SLOTS]]
// HIP-NEXT:            }
// HIP-NEXT:            gpu.barrier
// HIP-NEXT:            memref.load %[[SLOTS]]
// HIP-NOT:             gpu.barrier
//                    The interpolated read of @Q: both halves; the own
//                    state from the register, never from memory.
// HIP:               memref.load %[[OWN]]
// HIP:               memref.load %[[Q]]
// HIP:               memref.load %[[Q]]
// HIP-NOT:           memref.load %[[T]]
// HIP-NOT:           memref.store %{{.*}}, %[[T]]
// HIP:               memref.store %{{.*}}, %[[OWN]]
// HIP:               scf.yield
// HIP:             }
//                  The target half, once, after the sub-steps.
// HIP:             scf.if
// HIP-NEXT:          %[[FINAL:.*]] = memref.load %[[OWN]]
// HIP-NEXT:          arith.addi
// HIP-NEXT:          memref.store %[[FINAL]], %[[T]]
// HIP:           gpu.subgroup_reduce add
// HIP-LABEL: simplan.plan @rod strategy("hip") {{.*}} max_steps(4) step_cap(4)
// HIP:         simplan.component @Heater writes [@Q] evaluations(8) advance whole_step estimates{{$}}
// HIP-NEXT:    simplan.component @Rod writes [@T] evaluations(9) advance group_substeps{{$}}
// HIP:         simplan.phase step {
// HIP-NEXT:      simplan.launch @rod_kernels::@estimate_Heater items
// HIP-NEXT:      simplan.launch @rod_kernels::@advance single
// HIP-NEXT:      simplan.launch @rod_kernels::@evaluate_Heater items
// HIP-NEXT:      simplan.launch @rod_kernels::@substep_Rod items
