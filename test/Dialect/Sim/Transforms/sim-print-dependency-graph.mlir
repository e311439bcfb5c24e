// RUN: sim-opt %s --sim-print-dependency-graph -o /dev/null | FileCheck %s --check-prefix=TEXT
// RUN: sim-opt %s --sim-print-dependency-graph=format=dot -o /dev/null | FileCheck %s --check-prefix=DOT
// RUN: %if dot %{ sim-opt %s --sim-print-dependency-graph=format=dot -o /dev/null | dot -Tsvg | FileCheck %s --check-prefix=SVG %}

// The printer does not change the IR, and also prints a graph whose schedule
// is still undetermined (second simulation).

// TEXT-LABEL: dependency graph of @waves: 3 components, 3 buffers
// TEXT-NEXT:   schedule: @Push, @Spread, @Relax
// TEXT-NEXT:   hip step bounded by: @Push
// TEXT-NEXT:   traditional step bounded by: @Push, @Relax
// TEXT-NEXT:   component @Push writes @P
// TEXT-NEXT:     num_steps reads: @P[i] own
// TEXT-NEXT:     evaluate reads: @P[i] own, @R[i+2] back_edge
// TEXT-NEXT:     sub-stepping: in_kernel
// TEXT-NEXT:   component @Spread writes @S
// TEXT-NEXT:     evaluate reads: @P[i-2..i+2] interpolate, @S[i-1] own
// TEXT-NEXT:     sub-stepping: grid_sync
// TEXT-NEXT:   component @Relax writes @R
// TEXT-NEXT:     num_steps reads: nothing
// TEXT-NEXT:     evaluate reads: @S[gather] interpolate
// TEXT-NEXT:     sub-stepping: in_kernel
// TEXT-NEXT:   buffer @P : f32 interp #sim.linear, written by @Push
// TEXT-NEXT:     init reads: nothing
// TEXT-NEXT:   buffer @S : vector<2xf32> interp #sim.cubic, written by @Spread
// TEXT-NEXT:     init reads: nothing
// TEXT-NEXT:   buffer @R : f32 interp #sim.linear, written by @Relax
// TEXT-NEXT:     init reads: @P[i]
// TEXT-NEXT:     exact reads: nothing
// TEXT-NEXT:   edges:
// TEXT-NEXT:     @Relax -> @Push via @R[i+2] back_edge
// TEXT-NEXT:     @Push -> @Spread via @P[i-2..i+2] interpolate
// TEXT-NEXT:     @Spread -> @Relax via @S[gather] interpolate

// TEXT-LABEL: dependency graph of @open: 2 components, 2 buffers
// TEXT-NEXT:   schedule: undetermined (--sim-schedule reports why)
// TEXT:        edges:
// TEXT-NEXT:     @B -> @A via @Y[i]
// TEXT-NEXT:     @A -> @B via @X[i]{{$}}

// DOT-LABEL: digraph "waves" {
// DOT-DAG: "c_Push" [shape=box, label="@Push\n#0\nbounds the hip step"];
// DOT-DAG: "c_Spread" [shape=box, label="@Spread\n#1\ngrid_sync"];
// DOT-DAG: "b_S" [shape=ellipse, label="@S\nvector<2xf32>"];
// DOT-DAG: "c_Push" -> "b_P" [label="writes"];
// DOT-DAG: "b_R" -> "c_Push" [label="i+2\nback_edge", style=dashed, color=purple, fontcolor=purple];
// DOT-DAG: "b_P" -> "c_Spread" [label="i-2..i+2\ninterpolate"];
// DOT: }
// DOT-LABEL: digraph "open" {
// DOT: "b_X" -> "c_B" [label="i"];

// SVG: <svg
// SVG: waves
// SVG: <svg
// SVG: open

// Parameters are run-time values: an offset computed from one (directly, or
// as the bound of a loop) is not bounded, whatever its default or the range
// its type allows; a parameter that only scales the read value does not
// matter.
// TEXT-LABEL: dependency graph of @params: 2 components, 5 buffers
// TEXT:        component @Reader writes @R
// TEXT-NEXT:     evaluate reads: @A[gather] interpolate, @B[gather] interpolate, @C[i-1..i+1] interpolate, @D[gather] interpolate

sim.simulation @waves range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @P : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @S : vector<2xf32> interp(#sim.cubic) init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %p = sim.read @P[%i] : f32
    sim.yield %p : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Push writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %p = sim.read @P[%i] : f32
    %n = arith.fptosi %p : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : f32
    %c2 = arith.constant 2 : index
    %j = arith.addi %c2, %i : index
    %r = sim.read @R[%j] : f32
    %s = arith.addf %p, %r : f32
    sim.yield %s : f32
  }
  sim.component @Spread writes(@S) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -2 : index
    %hi = arith.constant 3 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> f32 {
      %j = arith.addi %i, %k : index
      %p = sim.read @P[%j] : f32
      %a = arith.addf %acc, %p : f32
      scf.yield %a : f32
    }
    %left = arith.subi %i, %one : index
    %old = sim.read @S[%left] : vector<2xf32>
    %b = vector.broadcast %sum : f32 to vector<2xf32>
    %new = arith.addf %old, %b : vector<2xf32>
    sim.yield %new : vector<2xf32>
  }
  sim.component @Relax writes(@R) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c3 = arith.constant 3 : index
    %j = arith.remui %i, %c3 : index
    %s = sim.read @S[%j] : vector<2xf32>
    %x = vector.extract %s[0] : f32 from vector<2xf32>
    sim.yield %x : f32
  }
  sim.schedule [@Push]
  sim.observe [@R]
}

sim.simulation @open range(8) dt(1.0e-2 : f32) max_steps(2) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @A writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %y = sim.read @Y[%i] : f32
    sim.yield %y : f32
  }
  sim.component @B writes(@Y) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@Y]
}

sim.simulation @params range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.param @L = 2 : i32
  sim.param @w = 0.5 : f32
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @D : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@A, @B, @C, @D) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = arith.constant 0.0 : f32
    sim.yield %c, %c, %c, %c : f32, f32, f32, f32
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %L = sim.get_param @L : i32
    %l = arith.index_cast %L : i32 to index
    %ja = arith.addi %i, %l : index
    %a = sim.read @A[%ja] : f32
    %zero = arith.constant 0 : index
    %one = arith.constant 1 : index
    %fzero = arith.constant 0.0 : f32
    %b = scf.for %k = %zero to %l step %one iter_args(%acc = %fzero) -> f32 {
      %j = arith.addi %i, %k : index
      %v = sim.read @B[%j] : f32
      %s = arith.addf %acc, %v : f32
      scf.yield %s : f32
    }
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %c = scf.for %k = %lo to %hi step %one iter_args(%acc = %fzero) -> f32 {
      %j = arith.addi %i, %k : index
      %v = sim.read @C[%j] : f32
      %w = sim.get_param @w : f32
      %vw = arith.mulf %v, %w : f32
      %s = arith.addf %acc, %vw : f32
      scf.yield %s : f32
    }
    %range = sim.get_param @range : i64
    %r = arith.index_cast %range : i64 to index
    %c2 = arith.constant 2 : index
    %half = arith.divui %r, %c2 : index
    %jd = arith.subi %i, %half : index
    %d = sim.read @D[%jd] : f32
    %ab = arith.addf %a, %b : f32
    %abc = arith.addf %ab, %c : f32
    %sum = arith.addf %abc, %d : f32
    sim.yield %sum : f32
  }
  sim.observe [@R]
}

// An index a body clamps around its own item is a window whatever it
// clamps (here a neighbour list's entry read from @N): `min(max(%g, %i -
// 2), %i + 3)` reaches i-2..i+3. A bound on one side only, an unsigned
// clamp (it orders `%i - 2` at item 0 above every item) or a bound taken
// from a parameter leave a gather.
// TEXT-LABEL: dependency graph of @clamped: 2 components, 8 buffers
// TEXT:        component @Reader writes @R
// TEXT-NEXT:     evaluate reads: @N[i] interpolate, @A[i-2..i+3] interpolate, @B[i-1..i] interpolate, @C[i..i+1] interpolate, @D[gather] interpolate, @E[gather] interpolate, @F[gather] interpolate

sim.simulation @clamped range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.param @w = 2 : i64
  sim.buffer @N : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @D : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @E : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @F : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @R : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Source writes(@N, @A, @B, @C, @D, @E, @F) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = arith.constant 0.0 : f32
    sim.yield %c, %c, %c, %c, %c, %c, %c : f32, f32, f32, f32, f32, f32, f32
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %nf = sim.read @N[%i] : f32
    %n64 = arith.fptosi %nf : f32 to i64
    %g = arith.index_cast %n64 : i64 to index
    %c0 = arith.constant 0 : index
    %c1 = arith.constant 1 : index
    %c2 = arith.constant 2 : index
    %c3 = arith.constant 3 : index
    %below = arith.subi %i, %c2 : index
    %above = arith.addi %i, %c3 : index
    %atLeast = arith.maxsi %g, %below : index
    %ja = arith.minsi %atLeast, %above : index
    %a = sim.read @A[%ja] : f32
    %left = arith.subi %i, %c1 : index
    %jb = arith.maxsi %left, %c0 : index
    %b = sim.read @B[%jb] : f32
    %last = arith.constant 63 : index
    %atEnd = arith.cmpi eq, %i, %last : index
    %right = arith.addi %i, %c1 : index
    %jc = arith.select %atEnd, %i, %right : index
    %c = sim.read @C[%jc] : f32
    %jd = arith.minsi %g, %above : index
    %d = sim.read @D[%jd] : f32
    %atLeastU = arith.maxui %g, %below : index
    %je = arith.minui %atLeastU, %above : index
    %e = sim.read @E[%je] : f32
    %w64 = sim.get_param @w : i64
    %w = arith.index_cast %w64 : i64 to index
    %belowW = arith.subi %i, %w : index
    %atLeastW = arith.maxsi %g, %belowW : index
    %jf = arith.minsi %atLeastW, %above : index
    %f = sim.read @F[%jf] : f32
    %ab = arith.addf %a, %b : f32
    %abc = arith.addf %ab, %c : f32
    %de = arith.addf %d, %e : f32
    %def = arith.addf %de, %f : f32
    %s0 = arith.addf %abc, %def : f32
    %s = arith.addf %s0, %nf : f32
    sim.yield %s : f32
  }
  sim.observe [@R]
}
