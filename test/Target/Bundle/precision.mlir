// The narrowest float each buffer's and total's values derive from
// (ValuePrecision): the bundle records it as precision_bytes, and
// sim-run --check takes its default tolerance from it, not from the element
// type. An f64 value computed from f32 data differs between backends by f32
// ulps (an f32 math.sin is libdevice's on CUDA, libm's in the reference).
//
// RUN: sim-translate %s --sim-to-bundle --sim-cpu-isas=host --sim-strategies=simple,hip -o %t.simb
// RUN: %python %S/Inputs/dump-bundle.py --flatc %flatc --schema %bundle_schema %t.simb \
// RUN:   | FileCheck %s
// RUN: sim-run %t.simb --backend cpu --strategy hip --steps 8 --check \
// RUN:   2> %t.stderr | FileCheck %s --check-prefix=CHECKED
// RUN: FileCheck %s --check-prefix=INIT --input-file=%t.stderr

// A is f32; B (f64) reads A; C (f64) reads only B, so it inherits A's f32;
// D (f64) is f64 all through, though its writer also writes E, which
// converts to f32 (a writer's body counts whole for each of its buffers:
// D is f32 too); P (f64) reads an f32 parameter; Q (f64) is f64 all
// through and reads P only through its own item's f64 value: f32 as well.
// R (f64) is pure f64. The totals: SumA (f64) sums f32 values, SumR only
// f64 ones.
// CHECK:      buffer 0 A F32 interp Linear boundary Clamp observed
// CHECK-NEXT: buffer 1 B F64 interp Linear boundary Clamp observed from f32
// CHECK-NEXT: buffer 2 C F64 interp Linear boundary Clamp observed from f32
// CHECK-NEXT: buffer 3 D F64 interp Linear boundary Clamp observed from f32
// CHECK-NEXT: buffer 4 E F32 interp Linear boundary Clamp observed
// CHECK-NEXT: buffer 5 P F64 interp Linear boundary Clamp observed from f32
// CHECK-NEXT: buffer 6 Q F64 interp Linear boundary Clamp observed from f32
// CHECK-NEXT: buffer 7 R F64 interp Linear boundary Clamp observed{{$}}
// CHECK-NEXT: total 0 SumA F64 from f32
// CHECK-NEXT: total 1 SumR F64{{$}}

// CHECKED: buffer A {{.*}} tolerance 1.0e-04 pass
// CHECKED: buffer B {{.*}} tolerance 1.0e-04 pass
// CHECKED: buffer C {{.*}} tolerance 1.0e-04 pass
// CHECKED: buffer R {{.*}} tolerance 1.0e-10 pass
// CHECKED: total SumA {{.*}} limit 1.0e-03 pass
// CHECKED: total SumR {{.*}} limit 1.0e-07 pass
// CHECKED: check: pass

// The init check (the inits here are not what the writers compute) holds
// each buffer to the tolerance of its precision too.
// INIT:      the init of buffer 'B' disagrees with its writer 'WB'
// INIT-NEXT: {{.*}} differ by more than 1.0e-05 of the largest
// INIT:      the init of buffer 'R' disagrees with its writer 'WR'
// INIT-NEXT: {{.*}} differ by more than 1.0e-12 of the largest

sim.simulation @precision range(16) dt(1.0e-1 : f64) max_steps(2) {
  sim.param @gain = 5.0e-1 : f32

  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @B : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @C : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @D : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @E : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f32
    sim.yield %z : f32
  }
  sim.buffer @P : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @Q : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }
  sim.buffer @R : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 1.0 : f64
    sim.yield %z : f64
  }

  sim.schedule [@WA, @WB, @WC, @WDE, @WP, @WQ, @WR]

  sim.component @WA writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f32
    %s = math.sin %a : f32
    sim.yield %s : f32
  }
  sim.component @WB writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %a = sim.read @A[%i] : f32
    %x = arith.extf %a : f32 to f64
    sim.yield %x : f64
  }
  sim.component @WC writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %b = sim.read @B[%i] : f64
    %c = arith.mulf %b, %dt : f64
    sim.yield %c : f64
  }
  sim.component @WDE writes(@D, @E) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %d = sim.read @D[%i] : f64
    %e = arith.truncf %d : f64 to f32
    sim.yield %d, %e : f64, f32
  }
  sim.component @WP writes(@P) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %g = sim.get_param @gain : f32
    %x = arith.extf %g : f32 to f64
    sim.yield %x : f64
  }
  sim.component @WQ writes(@Q) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %p = sim.read @P[%i] : f64
    %q = arith.addf %p, %dt : f64
    sim.yield %q : f64
  }
  sim.component @WR writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %r = sim.read @R[%i] : f64
    %s = math.sin %r : f64
    sim.yield %s : f64
  }

  sim.total @SumA : f64 {
  ^bb0(%i: index):
    %a = sim.read @A[%i] : f32
    %x = arith.extf %a : f32 to f64
    sim.yield %x : f64
  }
  sim.total @SumR : f64 {
  ^bb0(%i: index):
    %r = sim.read @R[%i] : f64
    sim.yield %r : f64
  }

  sim.observe [@A, @B, @C, @D, @E, @P, @Q, @R]
}
