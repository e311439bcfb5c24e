// A launch's total argument must name a simplan.total of the plan.
//
// RUN: sim-opt %s --split-input-file --verify-diagnostics --allow-unregistered-dialect

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @total_E(%arg0: memref<?xf64>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.buffer @E : f64 stride(8)
    simplan.phase total {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<total @E>, but the plan has no total @E}}
      simplan.launch @k::@total_E items [#simplan.arg<total @E>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @total_E(%arg0: i64) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.total @E : f64
    simplan.phase total {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<total @E> as argument 0 of type 'i64'}}
      simplan.launch @k::@total_E items [#simplan.arg<total @E>]
    }
  }
}

// -----

// expected-error @+1 {{a 'total' argument names a symbol}}
"test.op"() {arg = #simplan.arg<total>} : () -> ()
