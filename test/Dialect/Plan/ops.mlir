// RUN: sim-opt %s --split-input-file | sim-opt --split-input-file | FileCheck %s
// RUN: sim-opt %s --split-input-file --mlir-print-op-generic | sim-opt --split-input-file | FileCheck %s
// RUN: sim-opt %s --split-input-file --verify-roundtrip

// Round trip of every simplan operation and attribute, in the custom and
// the generic form: a plan with every kind of symbol, phase, launch shape
// and launch argument, and kernels (GPU and CPU) with the records the
// lowering leaves on them.

// CHECK-LABEL: gpu.module @every_kernels
// CHECK:         gpu.func @reset_clock(%{{.*}}: memref<?xi64>) kernel attributes {simplan.clock_slots = 22 : i64, simplan.shared = array<i64: 0, 0>}
// CHECK:         gpu.func @substep_C1(%{{.*}}: memref<?xi64>, %{{.*}}: memref<?xvector<4xf32>>, %{{.*}}: memref<?xvector<4xf32>>, %{{.*}}: i32, %{{.*}}: i64, %{{.*}}: f32) kernel attributes {simplan.clock_slots = 22 : i64, simplan.shared = array<i64: 16, 128>}
// CHECK:         gpu.func @exact_B1(%{{.*}}: memref<?xvector<4xf32>>, %{{.*}}: f64) kernel attributes {simplan.clock_slots = 22 : i64, simplan.shared = array<i64: 0, 0>}
// CHECK:         gpu.func @total_E(%{{.*}}: memref<?xf64>, %{{.*}}: memref<?xf64>) kernel attributes {simplan.clock_slots = 22 : i64, simplan.shared = array<i64: 0, 0>}
// CHECK-LABEL: simplan.plan @every strategy("hip-cache") kernels(@every_kernels) range(65536) dt(1.000000e-03 : f32) max_steps(4) step_cap(4) group_size(256) clock_slots(22) histogram(17) attributes {note = "kept"} {
// CHECK-NEXT:    simplan.param @L = 256 : i32
// CHECK-NEXT:    simplan.param @N = 7 : i64
// CHECK-NEXT:    simplan.param @k = 2.500000e-01 : f64
// CHECK-NEXT:    simplan.buffer @B0 : vector<4xf32> stride(16) snapshot observed exact
// CHECK-NEXT:    simplan.buffer @B1 : vector<4xf32> stride(16) exact
// CHECK-NEXT:    simplan.buffer @B2 : f64 stride(8) observed
// CHECK-NEXT:    simplan.component @C0 writes [@B0] evaluations(8) advance whole_step estimates
// CHECK-NEXT:    simplan.component @C1 writes [@B1, @B2] evaluations(9) advance group_substeps
// CHECK-NEXT:    simplan.component @C2 writes [] evaluations(10) advance grid_substeps estimates sub_clock(11)
// CHECK-NEXT:    simplan.total @E : f64
// CHECK-NEXT:    simplan.phase init {
// CHECK-NEXT:      simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>]
// CHECK-NEXT:    }
// CHECK-NEXT:    simplan.phase step {
// CHECK-NEXT:      simplan.launch @every_kernels::@substep_C1 items [#simplan.arg<clock>, #simplan.arg<buffer @B0>, #simplan.arg<snapshot @B0>, #simplan.arg<param @L>, #simplan.arg<range>, #simplan.arg<dt>] for @C1 shared(16, 128)
// CHECK-NEXT:      simplan.repeat 4 {
// CHECK-NEXT:        simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>] for @C2
// CHECK-NEXT:        simplan.repeat 2 {
// CHECK-NEXT:          simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>]
// CHECK-NEXT:        }
// CHECK-NEXT:      }
// CHECK-NEXT:    }
// CHECK-NEXT:    simplan.phase finish {
// CHECK-NEXT:    }
// CHECK-NEXT:    simplan.phase exact {
// CHECK-NEXT:      simplan.launch @every_kernels::@exact_B1 items [#simplan.arg<exact @B1>, #simplan.arg<time>]
// CHECK-NEXT:    }
// CHECK-NEXT:    simplan.phase total {
// CHECK-NEXT:      simplan.launch @every_kernels::@total_E items [#simplan.arg<total @E>, #simplan.arg<exact @B0>]
// CHECK-NEXT:    }
// CHECK-NEXT:  }
module attributes {gpu.container_module} {
  gpu.module @every_kernels {
    gpu.func @reset_clock(%clock: memref<?xi64>) kernel
        attributes {simplan.shared = array<i64: 0, 0>, simplan.clock_slots = 22 : i64} {
      gpu.return
    }
    gpu.func @substep_C1(%clock: memref<?xi64>, %b0: memref<?xvector<4xf32>>,
                         %s0: memref<?xvector<4xf32>>, %l: i32, %range: i64,
                         %dt: f32) kernel
        attributes {simplan.shared = array<i64: 16, 128>, simplan.clock_slots = 22 : i64} {
      gpu.return
    }
    gpu.func @exact_B1(%out: memref<?xvector<4xf32>>, %time: f64) kernel
        attributes {simplan.shared = array<i64: 0, 0>, simplan.clock_slots = 22 : i64} {
      gpu.return
    }
    gpu.func @total_E(%out: memref<?xf64>, %b0: memref<?xf64>) kernel
        attributes {simplan.shared = array<i64: 0, 0>, simplan.clock_slots = 22 : i64} {
      gpu.return
    }
  }
  simplan.plan @every strategy("hip-cache") kernels(@every_kernels)
      range(65536) dt(1.0e-3 : f32) max_steps(4) step_cap(4) group_size(256)
      clock_slots(22) histogram(17) attributes {note = "kept"} {
    simplan.param @L = 256 : i32
    simplan.param @N = 7 : i64
    simplan.param @k = 0.25 : f64
    simplan.buffer @B0 : vector<4xf32> stride(16) snapshot observed exact
    simplan.buffer @B1 : vector<4xf32> stride(16) exact
    simplan.buffer @B2 : f64 stride(8) observed
    simplan.component @C0 writes [@B0] evaluations(8) advance whole_step estimates
    simplan.component @C1 writes [@B1, @B2] evaluations(9) advance group_substeps
    simplan.component @C2 writes [] evaluations(10) advance grid_substeps estimates sub_clock(11)
    simplan.total @E : f64
    simplan.phase init {
      simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>]
    }
    simplan.phase step {
      simplan.launch @every_kernels::@substep_C1 items
          [#simplan.arg<clock>, #simplan.arg<buffer @B0>,
           #simplan.arg<snapshot @B0>, #simplan.arg<param @L>,
           #simplan.arg<range>, #simplan.arg<dt>] for @C1 shared(16, 128)
      simplan.repeat 4 {
        simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>] for @C2
        simplan.repeat 2 {
          simplan.launch @every_kernels::@reset_clock single [#simplan.arg<clock>]
        }
      }
    }
    simplan.phase finish {
    }
    simplan.phase exact {
      simplan.launch @every_kernels::@exact_B1 items
          [#simplan.arg<exact @B1>, #simplan.arg<time>]
    }
    simplan.phase total {
      simplan.launch @every_kernels::@total_E items
          [#simplan.arg<total @E>, #simplan.arg<exact @B0>]
    }
  }
}

// -----

// A CPU plan: kernels are func.funcs with three trailing group arguments
// that no launch passes; `shared(0, 0)` is the default and not printed; an
// f64 dt; a simple plan's step cap of 1; every plan is a symbol of the
// module.
// CHECK-LABEL: module @cpu_kernels attributes {sim.note}
// CHECK:         func.func @advance(%{{.*}}: memref<?xi64>, %{{.*}}: i64, %{{.*}}: i64, %{{.*}}: i64) attributes {simplan.clock_slots = 11 : i64, simplan.group_arguments = 3 : i64, simplan.shared = array<i64: 0, 0>}
// CHECK-LABEL: simplan.plan @cpu strategy("simple") kernels(@cpu_kernels) range(3) dt(5.000000e-01 : f64) max_steps(2) step_cap(1) group_size(32) clock_slots(11) histogram(8) {
// CHECK-NEXT:    simplan.phase step {
// CHECK-NEXT:      simplan.launch @cpu_kernels::@advance single [#simplan.arg<clock>]{{$}}
// CHECK-NEXT:    }
// CHECK-NEXT:  }
// CHECK-NEXT:  simplan.plan @second
module {
  module @cpu_kernels attributes {sim.note} {
    func.func @advance(%clock: memref<?xi64>, %first: i64, %end: i64,
                       %size: i64)
        attributes {simplan.group_arguments = 3 : i64,
                    simplan.shared = array<i64: 0, 0>,
                    simplan.clock_slots = 11 : i64} {
      return
    }
  }
  simplan.plan @cpu strategy("simple") kernels(@cpu_kernels) range(3)
      dt(0.5 : f64) max_steps(2) step_cap(1) group_size(32) clock_slots(11)
      histogram(8) {
    simplan.phase step {
      simplan.launch @cpu_kernels::@advance single [#simplan.arg<clock>] shared(0, 0)
    }
  }
  simplan.plan @second strategy("simple") kernels(@cpu_kernels) range(3)
      dt(0.5 : f64) max_steps(2) step_cap(1) group_size(32) clock_slots(11)
      histogram(8) {
  }
}

// -----

// Launches of compiled kernels (a gpu.binary has no functions to check
// against).
// CHECK-LABEL: gpu.binary @bin_kernels
// CHECK:       simplan.launch @bin_kernels::@anything items [#simplan.arg<buffer @X>]
module attributes {gpu.container_module} {
  gpu.binary @bin_kernels [#gpu.object<#nvvm.target, "PTX">]
  simplan.plan @bin strategy("traditional") kernels(@bin_kernels) range(8)
      dt(1.0 : f32) max_steps(3) step_cap(3) group_size(64) clock_slots(12)
      histogram(8) {
    simplan.buffer @X : f32 stride(4)
    simplan.phase init {
      simplan.launch @bin_kernels::@anything items [#simplan.arg<buffer @X>]
    }
  }
}

// -----

// A distributed plan: ghost items, the block's first item and extent, and
// the communication around launches.

// CHECK-LABEL: simplan.plan @spread
// CHECK-SAME: histogram(15) distributed halo(2) {
// CHECK: simplan.buffer @X : f32 stride(4) snapshot halo [1, 2]
// CHECK: simplan.launch @k::@init_X items [#simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>] exchange [@X]
// CHECK: simplan.launch @k::@advance single [#simplan.arg<clock>] reduce_min [4]
// CHECK: simplan.launch @k::@snapshot_X items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<snapshot @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] exchange_snapshots [@X]
// CHECK: simplan.launch @k::@substep_C items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @C exchange_sub_step [@X]
// CHECK: simplan.launch @k::@parity_C items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @C exchange_targets [@X]
module attributes {gpu.container_module} {
  gpu.binary @k [#gpu.object<#nvvm.target, "">]
  simplan.plan @spread strategy("hip") kernels(@k) range(100) dt(1.0e-2 : f32) max_steps(4) step_cap(4) group_size(32) clock_slots(20) histogram(15) distributed halo(2) {
    simplan.buffer @X : f32 stride(4) snapshot halo [1, 2]
    simplan.component @C writes [@X] evaluations(8) advance grid_substeps sub_clock(9)
    simplan.phase init {
      simplan.launch @k::@init_X items [#simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>] exchange [@X]
    }
    simplan.phase step {
      simplan.launch @k::@advance single [#simplan.arg<clock>] reduce_min [4]
      simplan.launch @k::@snapshot_X items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<snapshot @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] exchange_snapshots [@X]
      simplan.launch @k::@substep_C items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @C exchange_sub_step [@X]
      simplan.launch @k::@parity_C items [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<range>, #simplan.arg<first>, #simplan.arg<extent>] for @C exchange_targets [@X]
    }
  }
}
