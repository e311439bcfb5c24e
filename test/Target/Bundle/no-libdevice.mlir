// Without libdevice, kernels that call math functions cannot be made into
// PTX: the bundle holds no PTX for those strategies, says so once, and runs
// on the CPU. Kernels without math functions need no libdevice.
//
// RUN: sim-translate %s --sim-to-bundle --sim-strategies=simple,hip \
// RUN:   --sim-cuda-path=/nonexistent/cuda --verify-diagnostics -o %t.simb
// RUN: %python %S/Inputs/dump-bundle.py %t.simb | FileCheck %s --check-prefix=SECTIONS
// RUN: sim-run %t.simb --steps 5 | FileCheck %s --check-prefix=REPORT
//
// RUN: sim-translate %S/Inputs/decay.mlir --sim-to-bundle --sim-strategies=hip \
// RUN:   --sim-cuda-path=/nonexistent/cuda -o %t.decay.simb 2>&1 \
// RUN:   | FileCheck %s --allow-empty --check-prefix=QUIET
// RUN: %python %S/Inputs/dump-bundle.py %t.decay.simb | FileCheck %s --check-prefix=DECAY

// SECTIONS:      section 0: scene -
// SECTIONS-NEXT: section 1: plan simple
// SECTIONS-NEXT: section 2: cpu simple
// SECTIONS-NEXT: section 3: plan hip
// SECTIONS-NEXT: section 4: cpu hip
// SECTIONS-NOT:  ptx

// REPORT:      scene cooling, strategy hip, backend cpu
// REPORT-NEXT:   (not CUDA: the bundle has no PTX for strategy 'hip')
// REPORT:      big steps

// QUIET-NOT: warning

// DECAY: section 2: ptx hip
// DECAY: --- ptx hip: .target sm_90, {{[0-9]+}} kernels, every one an .entry

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
