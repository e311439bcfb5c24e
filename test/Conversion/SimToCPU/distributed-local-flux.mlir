// The flux pair of a distributed plan under lts: after each slot of the
// flux writer (local_flux_E) only the target half of the interfaces of
// the blocks where the reader starts a sub-step travels
// (exchange_local_flux): an interface is due only where its coarsest
// reader starts one, and interface j is read by item j (the reader's
// window holds offset 0), whose block's sub-step divides that one's. When
// the window does not hold 0 (the second run: the cells read F[i-1] twice),
// no reader's block says so and the whole target half travels after
// every slot (exchange_targets).
//
// RUN: sim-opt %s --sim-front-end="strategy=lts distributed=true" --sim-lower-to-cpu | FileCheck %s
// RUN: sed 's/sim.read @F\[%i\]/sim.read @F[%il]/' %s \
// RUN:   | sim-opt --sim-front-end="strategy=lts distributed=true" --sim-lower-to-cpu \
// RUN:   | FileCheck %s --check-prefix=NO-OWN

sim.simulation @rod range(100) dt(1.0e-2 : f32) max_steps(8) {
  sim.buffer @U : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.buffer @F : f32 interp(#sim.flux) boundary(clamp) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }
  sim.schedule [@Flux]
  sim.component @Flux writes(@F) num_steps {
  ^bb0(%j: index, %t: i64):
    %j64 = arith.index_cast %j : index to i64
    %c50 = arith.constant 50 : i64
    %stiff = arith.cmpi sge, %j64, %c50 : i64
    %c1 = arith.constant 1 : i32
    %c8 = arith.constant 8 : i32
    %n = arith.select %stiff, %c1, %c8 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%j: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %jr = arith.addi %j, %c1 : index
    %ul = sim.read @U[%j] : f32
    %ur = sim.read @U[%jr] : f32
    %du = arith.subf %ur, %ul : f32
    sim.yield %du : f32
  }
  sim.component @Cells writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %c8 = arith.constant 8 : i32
    sim.yield %c8 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %fw = sim.read @F[%il] : f32
    %fe = sim.read @F[%i] : f32
    %u0 = sim.read @U[%i] : f32
    %d = arith.subf %fe, %fw : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %u1 = math.fma %h, %d, %u0 : f32
    sim.yield %u1 : f32
  }
  sim.observe [@U]
}

// The flux writer's largest estimate, kept (its reader keeps its levels):
// the ranks agree on it by the minimum of its negated value, and no other
// estimate is all-reduced (the runtime skips the slot once it is kept).
// CHECK-LABEL: simplan.plan
// CHECK:         simplan.component @Flux writes [@F] evaluations(8) advance local_flux estimates largest_estimate(16) keeps_estimate
// CHECK:         simplan.launch @rod_kernels::@advance single [#simplan.arg<clock>] reduce_min [16]{{$}}
// CHECK:         simplan.repeat 8 {
// CHECK-NEXT:      simplan.launch @rod_kernels::@local_flux_Flux items [{{.*}}#simplan.arg<levels @Cells>{{.*}}] for @Flux exchange_local_flux [@F]
// CHECK-NEXT:      simplan.launch @rod_kernels::@local_step_Cells items [{{.*}}] for @Cells exchange_local_step [@U]
// CHECK-NEXT:    }

// NO-OWN-LABEL: simplan.plan
// NO-OWN:         simplan.launch @rod_kernels::@local_flux_Flux items [{{.*}}] for @Flux exchange_targets [@F]
// NO-OWN-NOT:     exchange_local_flux
