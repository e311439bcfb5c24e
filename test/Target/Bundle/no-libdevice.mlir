// Without libdevice, kernels that call math functions cannot be made into
// PTX: the bundle holds no PTX for those strategies, says so once, and runs
// on the CPU. Kernels without math functions need no libdevice.
//
// RUN: sim-translate %s --sim-to-bundle --sim-strategies=simple,hip \
// RUN:   --sim-cuda-path=/nonexistent/cuda --verify-diagnostics -o %t.simb
// RUN: %python %S/Inputs/dump-bundle.py --flatc %flatc --schema %bundle_schema %t.simb \
// RUN:   | FileCheck %s --check-prefix=PLANS
//
// RUN: sim-translate %S/Inputs/decay.mlir --sim-to-bundle --sim-strategies=hip \
// RUN:   --sim-cuda-path=/nonexistent/cuda -o %t.decay.simb 2>&1 \
// RUN:   | FileCheck %s --allow-empty --check-prefix=QUIET
// RUN: %python %S/Inputs/dump-bundle.py --flatc %flatc --schema %bundle_schema %t.decay.simb \
// RUN:   | FileCheck %s --check-prefix=DECAY
//
// RUN: sim-run %t.simb --steps 5 | FileCheck %s --check-prefix=REPORT

// PLANS:      --- plan 0 Simple
// PLANS:      ptx: none
// PLANS-NEXT: cpu x86-64: shared object, 4 kernels, every one exported
// PLANS-NEXT: cpu x86-64-v3: shared object, 4 kernels, every one exported
// PLANS-NEXT: cpu x86-64-v4: shared object, 4 kernels, every one exported
// PLANS-NEXT: --- plan 1 Hip
// PLANS:      ptx: none
// PLANS-NEXT: cpu x86-64: shared object, 4 kernels, every one exported
// PLANS-NEXT: cpu x86-64-v3: shared object, 4 kernels, every one exported
// PLANS-NEXT: cpu x86-64-v4: shared object, 4 kernels, every one exported
// PLANS-NEXT: --- reference

// REPORT:      scene cooling, strategy hip, backend cpu
// REPORT-NEXT:   (not CUDA: the bundle has no PTX for strategy 'hip')
// REPORT:      big steps

// QUIET-NOT: warning

// DECAY:      --- plan 0 Hip
// DECAY:      ptx: .target sm_90, chip sm_90, 4 kernels, every one an .entry
// DECAY-NEXT: cpu x86-64: shared object, 4 kernels, every one exported
// DECAY-NEXT: cpu x86-64-v3: shared object, 4 kernels, every one exported
// DECAY-NEXT: cpu x86-64-v4: shared object, 4 kernels, every one exported

sim.simulation @cooling range(64) dt(1.0e-2 : f32) max_steps(2) {
  sim.param @rate = 2.0 : f32
  sim.buffer @T : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.component @Cool writes(@T) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %temperature = sim.read @T[%i] : f32
    %rate = sim.get_param @rate : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %rh = arith.mulf %rate, %h : f32
    %minus = arith.negf %rh : f32
    // expected-warning @+1 {{the bundle has no PTX for strategies 'simple', 'hip': the kernels call the libdevice function __nv_expf, but there is no libdevice at '/nonexistent/cuda/nvvm/libdevice/libdevice.10.bc'; they run on the CPU only (give the CUDA toolkit's root with --sim-cuda-path or $CUDA_HOME)}}
    %factor = math.exp %minus : f32
    %next = arith.mulf %temperature, %factor : f32
    sim.yield %next : f32
  }
  sim.observe [@T]
}
