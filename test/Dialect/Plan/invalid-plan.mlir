// RUN: sim-opt %s --split-input-file --verify-diagnostics --allow-unregistered-dialect

// Errors of the plan, its symbols and its clock (PlanOps.cpp and the ODS
// constraints of plan, param, buffer, component, total, phase and repeat).

// expected-error @+1 {{'simplan.plan' op has a clock of 12 slots, too small for its histogram}}
simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(4) step_cap(4) group_size(32) clock_slots(12) histogram(8) {
}

// -----

// expected-error @+1 {{'simplan.plan' op has a step cap of 3, which is not between 1 and max_steps (2)}}
simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(3) group_size(32) clock_slots(11) histogram(8) {
}

// -----

// expected-error @+1 {{'simplan.plan' op has a step cap of 0, which is not between 1 and max_steps (2)}}
simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(0) group_size(32) clock_slots(11) histogram(8) {
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(11) histogram(9) {
  // expected-error @+1 {{'test.op' op cannot appear directly in a plan}}
  "test.op"() : () -> ()
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(11) histogram(9) {
  simplan.phase step {
  }
  // expected-error @+1 {{'simplan.phase' op repeats phase 'step' of the plan}}
  simplan.phase step {
  }
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(11) histogram(9) {
  // expected-error @+1 {{'simplan.component' op counts its evaluations in clock slot 5, which is not between the fixed slots and the histogram [8, 9)}}
  simplan.component @C writes [] evaluations(5) advance whole_step
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(11) histogram(9) {
  // expected-error @+1 {{'simplan.component' op counts its evaluations in clock slot 9, which is not between the fixed slots and the histogram [8, 9)}}
  simplan.component @C writes [] evaluations(9) advance whole_step
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(15) histogram(12) {
  // expected-error @+1 {{'simplan.component' op has a sub-step clock at slots 9 to 12, which are not between the fixed slots and the histogram [8, 12)}}
  simplan.component @C writes [] evaluations(8) advance grid_substeps sub_clock(9)
}

// -----

// Local time steps keep two more slots in the sub-step clock than grid-wide
// sub-steps (Unit and UnitRequest).
simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op has a sub-step clock at slots 9 to 14, which are not between the fixed slots and the histogram [8, 13)}}
  simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9)
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op advances in grid_substeps but has no sub_clock}}
  simplan.component @C writes [] evaluations(8) advance grid_substeps
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op has a sub_clock but advances in group_substeps; only grid_substeps and local_steps components have one}}
  simplan.component @C writes [] evaluations(8) advance group_substeps sub_clock(9)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) distributed halo(1) {
  // expected-error @+1 {{'simplan.component' op has a level_reach but advances in grid_substeps; only local_steps components have levels}}
  simplan.component @C writes [] evaluations(8) advance grid_substeps sub_clock(9) level_reach(40)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) distributed halo(1) {
  // expected-error @+1 {{'simplan.component' op has a level_reach of 0; it must be at least 1}}
  simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9) level_reach(0)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op has a level_reach in a plan that is not distributed}}
  simplan.component @C writes [] evaluations(8) advance local_steps sub_clock(9) level_reach(40)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op keeps levels but advances in grid_substeps; only local_steps components have levels}}
  simplan.component @C writes [] evaluations(8) advance grid_substeps sub_clock(9) keeps_levels
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op has a largest_estimate but advances in whole_step; only a pair's writer (local_flux) that estimates bounds the big step by its largest num_steps}}
  simplan.component @C writes [] evaluations(8) advance whole_step estimates largest_estimate(9)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op has a largest_estimate but does not estimate; only a pair's writer (local_flux) that estimates bounds the big step by its largest num_steps}}
  simplan.component @E writes [] evaluations(8) advance local_flux largest_estimate(9)
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op estimates and advances in local_flux but has no largest_estimate slots}}
  simplan.component @E writes [] evaluations(8) advance local_flux estimates
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op keeps its estimate but has no largest_estimate}}
  simplan.component @E writes [] evaluations(8) advance local_flux keeps_estimate
}

// -----

simplan.plan @p strategy("lts") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(16) histogram(13) {
  // expected-error @+1 {{'simplan.component' op keeps its largest estimate in clock slots 11 to 13, which are not between the fixed slots and the histogram [8, 13)}}
  simplan.component @E writes [] evaluations(8) advance local_flux estimates largest_estimate(11)
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(12) histogram(9) {
  // expected-error @+1 {{custom op 'simplan.component' unknown keyword 'sideways'}}
  simplan.component @C writes [] evaluations(8) advance sideways
}

// -----

// expected-error @+1 {{custom op 'simplan.phase' unknown keyword 'later'}}
simplan.phase later {
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(12) histogram(9) {
  // expected-error @+1 {{invalid properties {advance = #sim<sub_stepping grid_sync>, evaluations = 8 : i64, sym_name = "C", writes = []} for op simplan.component: Invalid attribute `advance` in property conversion: #sim<sub_stepping grid_sync>}}
  "simplan.component"() <{sym_name = "C", writes = [], evaluations = 8 : i64, advance = #sim<sub_stepping grid_sync>}> : () -> ()
}

// -----

// expected-error @+1 {{invalid properties {clock_slots = 10 : i64, dt = 1.000000e+00 : f32, group_size = 32 : i64, histogram_slot = 8 : i64, kernels = @k, max_steps = 1 : i64, range = 4 : i64, step_cap = 1 : i64, strategy = 2 : i32, sym_name = "p"} for op simplan.plan: Invalid attribute `strategy` in property conversion: 2 : i32}}
"simplan.plan"() <{sym_name = "p", strategy = 2 : i32, kernels = @k, range = 4 : i64, dt = 1.0 : f32, max_steps = 1 : i64, step_cap = 1 : i64, group_size = 32 : i64, clock_slots = 10 : i64, histogram_slot = 8 : i64}> ({
}) : () -> ()

// -----

// expected-error @+1 {{'simplan.plan' op requires attribute 'step_cap'}}
"simplan.plan"() <{sym_name = "p", strategy = "simple", kernels = @k, range = 4 : i64, dt = 1.0 : f32, max_steps = 1 : i64, group_size = 32 : i64, clock_slots = 10 : i64, histogram_slot = 8 : i64}> ({
}) : () -> ()

// -----

// expected-error @+1 {{'simplan.plan' op region #0 ('body') failed to verify constraint: region with 1 blocks}}
"simplan.plan"() <{sym_name = "p", strategy = "simple", kernels = @k, range = 4 : i64, dt = 1.0 : f32, max_steps = 1 : i64, step_cap = 1 : i64, group_size = 32 : i64, clock_slots = 10 : i64, histogram_slot = 8 : i64}> ({
}) : () -> ()

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
  // expected-note @+1 {{see existing symbol definition here}}
  simplan.buffer @X : f32 stride(4)
  // expected-error @+1 {{redefinition of symbol named 'X'}}
  simplan.param @X = 1 : i32
}

// -----

// expected-error @+1 {{'simplan.param' op expects parent op 'simplan.plan'}}
simplan.param @k = 1.0 : f32

// -----

// expected-error @+1 {{'simplan.buffer' op expects parent op 'simplan.plan'}}
simplan.buffer @X : f32 stride(4)

// -----

// expected-error @+1 {{'simplan.component' op expects parent op 'simplan.plan'}}
simplan.component @C writes [] evaluations(8) advance whole_step

// -----

// expected-error @+1 {{'simplan.total' op expects parent op 'simplan.plan'}}
simplan.total @E : f64

// -----

// expected-error @+1 {{'simplan.phase' op expects parent op 'simplan.plan'}}
simplan.phase init {
}

// -----

// expected-error @+1 {{'simplan.repeat' op expects parent op to be one of 'simplan.phase, simplan.repeat'}}
simplan.repeat 2 {
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
  simplan.phase step {
    // expected-error @+1 {{'simplan.repeat' op attribute 'count' failed to satisfy constraint: 64-bit signless integer attribute whose minimum value is 1}}
    simplan.repeat 0 {
    }
  }
}

// -----

simplan.plan @p strategy("simple") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(1) step_cap(1) group_size(32) clock_slots(10) histogram(8) {
  // expected-error @+1 {{'simplan.phase' op region should have no arguments}}
  "simplan.phase"() <{kind = #simplan<phase step>}> ({
  ^bb0(%x: i32):
  }) : () -> ()
}

// -----

// Halos count ghost items below and above a rank's block.
// expected-error @+1 {{'simplan.plan' op has a distributed halo of -3 items; it must be 0 or more}}
simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(11) histogram(8) distributed halo(-3) {
}

// -----

simplan.plan @p strategy("hip") kernels(@k) range(4) dt(1.0e-2 : f32) max_steps(2) step_cap(2) group_size(32) clock_slots(11) histogram(8) distributed halo(5) {
  // expected-error @+1 {{'simplan.buffer' op expects a halo of two counts of items (below and above), 0 or more}}
  simplan.buffer @B : f64 stride(8) halo [-5, 5]
}
