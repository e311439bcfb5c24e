// The whole front end (--sim-front-end: prune, schedule, sub-step legality,
// memory plan, interpolation insertion) on the paper's three scenes. Every
// component of these scenes reads its own buffer only at its own item, so
// under hip all sub-steps stay in one kernel with the state in registers:
// no snapshot, no parity copy. No view read is left in a component.
//
// RUN: sim-opt %examples/paper/fig5.mlir --sim-front-end | FileCheck %s --check-prefix=FIG5 --implicit-check-not=sim.read --implicit-check-not=snapshot --implicit-check-not=copy_if_even
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-front-end | FileCheck %s --check-prefix=GRAVITY --implicit-check-not=sim.read --implicit-check-not=snapshot --implicit-check-not=copy_if_even
// RUN: sim-opt %examples/paper/pbd_like.mlir --sim-front-end | FileCheck %s --check-prefix=PBD --implicit-check-not=sim.read --implicit-check-not=snapshot --implicit-check-not=copy_if_even
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-front-end=strategy=hip-cache | FileCheck %s --check-prefix=GRAVITY-CACHE
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-front-end=strategy=simple | FileCheck %s --check-prefix=SIMPLE --implicit-check-not=sim.read --implicit-check-not=sim.big_step
//
// The memory reports shown in docs/MemoryPlans.md:
// RUN: sim-opt %examples/paper/fig5.mlir --sim-front-end --sim-report-memory -o /dev/null | FileCheck %s --check-prefix=FIG5-MEM
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-front-end --sim-report-memory -o /dev/null | FileCheck %s --check-prefix=GRAVITY-MEM
// RUN: sim-opt %examples/paper/pbd_like.mlir --sim-front-end=strategy=hip-cache --sim-report-memory -o /dev/null | FileCheck %s --check-prefix=PBD-MEM

// C0 reads B3 through the back edge: it bounds the big step and takes it
// in one evaluation; the others sub-step in one kernel each.
// FIG5-LABEL: sim.simulation @fig5 {{.*}} attributes {step_cap = 3 : i32, strategy = #sim<strategy hip>}
// FIG5-LABEL: sim.component @C0 writes(@B0) attributes {advance = #sim<advance whole_step>, estimates, parity = #sim<parity none>, sub_stepping = #sim<sub_stepping in_kernel>}
// FIG5: } evaluate {
// FIG5: sim.load local @B0[%i] : f32
// FIG5: sim.load source @B3[%i] : f32
// FIG5-LABEL: sim.component @C1 writes(@B1) attributes {advance = #sim<advance group_substeps>, parity
// FIG5: } evaluate {
// FIG5-NEXT: ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
// FIG5-NEXT: %begin, %size = sim.big_step : i64, i64
// FIG5: %[[F:.*]] = arith.divf
// FIG5: sim.load target @B0[%i] : f32
// FIG5: } else {
// FIG5: sim.load source @B0[%i] : f32
// FIG5: } else {
// FIG5-NEXT: %[[A:.*]] = sim.load source @B0[%i] : f32
// FIG5-NEXT: %[[B:.*]] = sim.load target @B0[%i] : f32
// FIG5: arith.mulf %{{.*}}, %[[A]] : f32
// FIG5: arith.mulf %[[F]], %[[B]] : f32
// FIG5-LABEL: sim.component @C2
// FIG5: scf.for
// FIG5: sim.load source @B1[
// FIG5: sim.load target @B1[
// FIG5-LABEL: sim.component @C4
// FIG5: sim.load source @B3[%i] : f32
// FIG5: sim.load target @B3[%i] : f32
// FIG5: sim.schedule [@C0, @C1, @C2, @C3, @C4] bounded_by [@C0]

// GRAVITY-LABEL: sim.component @C0
// GRAVITY: sim.load local @B0[%i] : vector<4xf32>
// GRAVITY: sim.load source @B2[%i] : vector<4xf32>
// GRAVITY-LABEL: sim.component @C1
// GRAVITY: scf.for
// GRAVITY: sim.load target @B0[%[[J:.*]]] : vector<4xf32>
// GRAVITY: sim.load source @B0[%[[J]]] : vector<4xf32>
// GRAVITY: } else {
// GRAVITY-NEXT: %[[A:.*]] = sim.load source @B0[%[[J]]] : vector<4xf32>
// GRAVITY-NEXT: %[[B:.*]] = sim.load target @B0[%[[J]]] : vector<4xf32>
// GRAVITY: vector.broadcast
// GRAVITY-LABEL: sim.component @C2
// GRAVITY: sim.load local @B2[%i] : vector<4xf32>
// GRAVITY: sim.load source @B0[
// GRAVITY: sim.load target @B0[
// GRAVITY: sim.load source @B1[
// GRAVITY: sim.load target @B1[
// GRAVITY: sim.schedule [@C0, @C1, @C2] bounded_by [@C0]

// The paper's cubic (B3, B4) on vec4 elements, linear elsewhere.
// PBD-LABEL: sim.component @C0
// PBD: sim.load source @B6[%i] : vector<4xf32>
// PBD-LABEL: sim.component @C4
// PBD: sim.load source @B3[
// PBD: sim.load target @B3[
// PBD: arith.constant 3.000000e+00 : f32
// PBD-LABEL: sim.component @C6
// PBD: sim.load local @B6[%i] : vector<4xf32>
// PBD: sim.load source @B5[
// PBD: sim.schedule [@C0, @C1, @C2, @C3, @C4, @C5, @C6] bounded_by [@C0]

// One evaluation per big step: interpolated reads take the target in
// evaluate and the source in num_steps; no fraction is computed.
// SIMPLE-LABEL: sim.simulation @gravity_like {{.*}} attributes {step_cap = 1 : i32, strategy = #sim<strategy simple>}
// SIMPLE-LABEL: sim.component @C1
// SIMPLE: sim.load target @B0[
// SIMPLE-NOT: sim.load source @B0
// SIMPLE-LABEL: sim.component @C2

// FIG5-MEM:      memory plan of @fig5 (strategy hip, 1024 items)
// FIG5-MEM:      planned device memory                             40960 (40.00 KiB)
// FIG5-MEM-NEXT: naive plan (3 copies of every buffer)            61440 (60.00 KiB)
// FIG5-MEM-NEXT: saved                                            20480 (33.3%)
// FIG5-MEM-NEXT: shared-memory caches: none

// GRAVITY-MEM:      memory plan of @gravity_like (strategy hip, 65536 items)
// GRAVITY-MEM-COUNT-3: vector<4xf32>            16        2097152              0        2097152
// GRAVITY-MEM-NEXT: planned device memory                           6291456 (6.00 MiB)
// GRAVITY-MEM-NEXT: naive plan (3 copies of every buffer)           9437184 (9.00 MiB)

// Under hip-cache @C1 caches its window of @B0, @C2 those of @B0 and @B1
// (each i-4..i+4); @C0 reads only at its own item and through the back edge.
// GRAVITY-CACHE-LABEL: sim.simulation @gravity_like
// GRAVITY-CACHE-SAME: attributes {step_cap = 3 : i32, strategy = #sim<strategy "hip-cache">}
// GRAVITY-CACHE: sim.component @C0 writes(@B0) attributes {advance = #sim<advance whole_step>, estimates, parity
// GRAVITY-CACHE: sim.component @C1 writes(@B1) attributes {advance = #sim<advance group_substeps>, caches = [#sim.cache<@B0, -4, 4>], parity
// GRAVITY-CACHE: sim.component @C2 writes(@B2) attributes {advance = #sim<advance group_substeps>, caches = [#sim.cache<@B0, -4, 4>, #sim.cache<@B1, -4, 4>], parity

// Under hip-cache every component caches the buffers it interpolates through
// windows i-4..i+4: one vec4 per thread of a 256-thread group plus 8 of
// halo each. @C2 reads @B0 only at its own item, which is not worth a cache.
// PBD-MEM:      memory plan of @pbd_like (strategy hip-cache, 65536 items)
// PBD-MEM:      planned device memory                          14680064 (14.00 MiB)
// PBD-MEM-NEXT: naive plan (3 copies of every buffer)          22020096 (21.00 MiB)
// PBD-MEM:      shared-memory caches (256 threads per group):
// PBD-MEM-NEXT:   @C1                4224 bytes per group
// PBD-MEM-NEXT:   @C2                4224 bytes per group
// PBD-MEM-NEXT:   @C3                4224 bytes per group
// PBD-MEM-NEXT:   @C4                4224 bytes per group
// PBD-MEM-NEXT:   @C5                8448 bytes per group
// PBD-MEM-NEXT:   @C6                4224 bytes per group
