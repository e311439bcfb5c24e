// The whole way from a scene to PTX as one pass pipeline: the front end, the
// lowering of every sim.simulation to GPU kernels and a plan, and the GPU
// back end, each with its options.
//
// RUN: sim-opt %s --dump-pass-pipeline -o /dev/null 2>&1 \
// RUN:   --sim-to-gpu-pipeline="strategy=simple group-size=128 chip=sm_80 features=+ptx80 opt-level=2 cuda-path=%t/cuda" \
// RUN:   | FileCheck %s --check-prefix=PIPELINE
// RUN: sim-opt %s --sim-to-gpu-pipeline | FileCheck %s --implicit-check-not=sim.simulation

// PIPELINE:      builtin.module(
// PIPELINE-NEXT:   sim.simulation(
// PIPELINE:          sim-plan-memory{group-size=128 strategy=simple}
// PIPELINE:          sim-insert-interpolation
// PIPELINE:        ),
// PIPELINE-NEXT:   sim-lower-to-gpu{group-size=128},
// PIPELINE:          sim-nvvm-check-target{attaching=true chip=sm_80 libdevice=}
// PIPELINE:        nvvm-attach-target{O=2 chip=sm_80 {{.*}}features=+ptx80 {{.*}}}
// PIPELINE-NEXT:   gpu.module(
// PIPELINE:          convert-gpu-to-nvvm{{{.*}} has-redux=true
// PIPELINE:          sim-nvvm-check-target{attaching=false chip= libdevice={{.*}}/cuda/nvvm/libdevice/libdevice.10.bc}
// PIPELINE-NEXT:   ),
// PIPELINE-NEXT:   gpu-module-to-binary{format=isa {{.*}}toolkit=}
// PIPELINE-NEXT: )

// CHECK: gpu.binary @decay_kernels [#gpu.object<#nvvm.target<O = 3, chip = "sm_90">
// CHECK-SAME: .visible .entry advance
// CHECK: simplan.plan @decay strategy("hip") kernels(@decay_kernels)

sim.simulation @decay range(1024) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Decay writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 2 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %dx = arith.mulf %h, %x : f32
    %next = arith.subf %x, %dx : f32
    sim.yield %next : f32
  }
  sim.observe [@X]
}
