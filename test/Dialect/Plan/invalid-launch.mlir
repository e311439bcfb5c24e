// RUN: sim-opt %s --split-input-file --verify-diagnostics --allow-unregistered-dialect

// Errors of launches (LaunchOp::verifySymbolUses and the ODS constraints):
// the kernel, its arguments, the symbols they name, and the records of the
// kernel function. invalid-total.mlir has the errors of total arguments.

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op launches @k::@init, but there is no kernel container @k}}
      simplan.launch @k::@init single [#simplan.arg<clock>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op launches @k::@init, which is not a kernel function}}
      simplan.launch @k::@init single [#simplan.arg<clock>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: memref<?xi64>, %range: i64) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes 1 arguments to @k::@init, which takes 2}}
      simplan.launch @k::@init single [#simplan.arg<clock>]
    }
  }
}

// -----

// A CPU kernel's trailing group arguments are not launch arguments.
module {
  module @k {
    func.func @init(%clock: memref<?xi64>, %a: i64, %b: i64, %c: i64) attributes {simplan.group_arguments = 3 : i64} {
      return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes 2 arguments to @k::@init, which takes 1}}
      simplan.launch @k::@init single [#simplan.arg<clock>, #simplan.arg<range>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: memref<?xi64>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.buffer @C : f32 stride(4)
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op is for @C, which is not a component of the plan}}
      simplan.launch @k::@init single [#simplan.arg<clock>] for @C
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: memref<?xi64>) kernel attributes {simplan.shared = array<i64: 4, 8>} {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op asks for shared(4, 0), but @k::@init records shared(4, 8)}}
      simplan.launch @k::@init items [#simplan.arg<clock>] shared(4, 0)
    }
  }
}

// -----

// A launch without `shared` asks for none.
module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: memref<?xi64>) kernel attributes {simplan.shared = array<i64: 4, 8>} {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op asks for shared(0, 0), but @k::@init records shared(4, 8)}}
      simplan.launch @k::@init items [#simplan.arg<clock>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: memref<?xi64>) kernel attributes {simplan.clock_slots = 12 : i64} {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op launches @k::@init, which was made for a clock of 12 slots, in a plan whose clock has 10}}
      simplan.launch @k::@init single [#simplan.arg<clock>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%clock: i64) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<clock> as argument 0 of type 'i64'}}
      simplan.launch @k::@init single [#simplan.arg<clock>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%range: memref<?xi64>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<range> as argument 0 of type 'memref<?xi64>'}}
      simplan.launch @k::@init single [#simplan.arg<range>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%x: memref<?xf32>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.param @X = 1 : i32
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<buffer @X>, but the plan has no buffer @X}}
      simplan.launch @k::@init items [#simplan.arg<buffer @X>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%l: i32) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.buffer @L : f32 stride(4)
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<param @L>, but the plan has no parameter @L}}
      simplan.launch @k::@init items [#simplan.arg<param @L>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%x: memref<?xf32>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.buffer @X : f32 stride(4)
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<snapshot @X>, but buffer @X has no snapshot}}
      simplan.launch @k::@init items [#simplan.arg<snapshot @X>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  gpu.module @k {
    gpu.func @init(%x: memref<?xf32>) kernel {
      gpu.return
    }
  }
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.buffer @X : f32 stride(4) snapshot
    simplan.phase exact {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<exact @X>, but buffer @X has no exact solution}}
      simplan.launch @k::@init items [#simplan.arg<exact @X>]
    }
  }
}

// -----

// expected-error @+1 {{'simplan.launch' op expects parent op to be one of 'simplan.phase, simplan.repeat'}}
simplan.launch @k::@init single [#simplan.arg<clock>]

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
  simplan.phase init {
    // expected-error @+1 {{'simplan.launch' op attribute 'args' failed to satisfy constraint: launch arguments}}
    "simplan.launch"() <{kernel = @k::@init, shape = #simplan<shape single>, args = [1 : i32]}> : () -> ()
  }
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
  simplan.phase init {
    // expected-error @+1 {{custom op 'simplan.launch' unknown keyword 'everywhere'}}
    simplan.launch @k::@init everywhere [#simplan.arg<clock>]
  }
}

// -----

// Communication belongs to distributed plans only.
module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op passes #simplan.arg<first>, which only a distributed plan has}}
      simplan.launch @k::@init items [#simplan.arg<clock>, #simplan.arg<first>]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op communicates between ranks in a plan that is not distributed}}
      simplan.launch @k::@advance single [#simplan.arg<clock>] reduce_min [4]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op all-reduces clock slot 10, but the clock has 10 slots}}
      simplan.launch @k::@advance single [#simplan.arg<clock>] reduce_min [10]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op exchanges @Y, which is not a buffer of the plan}}
      simplan.launch @k::@init_X items [#simplan.arg<buffer @X>, #simplan.arg<first>] exchange [@Y]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.phase init {
      // expected-error @+1 {{'simplan.launch' op exchanges the snapshot of @X, which has none}}
      simplan.launch @k::@init_X items [#simplan.arg<buffer @X>, #simplan.arg<first>] exchange_snapshots [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op all-reduces the levels of @C, which is not a component of the plan}}
      simplan.launch @k::@limit_levels_C single [#simplan.arg<clock>] reduce_max_levels [@C]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.component @C writes [] evaluations(8) advance whole_step
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op all-reduces the levels of @C, which advances in whole_step; only local_steps components have levels}}
      simplan.launch @k::@limit_levels_C single [#simplan.arg<clock>] reduce_max_levels [@C]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(14) histogram(12) {
    simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op communicates between ranks in a plan that is not distributed}}
      simplan.launch @k::@limit_levels_C single [#simplan.arg<clock>] reduce_max_levels [@C]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X both whole and by its target half}}
      simplan.launch @k::@evaluate_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] exchange [@X] exchange_targets [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) distributed halo(1) {
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @Y, which is not a buffer of the plan}}
      simplan.launch @k::@evaluate_C items [#simplan.arg<first>] exchange_targets [@Y]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.component @C writes [@X] evaluations(8) advance grid_substeps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X both by its target half and by the half its sub-step wrote}}
      simplan.launch @k::@substep_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] for @C exchange_targets [@X] exchange_sub_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(12) histogram(9) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.component @C writes [@X] evaluations(8) advance whole_step
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X by the half its sub-step wrote, but the launch is not for a grid_substeps component, whose sub-step clock says which}}
      simplan.launch @k::@evaluate_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] for @C exchange_sub_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(11) histogram(8) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X by the half its sub-step wrote, but the launch is not for a grid_substeps component, whose sub-step clock says which}}
      simplan.launch @k::@evaluate_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] exchange_sub_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.component @C writes [@X] evaluations(8) advance grid_substeps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X by the blocks and halves its slot wrote, but the launch is not for a local_steps component, whose levels say which}}
      simplan.launch @k::@substep_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] for @C exchange_local_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.component @C writes [@X] evaluations(8) advance local_steps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X by the blocks and halves its slot wrote, but does not pass the levels of @C, which say which}}
      simplan.launch @k::@local_step_C items [#simplan.arg<buffer @X>, #simplan.arg<first>] for @C exchange_local_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @X : f32 stride(4) halo [1, 1]
    simplan.component @C writes [@X] evaluations(8) advance local_steps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @X both whole and by the blocks and halves its slot wrote}}
      simplan.launch @k::@local_step_C items [#simplan.arg<buffer @X>, #simplan.arg<levels @C>, #simplan.arg<first>] for @C exchange [@X] exchange_local_step [@X]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9)
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op reduces the levels of @C, which has no level_reach to say which blocks}}
      simplan.launch @k::@limit_levels_C single [#simplan.arg<clock>] reduce_max_levels [@C]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @F : f32 stride(4) halo [1, 1]
    simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9) level_reach(40)
    simplan.component @E writes [@F] evaluations(10) advance whole_step
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @F by the blocks its slot's fluxes are due in, but the launch is not for a local_flux component}}
      simplan.launch @k::@local_flux_E items [#simplan.arg<buffer @F>, #simplan.arg<levels @C>, #simplan.arg<first>] for @E exchange_local_flux [@F]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @F : f32 stride(4) halo [1, 1]
    simplan.component @E writes [@F] evaluations(10) advance local_flux
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @F by the blocks its slot's fluxes are due in, but passes the levels of 0 components instead of those of the flux pair's reader}}
      simplan.launch @k::@local_flux_E items [#simplan.arg<buffer @F>, #simplan.arg<first>] for @E exchange_local_flux [@F]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) distributed halo(1) {
    simplan.buffer @F : f32 stride(4) halo [1, 1]
    simplan.component @E writes [@F] evaluations(10) advance local_flux
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op exchanges @F both by its target half and by the blocks its slot's fluxes are due in}}
      simplan.launch @k::@local_flux_E items [#simplan.arg<buffer @F>, #simplan.arg<first>] for @E exchange_targets [@F] exchange_local_flux [@F]
    }
  }
}

// -----

module attributes {gpu.container_module} {
  simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(13) histogram(9) {
    simplan.buffer @F : f32 stride(4)
    simplan.component @E writes [@F] evaluations(10) advance local_flux
    simplan.phase step {
      // expected-error @+1 {{'simplan.launch' op communicates between ranks in a plan that is not distributed}}
      simplan.launch @k::@local_flux_E items [#simplan.arg<buffer @F>] for @E exchange_local_flux [@F]
    }
  }
}
