// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory --sim-insert-interpolation 2>/dev/null | FileCheck %s --check-prefixes=CHECK,HIP
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=simple --sim-insert-interpolation 2>/dev/null | FileCheck %s --check-prefixes=CHECK,ONE
// RUN: sim-opt %s --split-input-file --sim-schedule --sim-substep-legality --sim-plan-memory=strategy=traditional --sim-insert-interpolation 2>/dev/null | FileCheck %s --check-prefixes=CHECK,ONE

// Roles become loads of named copies: own -> local, back_edge -> source.
// Under hip an interpolated read (here in a neighbour loop) becomes the value
// at T (source: the writer keeps its state in registers), the value at T + m
// (target), and linear interpolation at (t + n - T) / m, except at the ends
// of the big step (t + n - T is 0 or m), where it is the copy itself. Under
// simple and traditional it reads the target: the fraction is always 1.

// CHECK-LABEL: sim.simulation @linear_f32
// CHECK: sim.component @First
// CHECK:   } evaluate {
// CHECK-NEXT: ^bb0(%[[I0:.*]]: index,
// CHECK-NOT: sim.big_step
// CHECK:   sim.load local @A[%[[I0]]] : f32
// CHECK:   sim.load source @B[%[[I0]]] : f32
// CHECK: sim.component @Second
// CHECK:   } evaluate {
// CHECK-NEXT: ^bb0(%[[I:.*]]: index, %[[T:.*]]: i64, %[[N:.*]]: i32, %{{.*}}: f32):
// HIP-NEXT:  %[[BEGIN:.*]], %[[SIZE:.*]] = sim.big_step : i64, i64
// HIP-NEXT:  %[[N64:.*]] = arith.extsi %[[N]] : i32 to i64
// HIP-NEXT:  %[[END:.*]] = arith.addi %[[T]], %[[N64]] : i64
// HIP-NEXT:  %[[OFF:.*]] = arith.subi %[[END]], %[[BEGIN]] : i64
// HIP-NEXT:  %[[OFFF:.*]] = arith.sitofp %[[OFF]] : i64 to f32
// HIP-NEXT:  %[[SIZEF:.*]] = arith.sitofp %[[SIZE]] : i64 to f32
// HIP-NEXT:  %[[F:.*]] = arith.divf %[[OFFF]], %[[SIZEF]] : f32
// HIP-NEXT:  %[[ZERO:.*]] = arith.constant 0 : i64
// HIP-NEXT:  %[[START:.*]] = arith.cmpi eq, %[[OFF]], %[[ZERO]] : i64
// HIP-NEXT:  %[[ATEND:.*]] = arith.cmpi eq, %[[OFF]], %[[SIZE]] : i64
// CHECK:     scf.for %[[K:[^ ]+]] =
// CHECK-NEXT:  %[[J:.*]] = arith.addi %[[I]], %[[K]] : index
// HIP-NEXT:    scf.if %[[ATEND]] -> (f32) {
// HIP-NEXT:      %[[AT:.*]] = sim.load target @A[%[[J]]] : f32
// HIP-NEXT:      scf.yield %[[AT]] : f32
// HIP-NEXT:    } else {
// HIP-NEXT:      scf.if %[[START]] -> (f32) {
// HIP-NEXT:        %[[AS:.*]] = sim.load source @A[%[[J]]] : f32
// HIP-NEXT:        scf.yield %[[AS]] : f32
// HIP-NEXT:      } else {
// HIP-NEXT:    %[[A0:.*]] = sim.load source @A[%[[J]]] : f32
// HIP-NEXT:    %[[A1:.*]] = sim.load target @A[%[[J]]] : f32
// HIP-NEXT:    %[[C1:.*]] = arith.constant 1.000000e+00 : f32
// HIP-NEXT:    %[[W0:.*]] = arith.subf %[[C1]], %[[F]] : f32
// HIP-NEXT:    %[[P0:.*]] = arith.mulf %[[W0]], %[[A0]] : f32
// HIP-NEXT:    %[[P1:.*]] = arith.mulf %[[F]], %[[A1]] : f32
// HIP-NEXT:    %{{.*}} = arith.addf %[[P0]], %[[P1]] : f32
// ONE-NEXT:    %{{.*}} = sim.load target @A[%[[J]]] : f32
// CHECK:     sim.load local @C[%[[I]]] : f32
// CHECK-NOT: sim.read
sim.simulation @linear_f32 range(64) dt(1.0e-2 : f32) max_steps(3) {
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
  sim.component @First writes(@A) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    %b = sim.read @B[%i] : f32
    %s = arith.addf %a, %b : f32
    sim.yield %s : f32
  }
  sim.component @Second writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> f32 {
      %j = arith.addi %i, %k : index
      %a = sim.read @A[%j] : f32
      %next = arith.addf %acc, %a : f32
      scf.yield %next : f32
    }
    %c = sim.read @C[%i] : f32
    %r = arith.addf %sum, %c : f32
    sim.yield %r : f32
  }
  sim.component @Third writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c = sim.read @C[%i] : f32
    sim.yield %c : f32
  }
  sim.schedule [@First]
  sim.observe [@B]
}

// -----

// In num_steps an interpolated read is at the start t of the sub-step: the
// fraction has no n. Under simple and traditional estimates read the source.

// CHECK-LABEL: sim.simulation @num_steps_fraction
// CHECK: sim.component @Late
// CHECK-SAME: num_steps {
// CHECK-NEXT: ^bb0(%{{.*}}: index, %[[T:.*]]: i64):
// HIP-NEXT:  %[[BEGIN:.*]], %[[SIZE:.*]] = sim.big_step : i64, i64
// HIP-NEXT:  %[[OFF:.*]] = arith.subi %[[T]], %[[BEGIN]] : i64
// HIP:       sim.load target @E[
// HIP:       sim.load source @E[
// HIP:       sim.load source @E[
// HIP-NEXT:  sim.load target @E[
// ONE-NEXT:  sim.load source @E[
// ONE-NOT:   sim.load target
// CHECK:     } evaluate {
sim.simulation @num_steps_fraction range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @E : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @L : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Early writes(@E) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %e = sim.read @E[%i] : f32
    sim.yield %e : f32
  }
  sim.component @Late writes(@L) num_steps {
  ^bb0(%i: index, %t: i64):
    %e = sim.read @E[%i] : f32
    %n = arith.fptosi %e : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %l = sim.read @L[%i] : f32
    sim.yield %l : f32
  }
  sim.observe [@L]
}

// -----

// Hermite interpolation of @X with derivative @V. Their writer reads its own
// neighbours (grid_sync) and sub-steps (num_steps), so under hip its
// sub-steps ping-pong and both buffers have snapshots: the values at T
// come from them. The span of the big step (m * dt, dt read with
// sim.get_param as a run-time value and converted to the element type)
// scales the derivatives.

// CHECK-LABEL: sim.simulation @hermite_f64
// CHECK: sim.component @Observe
// CHECK:   } evaluate {
// CHECK-NEXT: ^bb0(%[[I:.*]]: index,
// HIP-NEXT:  %[[BEGIN:.*]], %[[SIZE:.*]] = sim.big_step : i64, i64
// HIP:       %[[F:.*]] = arith.divf %{{.*}}, %{{.*}} : f64
// HIP-NEXT:  %[[SIZEF:.*]] = arith.sitofp %[[SIZE]] : i64 to f64
// HIP-NEXT:  %[[DT32:.*]] = sim.get_param @dt : f32
// HIP-NEXT:  %[[DT:.*]] = arith.extf %[[DT32]] : f32 to f64
// HIP-NEXT:  %[[SPAN:.*]] = arith.mulf %[[SIZEF]], %[[DT]] : f64
// At the start of the big step the snapshot, at its end the target.
// HIP:       sim.load target @X[%[[I]]] : f64
// HIP:       sim.load snapshot @X[%[[I]]] : f64
// HIP:       } else {
// HIP-NEXT:  %[[X0:.*]] = sim.load snapshot @X[%[[I]]] : f64
// HIP-NEXT:  %[[X1:.*]] = sim.load target @X[%[[I]]] : f64
// HIP-NEXT:  %[[V0:.*]] = sim.load snapshot @V[%[[I]]] : f64
// HIP-NEXT:  %[[V1:.*]] = sim.load target @V[%[[I]]] : f64
// HIP:       arith.mulf %{{.*}}, %[[SPAN]] : f64
// HIP:       arith.mulf %{{.*}}, %[[V0]] : f64
// HIP:       arith.mulf %{{.*}}, %[[X1]] : f64
// HIP:       arith.mulf %{{.*}}, %[[V1]] : f64
// ONE-NEXT:  sim.load target @X[%[[I]]] : f64
// ONE-NOT:   sim.load {{.*}} @V
// CHECK:     sim.yield
sim.simulation @hermite_f64 range(64) dt(2.5e-1 : f32) max_steps(3) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @O : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Move writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %x = sim.read @X[%i] : f64
    %xr = sim.read @X[%j] : f64
    %v = sim.read @V[%i] : f64
    %x1 = arith.addf %x, %v : f64
    sim.yield %x1, %xr : f64, f64
  }
  sim.component @Observe writes(@O) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.observe [@O]
}

// -----

// A Hermite derivative with another boundary rule than its buffer's: outside
// the range the read is @X's item under @X's rule (zero: none), so @V is
// read at that item, and under zero its value there is 0 (each load would
// apply its own buffer's rule, clamp for @V).

// CHECK-LABEL: sim.simulation @hermite_boundary
// CHECK: sim.component @Observe
// HIP:       %[[RANGE:.*]] = sim.get_param @range : i64
// HIP-NEXT:  %[[N:.*]] = arith.index_cast %[[RANGE]] : i64 to index
// HIP-NEXT:  %[[ZERO:.*]] = arith.constant 0 : index
// HIP-NEXT:  %[[IN:.*]] = arith.cmpi ult, %[[J:.*]], %[[N]] : index
// HIP-NEXT:  %[[K:.*]] = arith.select %[[IN]], %[[J]], %[[ZERO]] : index
// HIP-NEXT:  %[[V0:.*]] = sim.load {{source|snapshot}} @V[%[[K]]] : f64
// HIP-NEXT:  %[[Z0:.*]] = arith.constant 0.000000e+00 : f64
// HIP-NEXT:  %{{.*}} = arith.select %[[IN]], %[[V0]], %[[Z0]] : f64
// HIP-NEXT:  %[[V1:.*]] = sim.load target @V[%[[K]]] : f64
// HIP-NEXT:  %[[Z1:.*]] = arith.constant 0.000000e+00 : f64
// HIP-NEXT:  %{{.*}} = arith.select %[[IN]], %[[V1]], %[[Z1]] : f64
// CHECK:     sim.yield
sim.simulation @hermite_boundary range(64) dt(2.5e-1 : f32) max_steps(3) {
  sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @V : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @O : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Move writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %c2 = arith.constant 2 : i32
    sim.yield %c2 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f64
    %v = sim.read @V[%i] : f64
    %x1 = arith.addf %x, %v : f64
    sim.yield %x1, %v : f64, f64
  }
  sim.component @Observe writes(@O) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %x = sim.read @X[%j] : f64
    sim.yield %x : f64
  }
  sim.observe [@O]
}

// -----

// The paper's cubic on vector elements: the scalar weights are splatted.

// CHECK-LABEL: sim.simulation @cubic_vector
// CHECK: sim.component @Reader
// HIP:   %[[F:.*]] = arith.divf
// HIP:   %[[P:.*]] = sim.load source @P[
// HIP:   %[[Q:.*]] = sim.load target @P[
// HIP:   %[[TWO:.*]] = arith.constant 2.000000e+00 : f32
// HIP:   %[[TWOF:.*]] = arith.mulf %[[TWO]], %[[F]] : f32
// HIP:   %[[FF:.*]] = arith.mulf %[[F]], %[[F]] : f32
// HIP:   %[[THREE:.*]] = arith.constant 3.000000e+00 : f32
// HIP:   %[[D:.*]] = arith.subf %[[THREE]], %[[TWOF]] : f32
// HIP:   %[[S:.*]] = arith.mulf %[[FF]], %[[D]] : f32
// HIP:   %[[W:.*]] = arith.subf %{{.*}}, %[[S]] : f32
// HIP:   %[[WV:.*]] = vector.broadcast %[[W]] : f32 to vector<2xf32>
// HIP:   %[[A:.*]] = arith.mulf %[[WV]], %[[P]] : vector<2xf32>
// HIP:   %[[SV:.*]] = vector.broadcast %[[S]] : f32 to vector<2xf32>
// HIP:   %[[B:.*]] = arith.mulf %[[SV]], %[[Q]] : vector<2xf32>
// HIP:   %[[R:.*]] = arith.addf %[[A]], %[[B]] : vector<2xf32>
// HIP:   scf.yield %[[R]] : vector<2xf32>
// ONE:   %[[Q:.*]] = sim.load target @P[
// ONE-NEXT: sim.yield %[[Q]] : vector<2xf32>
sim.simulation @cubic_vector range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @P : vector<2xf32> interp(#sim.cubic) init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  sim.buffer @R : vector<2xf32> init {
  ^bb0(%i: index):
    %c = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %c : vector<2xf32>
  }
  sim.component @Writer writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : vector<2xf32>
    sim.yield %p : vector<2xf32>
  }
  sim.component @Reader writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %p = sim.read @P[%i] : vector<2xf32>
    sim.yield %p : vector<2xf32>
  }
  sim.observe [@R]
}

// -----

// The span of a Hermite interpolation of f32 elements in a scene with an f64
// dt: the run-time dt is truncated to the element type.

// CHECK-LABEL: sim.simulation @hermite_f64_dt
// CHECK: sim.component @Observe
// HIP:       arith.divf
// HIP-NEXT:  %[[SIZEF:.*]] = arith.sitofp %{{.*}} : i64 to f32
// HIP-NEXT:  %[[DT64:.*]] = sim.get_param @dt : f64
// HIP-NEXT:  %[[DT:.*]] = arith.truncf %[[DT64]] : f64 to f32
// HIP-NEXT:  %[[SPAN:.*]] = arith.mulf %[[SIZEF]], %[[DT]] : f32
// ONE-NOT:   sim.get_param
// CHECK:     sim.yield
sim.simulation @hermite_f64_dt range(64) dt(2.5e-1 : f64) max_steps(3) {
  sim.buffer @X : f32 interp(#sim.hermite<@V>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @V : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 1.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @O : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @Move writes(@X, @V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f32
    %v = sim.read @V[%i] : f32
    %x1 = arith.addf %x, %v : f32
    sim.yield %x1, %v : f32, f32
  }
  sim.component @Observe writes(@O) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f32
    sim.yield %x : f32
  }
  sim.observe [@O]
}
