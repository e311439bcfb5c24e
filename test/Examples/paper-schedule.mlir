// The paper's three scenes through --sim-schedule and the dependency graph.
// Fig. 5 must give C0, C1, C2, C3, C4 with C0 bounding the step through B3
// (Fig. 6); gravity-like (Fig. 9) and PBD-like (Fig. 10) are bounded by C0,
// which reads the last buffer through the back edge. Every read gets a role:
// --implicit-check-not rejects any read left without one and any back-edge
// read other than those listed.
//
// RUN: sim-opt %examples/paper/fig5.mlir --sim-schedule | FileCheck %s --check-prefix=FIG5 --implicit-check-not=back_edge --implicit-check-not='{{sim.read @[A-Z0-9]+\[[^]]*\] :}}'
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-schedule | FileCheck %s --check-prefix=GRAVITY --implicit-check-not=back_edge --implicit-check-not='{{sim.read @[A-Z0-9]+\[[^]]*\] :}}'
// RUN: sim-opt %examples/paper/pbd_like.mlir --sim-schedule | FileCheck %s --check-prefix=PBD --implicit-check-not=back_edge --implicit-check-not='{{sim.read @[A-Z0-9]+\[[^]]*\] :}}'
// RUN: sim-opt %examples/paper/fig5.mlir --sim-print-dependency-graph -o /dev/null | FileCheck %s --check-prefix=FIG5-GRAPH
// RUN: sim-opt %examples/paper/gravity_like.mlir --sim-print-dependency-graph -o /dev/null | FileCheck %s --check-prefix=GRAVITY-GRAPH
// RUN: sim-opt %examples/paper/pbd_like.mlir --sim-print-dependency-graph -o /dev/null | FileCheck %s --check-prefix=PBD-GRAPH
// RUN: %if dot %{ sim-opt %examples/paper/pbd_like.mlir --sim-print-dependency-graph=format=dot -o /dev/null | dot -Tsvg | FileCheck %s --check-prefix=SVG %}

// FIG5-LABEL: sim.component @C0
// FIG5: sim.read @B0[%i] own
// FIG5: sim.read @B3[%i] back_edge
// FIG5-LABEL: sim.component @C1
// FIG5: sim.read @B0[%i] interpolate
// FIG5-LABEL: sim.component @C2
// FIG5: sim.read @B1[%{{.*}}] interpolate
// FIG5-LABEL: sim.component @C3
// FIG5: sim.read @B2[%i] interpolate
// FIG5-LABEL: sim.component @C4
// FIG5: sim.read @B3[%i] interpolate
// FIG5: sim.schedule [@C0, @C1, @C2, @C3, @C4] bounded_by [@C0]

// GRAVITY-LABEL: sim.component @C0
// GRAVITY: sim.read @B0[%i] own
// GRAVITY: sim.read @B2[%i] back_edge
// GRAVITY-LABEL: sim.component @C1
// GRAVITY-COUNT-4: sim.read @B0[%{{.*}}] interpolate
// GRAVITY-LABEL: sim.component @C2
// GRAVITY: sim.read @B2[%i] own
// GRAVITY: sim.read @B0[%{{.*}}] interpolate
// GRAVITY: sim.read @B1[%{{.*}}] interpolate
// GRAVITY: sim.schedule [@C0, @C1, @C2] bounded_by [@C0]

// PBD-LABEL: sim.component @C0
// PBD: sim.read @B0[%i] own
// PBD: sim.read @B6[%i] back_edge
// PBD-LABEL: sim.component @C6
// PBD: sim.read @B6[%i] own
// PBD: sim.schedule [@C0, @C1, @C2, @C3, @C4, @C5, @C6] bounded_by [@C0]

// FIG5-GRAPH: schedule: @C0, @C1, @C2, @C3, @C4
// FIG5-GRAPH-NEXT: hip step bounded by: @C0
// FIG5-GRAPH: edges:
// FIG5-GRAPH-NEXT: @C3 -> @C0 via @B3[i] back_edge
// FIG5-GRAPH-NEXT: @C0 -> @C1 via @B0[i] interpolate
// FIG5-GRAPH-NEXT: @C1 -> @C2 via @B1[i-1..i+1] interpolate
// FIG5-GRAPH-NEXT: @C2 -> @C3 via @B2[i] interpolate
// FIG5-GRAPH-NEXT: @C3 -> @C4 via @B3[i] interpolate

// GRAVITY-GRAPH: schedule: @C0, @C1, @C2
// GRAVITY-GRAPH-COUNT-3: sub-stepping: in_kernel
// GRAVITY-GRAPH: edges:
// GRAVITY-GRAPH-NEXT: @C2 -> @C0 via @B2[i] back_edge
// GRAVITY-GRAPH-NEXT: @C0 -> @C1 via @B0[i-4..i+4] interpolate
// GRAVITY-GRAPH-NEXT: @C0 -> @C2 via @B0[i-4..i+4] interpolate
// GRAVITY-GRAPH-NEXT: @C1 -> @C2 via @B1[i-4..i+4] interpolate

// PBD-GRAPH: schedule: @C0, @C1, @C2, @C3, @C4, @C5, @C6
// PBD-GRAPH-COUNT-7: sub-stepping: in_kernel
// PBD-GRAPH: edges:
// PBD-GRAPH-NEXT: @C6 -> @C0 via @B6[i] back_edge
// PBD-GRAPH-NEXT: @C0 -> @C1 via @B0[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C0 -> @C2 via @B0[i] interpolate
// PBD-GRAPH-NEXT: @C1 -> @C2 via @B1[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C2 -> @C3 via @B2[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C3 -> @C4 via @B3[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C4 -> @C5 via @B4[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C3 -> @C5 via @B3[i-4..i+4] interpolate
// PBD-GRAPH-NEXT: @C5 -> @C6 via @B5[i-4..i+4] interpolate

// SVG: <svg
// SVG: pbd_like
