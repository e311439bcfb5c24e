// RUN: sim-opt %s --sim-vectorize-lanes=width=8 --split-input-file | FileCheck %s
// RUN: sim-opt %s --sim-vectorize-lanes="width=8 report=true" --split-input-file --verify-diagnostics -o /dev/null
// RUN: sim-opt %s --sim-vectorize-lanes="width=8 wide-int-conversions=true" --split-input-file | FileCheck %s --check-prefix=WIDE
// RUN: sim-opt %s --sim-vectorize-lanes="width=8 chains-apart=true" --split-input-file | FileCheck %s --check-prefix=CHAINS

// Consecutive items of vec4 buffers: one wide load of 8 items; elementwise
// math on the items' elements as loaded (interleaved: no shuffle); one wide
// store of them. The lanes after the last whole chunk stay in the original
// loop.
// CHECK-LABEL: func.func @consecutive
// CHECK-SAME:      (%[[IN:.*]]: memref<?xvector<4xf32>>, %[[OUT:.*]]: memref<?xvector<4xf32>>, %[[BASE:.*]]: index, %[[G:.*]]: index)
// CHECK-DAG:     %[[C8:.*]] = arith.constant 8 : index
// CHECK:         %[[CHUNKS:.*]] = arith.divui %{{.*}}, %[[C8]]
// CHECK:         %[[WHOLE:.*]] = arith.muli %[[CHUNKS]], %[[C8]]
// CHECK:         %[[END:.*]] = arith.addi %{{.*}}, %[[WHOLE]]
// CHECK:         %[[IOTA:.*]] = arith.constant dense<[0, 1, 2, 3, 4, 5, 6, 7]> : vector<8xindex>
// CHECK-DAG:     memref.extract_aligned_pointer_as_index %[[IN]]
// CHECK-DAG:     memref.extract_aligned_pointer_as_index %[[OUT]]
// CHECK:         scf.for %[[CHUNK:.*]] = %{{.*}} to %[[END]] step %[[C8]] {
// CHECK:           %[[FIRSTS:.*]] = vector.broadcast %[[CHUNK]] : index to vector<8xindex>
// CHECK:           %[[LANES:.*]] = arith.addi %[[FIRSTS]], %[[IOTA]] : vector<8xindex>
// CHECK:           %[[ALL:.*]] = llvm.load %{{.*}} {alignment = 4 : i64} : !llvm.ptr -> vector<32xf32>
// CHECK-NEXT:      %[[T:.*]] = math.tanh %[[ALL]] : vector<32xf32>
// CHECK-NOT:       vector.shuffle
// CHECK:           llvm.store %[[T]], %{{.*}} {alignment = 4 : i64} : vector<32xf32>, !llvm.ptr
// CHECK:         }
// CHECK:         scf.for %[[LANE:.*]] = %[[END]] to %[[G]] step %{{.*}} {
// CHECK:           memref.load %[[IN]]
// CHECK:           math.tanh %{{.*}} : vector<4xf32>
// CHECK-NOT:     simplan.lanes
func.func @consecutive(%in: memref<?xvector<4xf32>>, %out: memref<?xvector<4xf32>>, %base: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %v = memref.load %in[%item] : memref<?xvector<4xf32>>
    %t = math.tanh %v : vector<4xf32>
    memref.store %t, %out[%item] : memref<?xvector<4xf32>>
  } {simplan.lanes}
  return
}

// -----

// A branch on a lane-dependent condition (the range check of a partial
// group) runs when one lane takes it, under its mask; its result is selected
// per lane. Loads inside it take the gather path unless the lanes are
// consecutive and all active; a load whose index is clamped is a gather
// from an active lane's address.
// CHECK-LABEL: func.func @masked
// CHECK:         scf.for
// CHECK:           %[[ACTIVE:.*]] = arith.cmpi ult, %{{.*}}, %{{.*}} : vector<8xindex>
// CHECK:           %[[ANY:.*]] = vector.reduction <or>, %{{.*}} : vector<8xi1> into i1
// CHECK:           %[[THEN:.*]] = scf.if %[[ANY]] -> (vector<8xf32>) {
// CHECK:             %[[MIN:.*]] = vector.reduction <minsi>, %{{.*}} : vector<8xi64> into i64
// CHECK:             llvm.intr.masked.gather
// CHECK:           } else {
// CHECK:             arith.constant dense<0.000000e+00> : vector<8xf32>
// CHECK:           }
// CHECK:           arith.select %[[ACTIVE]], %[[THEN]], %{{.*}} : vector<8xi1>, vector<8xf32>
// CHECK:           llvm.intr.masked.scatter
func.func @masked(%in: memref<?xf32>, %out: memref<?xf32>, %base: index, %range: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %zero = arith.constant 0.0 : f32
  %last = arith.subi %range, %c1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %active = arith.cmpi ult, %item, %range : index
    %v = scf.if %active -> (f32) {
      %right = arith.addi %item, %c1 : index
      %clamped = arith.minsi %right, %last : index
      %x = memref.load %in[%clamped] : memref<?xf32>
      scf.yield %x : f32
    } else {
      scf.yield %zero : f32
    }
    scf.if %active {
      memref.store %v, %out[%item] : memref<?xf32>
    }
  } {simplan.lanes}
  return
}

// -----

// An interpolated read of a vec4 buffer (two halves, weights uniform):
// both loads stay interleaved as loaded (a gather's parts interleaved in
// the slow path), the interpolation runs on them, and the result is
// de-interleaved once, where the accumulator (held per element) needs it.
// CHECK-LABEL: func.func @interpolated
// CHECK:         scf.for
// CHECK:           %[[A:.*]] = scf.if %{{.*}} -> (vector<32xf32>) {
// CHECK:             llvm.load {{.*}} -> vector<32xf32>
// CHECK:           } else {
// CHECK-COUNT-4:     llvm.intr.masked.gather
// CHECK:             vector.shuffle {{.*}} : vector<16xf32>, vector<16xf32>
// CHECK:           }
// CHECK:           %[[B:.*]] = scf.if %{{.*}} -> (vector<32xf32>) {
// CHECK:           %[[WA:.*]] = vector.shuffle %{{.*}}, %{{.*}} [0, 1, 2, 3, 0, 1, 2, 3,
// CHECK:           %[[SA:.*]] = arith.mulf %[[WA]], %[[A]] : vector<32xf32>
// CHECK:           %[[SB:.*]] = arith.mulf %{{.*}}, %[[B]] : vector<32xf32>
// CHECK:           %[[SUM:.*]] = arith.addf %[[SA]], %[[SB]] : vector<32xf32>
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [0, 4, 8, 12, 16, 20, 24, 28]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [1, 5, 9, 13, 17, 21, 25, 29]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [2, 6, 10, 14, 18, 22, 26, 30]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [3, 7, 11, 15, 19, 23, 27, 31]
// CHECK-NOT:       vector.shuffle %[[A]]
// CHECK:           arith.addf %{{.*}}, %{{.*}} : vector<8xf32>
func.func @interpolated(%halves: memref<?xvector<4xf32>>, %out: memref<?xvector<4xf32>>,
                        %base: index, %extent: index, %range: index,
                        %fraction: f32, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %one = arith.constant 1.0 : f32
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %active = arith.cmpi ult, %item, %range : index
    scf.if %active {
      %late = arith.addi %item, %extent : index
      %a = memref.load %halves[%item] : memref<?xvector<4xf32>>
      %b = memref.load %halves[%late] : memref<?xvector<4xf32>>
      %rest = arith.subf %one, %fraction : f32
      %wa = vector.broadcast %rest : f32 to vector<4xf32>
      %wb = vector.broadcast %fraction : f32 to vector<4xf32>
      %sa = arith.mulf %wa, %a : vector<4xf32>
      %sb = arith.mulf %wb, %b : vector<4xf32>
      %v = arith.addf %sa, %sb : vector<4xf32>
      %i64 = arith.index_cast %item : index to i64
      %if = arith.sitofp %i64 : i64 to f32
      %w = vector.broadcast %if : f32 to vector<4xf32>
      %acc = arith.addf %w, %v : vector<4xf32>
      %x = vector.extract %acc[0] : f32 from vector<4xf32>
      %y = vector.broadcast %x : f32 to vector<4xf32>
      %r = arith.mulf %y, %acc : vector<4xf32>
      memref.store %r, %out[%item] : memref<?xvector<4xf32>>
    }
  } {simplan.lanes}
  return
}

// -----

// Lanes that do not take a branch divide by one, not by their divisor.
// CHECK-LABEL: func.func @division
// CHECK:         scf.if
// CHECK:           %[[ONE:.*]] = arith.constant dense<1> : vector<8xi64>
// CHECK:           %[[SAFE:.*]] = arith.select %{{.*}}, %{{.*}}, %[[ONE]] : vector<8xi1>, vector<8xi64>
// CHECK:           arith.divui %{{.*}}, %[[SAFE]] : vector<8xi64>
func.func @division(%d: memref<?xi64>, %out: memref<?xi64>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c0_i64 = arith.constant 0 : i64
  %c100 = arith.constant 100 : i64
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %divisor = memref.load %d[%lane] : memref<?xi64>
    %nonzero = arith.cmpi ne, %divisor, %c0_i64 : i64
    %q = scf.if %nonzero -> (i64) {
      %x = arith.divui %c100, %divisor : i64
      scf.yield %x : i64
    } else {
      scf.yield %c0_i64 : i64
    }
    memref.store %q, %out[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// Divisions by divisors that are not constants go through f64 where that is
// exact: 32-bit operands always; 64-bit and index ones where every lane of
// the chunk is within 2^51 of zero (converted through the bits of
// 1.5 * 2^52), else the integer division.
// CHECK-LABEL: func.func @division_through_double
// CHECK:         scf.for
// CHECK:           %[[X32:.*]] = arith.sitofp %{{.*}} : vector<8xi32> to vector<8xf64>
// CHECK:           %[[D32:.*]] = arith.sitofp %{{.*}} : vector<8xi32> to vector<8xf64>
// CHECK:           %[[R32:.*]] = arith.divf %[[X32]], %[[D32]] : vector<8xf64>
// CHECK:           %[[Q32:.*]] = arith.fptosi %[[R32]] : vector<8xf64> to vector<8xi32>
// CHECK:           %[[QD32:.*]] = arith.muli %[[Q32]], %{{.*}} : vector<8xi32>
// CHECK:           arith.subi %{{.*}}, %[[QD32]] : vector<8xi32>
// CHECK:           %[[X64:.*]] = llvm.load %{{.*}} -> vector<8xi64>
// CHECK:           %[[D64:.*]] = vector.broadcast %{{.*}} : i64 to vector<8xi64>
// CHECK:           %[[BITS:.*]] = arith.constant dense<4843621399236968448> : vector<8xi64>
// CHECK:           %[[MAGIC:.*]] = arith.constant dense<0x4338000000000000> : vector<8xf64>
// CHECK:           %[[LIMIT:.*]] = arith.constant dense<2251799813685248> : vector<8xi64>
// CHECK:           %[[XOK:.*]] = arith.cmpi ult, %[[X64]], %[[LIMIT]] : vector<8xi64>
// CHECK:           %[[LANES:.*]] = arith.andi %[[XOK]], %{{.*}} : vector<8xi1>
// CHECK:           %[[CHUNK:.*]] = vector.reduction <and>, %[[LANES]] : vector<8xi1> into i1
// CHECK:           scf.if %[[CHUNK]] -> (vector<8xi64>) {
// CHECK:             %[[XB:.*]] = arith.addi %[[X64]], %[[BITS]] : vector<8xi64>
// CHECK:             %[[XS:.*]] = arith.bitcast %[[XB]] : vector<8xi64> to vector<8xf64>
// CHECK:             %[[XF:.*]] = arith.subf %[[XS]], %[[MAGIC]] : vector<8xf64>
// CHECK:             %[[RATIO:.*]] = arith.divf %[[XF]], %{{.*}} : vector<8xf64>
// CHECK:             %[[TRUNC:.*]] = math.trunc %[[RATIO]] : vector<8xf64>
// CHECK:             %[[QS:.*]] = arith.addf %[[TRUNC]], %[[MAGIC]] : vector<8xf64>
// CHECK:             %[[QB:.*]] = arith.bitcast %[[QS]] : vector<8xf64> to vector<8xi64>
// CHECK:             %[[Q:.*]] = arith.subi %[[QB]], %[[BITS]] : vector<8xi64>
// CHECK:             scf.yield %[[Q]] : vector<8xi64>
// CHECK:           } else {
// CHECK:             arith.divui %[[X64]], %[[D64]] : vector<8xi64>
// CHECK:           }
// CHECK:           %[[SHIFT:.*]] = arith.constant dense<2251799813685247> : vector<8xi64>
// CHECK:           arith.addi %{{.*}}, %[[SHIFT]] : vector<8xi64>
// CHECK:           %[[RANGE:.*]] = arith.constant dense<4503599627370495> : vector<8xi64>
// CHECK:           arith.cmpi ult, %{{.*}}, %[[RANGE]] : vector<8xi64>
// CHECK:           scf.if %{{.*}} -> (vector<8xi64>) {
// CHECK:             math.trunc
// CHECK:             arith.muli
// CHECK:             arith.subi
// CHECK:           } else {
// CHECK:             arith.remsi %{{.*}} : vector<8xi64>
// CHECK:           }
// CHECK:           arith.index_cast %{{.*}} : vector<8xi64> to vector<8xindex>
// CHECK-NOT:       arith.remsi %{{.*}} : vector<8xi32>
//
// With the target's conversions (AVX-512DQ), within 2^53.
// WIDE-LABEL: func.func @division_through_double
// WIDE:         arith.sitofp %{{.*}} : vector<8xi32> to vector<8xf64>
// WIDE:         %[[LIMIT:.*]] = arith.constant dense<9007199254740992> : vector<8xi64>
// WIDE:         arith.cmpi ult, %{{.*}}, %[[LIMIT]] : vector<8xi64>
// WIDE:         scf.if %{{.*}} -> (vector<8xi64>) {
// WIDE-NEXT:      %[[X:.*]] = arith.uitofp %{{.*}} : vector<8xi64> to vector<8xf64>
// WIDE-NEXT:      %[[D:.*]] = arith.uitofp %{{.*}} : vector<8xi64> to vector<8xf64>
// WIDE-NEXT:      %[[R:.*]] = arith.divf %[[X]], %[[D]] : vector<8xf64>
// WIDE-NEXT:      %[[Q:.*]] = arith.fptoui %[[R]] : vector<8xf64> to vector<8xi64>
// WIDE-NEXT:      scf.yield %[[Q]] : vector<8xi64>
// WIDE:         arith.constant dense<9007199254740991> : vector<8xi64>
// WIDE:         arith.sitofp %{{.*}} : vector<8xi64> to vector<8xf64>
// WIDE:         arith.fptosi %{{.*}} : vector<8xf64> to vector<8xi64>
// WIDE-NOT:     math.trunc
func.func @division_through_double(%d32: memref<?xi32>, %d64: memref<?xi64>,
                                   %out32: memref<?xi32>, %out64: memref<?xi64>,
                                   %outi: memref<?xi64>, %g: index,
                                   %uniform: i64, %n: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %x32 = memref.load %d32[%lane] : memref<?xi32>
    %lane32 = arith.index_cast %lane : index to i32
    %r32 = arith.remsi %x32, %lane32 : i32
    memref.store %r32, %out32[%lane] : memref<?xi32>
    %x64 = memref.load %d64[%lane] : memref<?xi64>
    %q64 = arith.divui %x64, %uniform : i64
    memref.store %q64, %out64[%lane] : memref<?xi64>
    %wrapped = arith.remsi %lane, %n : index
    %wrapped64 = arith.index_cast %wrapped : index to i64
    memref.store %wrapped64, %outi[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// A 64-bit remainder by a constant below 2^16 that is not a power of two is
// computed from the 32-bit halves (x86 has no vector high half of a 64-bit
// product, so LLVM would take the i64 remainder lane by lane):
// ((hi % c) * (2^32 % c) + lo % c) % c, without the multiplication where
// 2^32 % c is 1. Powers of two and wider divisors stay as they are.
// CHECK-LABEL: func.func @remainder_by_halves
// CHECK:         scf.for
// CHECK:           %[[X:.*]] = llvm.load %{{.*}} -> vector<8xi64>
// CHECK:           %[[C3:.*]] = arith.constant dense<3> : vector<8xi32>
// CHECK:           %[[C32:.*]] = arith.constant dense<32> : vector<8xi64>
// CHECK:           %[[SHIFTED:.*]] = arith.shrui %[[X]], %[[C32]] : vector<8xi64>
// CHECK:           %[[HI:.*]] = arith.trunci %[[SHIFTED]] : vector<8xi64> to vector<8xi32>
// CHECK:           %[[LO:.*]] = arith.trunci %[[X]] : vector<8xi64> to vector<8xi32>
// CHECK:           %[[HI3:.*]] = arith.remui %[[HI]], %[[C3]] : vector<8xi32>
// CHECK:           %[[LO3:.*]] = arith.remui %[[LO]], %[[C3]] : vector<8xi32>
// CHECK-NEXT:      %[[SUM3:.*]] = arith.addi %[[HI3]], %[[LO3]] : vector<8xi32>
// CHECK-NEXT:      %[[R3:.*]] = arith.remui %[[SUM3]], %[[C3]] : vector<8xi32>
// CHECK-NEXT:      arith.extui %[[R3]] : vector<8xi32> to vector<8xi64>
// CHECK:           %[[C7:.*]] = arith.constant dense<7> : vector<8xi32>
// CHECK:           %[[HI7:.*]] = arith.remui %{{.*}}, %[[C7]] : vector<8xi32>
// CHECK:           %[[LO7:.*]] = arith.remui %{{.*}}, %[[C7]] : vector<8xi32>
// CHECK:           %[[SCALE7:.*]] = arith.constant dense<4> : vector<8xi32>
// CHECK:           %[[SCALED7:.*]] = arith.muli %[[HI7]], %[[SCALE7]] : vector<8xi32>
// CHECK:           %[[SUM7:.*]] = arith.addi %[[SCALED7]], %[[LO7]] : vector<8xi32>
// CHECK:           arith.remui %[[SUM7]], %[[C7]] : vector<8xi32>
// CHECK:           arith.remui %[[X]], %{{.*}} : vector<8xi64>
// CHECK:           arith.remui %[[X]], %{{.*}} : vector<8xi64>
func.func @remainder_by_halves(%d: memref<?xi64>, %out: memref<?xi64>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c3 = arith.constant 3 : i64
  %c7 = arith.constant 7 : i64
  %c8 = arith.constant 8 : i64
  %c65537 = arith.constant 65537 : i64
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %x = memref.load %d[%lane] : memref<?xi64>
    %r3 = arith.remui %x, %c3 : i64
    %r7 = arith.remui %x, %c7 : i64
    %r8 = arith.remui %x, %c8 : i64
    %r65537 = arith.remui %x, %c65537 : i64
    %s0 = arith.addi %r3, %r7 : i64
    %s1 = arith.addi %s0, %r8 : i64
    %s2 = arith.addi %s1, %r65537 : i64
    memref.store %s2, %out[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// A division by a constant other than 0 cannot trap: no mask, so LLVM can
// multiply by the reciprocal instead of dividing lane by lane. A signed
// division by -1 keeps its mask (INT_MIN / -1 traps).
// CHECK-LABEL: func.func @constant_divisor
// CHECK:         scf.if
// CHECK-NOT:       arith.select
// CHECK:           arith.divui %{{.*}}, %{{.*}} : vector<8xi64>
// CHECK:           %[[SAFE:.*]] = arith.select %{{.*}}, %{{.*}}, %{{.*}} : vector<8xi1>, vector<8xi64>
// CHECK:           arith.divsi %{{.*}}, %[[SAFE]] : vector<8xi64>
func.func @constant_divisor(%d: memref<?xi64>, %out: memref<?xi64>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c0_i64 = arith.constant 0 : i64
  %c3 = arith.constant 3 : i64
  %minus_one = arith.constant -1 : i64
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %x = memref.load %d[%lane] : memref<?xi64>
    %positive = arith.cmpi sgt, %x, %c0_i64 : i64
    %q = scf.if %positive -> (i64) {
      %r = arith.divui %x, %c3 : i64
      %n = arith.divsi %r, %minus_one : i64
      scf.yield %n : i64
    } else {
      scf.yield %c0_i64 : i64
    }
    memref.store %q, %out[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// A select on a lane-independent condition whose operand costs a division
// (num_steps keyed by `i / @group` or `i`, chosen by a parameter) becomes a
// branch that computes only the chosen operand, in the widened loop and in
// the scalar one after it; so does a select that picks that select's value.
// A select on a lane-dependent condition stays a select.
// CHECK-LABEL: func.func @uniform_select
// CHECK:         scf.for
// CHECK:           %[[KEY:.*]] = scf.if %{{.*}} -> (vector<8xindex>) {
// CHECK:             arith.divf %{{.*}} : vector<8xf64>
// CHECK:             arith.divui %{{.*}} : vector<8xi64>
// CHECK:           } else {
// CHECK-NEXT:        scf.yield
// CHECK-NEXT:      }
// CHECK-NEXT:      scf.if %{{.*}} -> (vector<8xindex>) {
// CHECK-NEXT:        scf.yield %[[KEY]]
// CHECK-NEXT:      } else {
// CHECK-NOT:         arith.divui
// CHECK:             arith.select %{{.*}}, %{{.*}}, %{{.*}} : vector<8xi1>, vector<8xindex>
// CHECK:         scf.for
// CHECK:           scf.if %{{.*}} -> (index) {
// CHECK:             arith.divui %{{.*}} : index
// CHECK:           } else {
// CHECK-NEXT:        scf.yield
func.func @uniform_select(%out: memref<?xi64>, %g: index, %group: index,
                          %per_group: i1, %plain: i1) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c7 = arith.constant 7 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %size = arith.maxui %group, %c1 : index
    %group_id = arith.divui %lane, %size : index
    %key = arith.select %per_group, %group_id, %lane : index
    %odd = arith.cmpi ugt, %lane, %c7 : index
    %cheap = arith.select %odd, %lane, %c7 : index
    %both = arith.select %plain, %key, %cheap : index
    %value = arith.index_cast %both : index to i64
    memref.store %value, %out[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// Reductions combine in the scalar lowering's order: from +0.0 for an fadd
// without accumulator, element by element (the builder puts the constant
// on the right of the first add, which rounds the same). Uniform loops keep their bounds
// and carry lane vectors.
// CHECK-LABEL: func.func @reduction
// CHECK:         scf.for
// CHECK:           %[[START:.*]] = arith.constant dense<0.000000e+00> : vector<8xf32>
// CHECK:           %[[S0:.*]] = arith.addf %{{.*}}, %[[START]] : vector<8xf32>
// CHECK:           %[[S1:.*]] = arith.addf %[[S0]], %{{.*}} : vector<8xf32>
// CHECK:           %[[S2:.*]] = arith.addf %[[S1]], %{{.*}} : vector<8xf32>
// CHECK:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args(%{{.*}} = %[[S2]]) -> (vector<8xf32>)
func.func @reduction(%in: memref<?xvector<3xf32>>, %out: memref<?xf32>, %rounds: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %v = memref.load %in[%lane] : memref<?xvector<3xf32>>
    %s = vector.reduction <add>, %v : vector<3xf32> into f32
    %r = scf.for %k = %c0 to %rounds step %c1 iter_args(%acc = %s) -> (f32) {
      %m = arith.mulf %acc, %acc : f32
      scf.yield %m : f32
    }
    memref.store %r, %out[%lane] : memref<?xf32>
  } {simplan.lanes}
  return
}

// -----

// What the pass cannot widen stays the scalar loop, unmarked: a loop whose
// trip count depends on the lane, a store of different lanes to one
// element, an atomic.
// CHECK-LABEL: func.func @stays_scalar
// CHECK-NOT:     vector<8x
// CHECK-NOT:     simplan.lanes
func.func @stays_scalar(%in: memref<?xindex>, %out: memref<?xf32>, %sum: memref<?xi64>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %one = arith.constant 1.0 : f32
  %one_i64 = arith.constant 1 : i64
  // expected-remark @below {{lanes stay scalar: a loop with lane-dependent bounds: scf.for}}
  scf.for %lane = %c0 to %g step %c1 {
    scf.for %k = %c0 to %lane step %c1 {
      memref.store %one, %out[%k] : memref<?xf32>
    }
  } {simplan.lanes}
  // expected-remark @below {{lanes stay scalar: lanes that store different values to one element: memref.store}}
  scf.for %lane = %c0 to %g step %c1 {
    %x = arith.index_cast %lane : index to i64
    %f = arith.sitofp %x : i64 to f32
    memref.store %f, %out[%c0] : memref<?xf32>
  } {simplan.lanes}
  // expected-remark @below {{lanes stay scalar: an op with effects or regions: memref.atomic_rmw}}
  scf.for %lane = %c0 to %g step %c1 {
    %old = memref.atomic_rmw addi %one_i64, %sum[%c0] : (i64, memref<?xi64>) -> i64
  } {simplan.lanes}
  return
}

// -----

// A load at an item divided by at least the lanes of a chunk (a block's
// level: half + item / 32) is most often the same element in every lane
// and never consecutive: one scalar load to every lane when all lanes
// agree; else, when every lane's index is the first lane's or the last
// lane's (the chunk crosses one block boundary), two scalar loads and a
// select per lane; a gather only when neither holds; and no contiguity
// check. An index divided by less (item / 4) checks for consecutive lanes
// and gathers as before.
// CHECK-LABEL: func.func @block_index_loads
// CHECK:         scf.for
// CHECK:           %[[INDEX:.*]] = arith.index_cast %{{.*}} : vector<8xindex> to vector<8xi64>
// CHECK-NEXT:      %[[FIRST:.*]] = vector.extract %[[INDEX]][0] : i64 from vector<8xi64>
// CHECK-NEXT:      %[[FIRSTS:.*]] = vector.broadcast %[[FIRST]] : i64 to vector<8xi64>
// CHECK-NEXT:      %[[SAME:.*]] = arith.cmpi eq, %[[INDEX]], %[[FIRSTS]] : vector<8xi64>
// CHECK-NEXT:      %[[ALL:.*]] = vector.reduction <and>, %[[SAME]] : vector<8xi1> into i1
// CHECK-NEXT:      scf.if %[[ALL]] -> (vector<8xi64>) {
// CHECK:             %[[ONE:.*]] = llvm.load %{{.*}} : !llvm.ptr -> i64
// CHECK:             vector.broadcast %[[ONE]] : i64 to vector<8xi64>
// CHECK:           } else {
// CHECK-NEXT:        %[[LAST:.*]] = vector.extract %[[INDEX]][7] : i64 from vector<8xi64>
// CHECK-NEXT:        %[[LASTS:.*]] = vector.broadcast %[[LAST]] : i64 to vector<8xi64>
// CHECK-NEXT:        %[[IS_LAST:.*]] = arith.cmpi eq, %[[INDEX]], %[[LASTS]] : vector<8xi64>
// CHECK-NEXT:        %[[EITHER:.*]] = arith.ori %[[SAME]], %[[IS_LAST]] : vector<8xi1>
// CHECK-NEXT:        %[[BOTH:.*]] = vector.reduction <and>, %[[EITHER]] : vector<8xi1> into i1
// CHECK-NEXT:        scf.if %[[BOTH]] -> (vector<8xi64>) {
// CHECK:               %[[AT_FIRST:.*]] = llvm.load %{{.*}} : !llvm.ptr -> i64
// CHECK:               %[[FROM_FIRST:.*]] = vector.broadcast %[[AT_FIRST]] : i64 to vector<8xi64>
// CHECK:               %[[AT_LAST:.*]] = llvm.load %{{.*}} : !llvm.ptr -> i64
// CHECK:               %[[FROM_LAST:.*]] = vector.broadcast %[[AT_LAST]] : i64 to vector<8xi64>
// CHECK:               arith.select %[[SAME]], %[[FROM_FIRST]], %[[FROM_LAST]] : vector<8xi1>, vector<8xi64>
// CHECK:             } else {
// CHECK:               llvm.intr.masked.gather
// CHECK:           arith.divui %{{.*}}, %{{.*}} : vector<8xindex>
// CHECK-NOT:       llvm.load %{{.*}} : !llvm.ptr -> i64
// CHECK:           llvm.intr.masked.gather
// CHECK:         return
func.func @block_index_loads(%levels: memref<?xi64>, %out: memref<?xi64>, %half: index, %base: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c4 = arith.constant 4 : index
  %c32 = arith.constant 32 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %block = arith.divui %item, %c32 : index
    %at = arith.addi %half, %block : index
    %level = memref.load %levels[%at] : memref<?xi64>
    %quarter = arith.divui %item, %c4 : index
    %other = memref.load %levels[%quarter] : memref<?xi64>
    %sum = arith.addi %level, %other : i64
    memref.store %sum, %out[%item] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// The boundary rules on item + offset (clamp: minsi(maxsi(x, 0), last);
// zero: select(x < range, x, 0); wrap: scf.if (x < range) { x } else
// {...}), shifted by a uniform offset: one wide load when the chunk's first
// and last lanes lie inside and the run does not wrap around the 64-bit
// integers between them, decided by three scalar compares on the first
// lane instead of comparing every lane; else the gathers. An item shifted
// by a uniform value (minus the block's first item) stays consecutive: its
// store is wide without a check.
// CHECK-LABEL: func.func @bounded_runs
// CHECK:         scf.for %[[CHUNK:.*]] =
// CHECK:           arith.maxsi %[[X:[0-9a-z_]+]], %{{.*}} : vector<8xindex>
// CHECK:           %[[XI64:.*]] = arith.index_cast %[[X]] : vector<8xindex> to vector<8xi64>
// CHECK:           %[[FIRST:.*]] = vector.extract %[[XI64]][0] : i64 from vector<8xi64>
// CHECK:           %[[LAST:.*]] = arith.addi %[[FIRST]], %{{.*}} : i64
// CHECK:           %[[ABOVE:.*]] = arith.cmpi sge, %[[FIRST]], %{{.*}} : i64
// CHECK:           %[[BELOW:.*]] = arith.cmpi sle, %[[LAST]], %{{.*}} : i64
// CHECK:           %[[BOTH:.*]] = arith.andi %[[ABOVE]], %[[BELOW]] : i1
// CHECK:           %[[NOWRAP:.*]] = arith.cmpi sge, %[[LAST]], %[[FIRST]] : i64
// CHECK:           %[[INSIDE:.*]] = arith.andi %[[BOTH]], %[[NOWRAP]] : i1
// CHECK:           scf.if %[[INSIDE]] -> (vector<8xf32>) {
// CHECK:             llvm.load %{{.*}} : !llvm.ptr -> vector<8xf32>
// CHECK:           } else {
// CHECK:             llvm.intr.masked.gather
// CHECK:           }
// CHECK:           arith.cmpi slt, %{{.*}}, %{{.*}} : i64
// CHECK:           scf.if %{{.*}} -> (vector<8xf32>) {
// CHECK:             llvm.load
// CHECK:           } else {
// CHECK:             llvm.intr.masked.gather
// CHECK:           }
// CHECK:           arith.cmpi slt, %{{.*}}, %{{.*}} : i64
// CHECK:           scf.if %{{.*}} -> (vector<8xf32>) {
// CHECK:             llvm.load
// CHECK:           } else {
// CHECK:             llvm.intr.masked.gather
// CHECK:           }
// CHECK:           llvm.store %{{.*}}, %{{.*}} {alignment = 4 : i64} : vector<8xf32>, !llvm.ptr
// CHECK-NEXT:    }
func.func @bounded_runs(%clamped: memref<?xf32>, %zeroed: memref<?xf32>, %wrapped: memref<?xf32>,
                        %out: memref<?xf32>, %base: index, %first: index, %range: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %cm1 = arith.constant -1 : index
  %last = arith.subi %range, %c1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %x = arith.addi %item, %cm1 : index
    %low = arith.maxsi %x, %c0 : index
    %clamp = arith.minsi %low, %last : index
    %ci = arith.subi %clamp, %first : index
    %a = memref.load %clamped[%ci] : memref<?xf32>
    %in = arith.cmpi ult, %x, %range : index
    %zero = arith.select %in, %x, %c0 : index
    %b = memref.load %zeroed[%zero] : memref<?xf32>
    %wrap = scf.if %in -> (index) {
      scf.yield %x : index
    } else {
      %rem = arith.remsi %x, %range : index
      %neg = arith.cmpi slt, %rem, %c0 : index
      %up = arith.addi %rem, %range : index
      %w = arith.select %neg, %up, %rem : index
      scf.yield %w : index
    }
    %c = memref.load %wrapped[%wrap] : memref<?xf32>
    %ab = arith.addf %a, %b : f32
    %abc = arith.addf %ab, %c : f32
    %own = arith.subi %item, %first : index
    memref.store %abc, %out[%own] : memref<?xf32>
  } {simplan.lanes}
  return
}

// -----

// Consecutive lanes under a branch's mask (a partial group's range check):
// the wide load needs only every lane to run, not a lane-by-lane compare
// of the indices.
// CHECK-LABEL: func.func @masked_consecutive
// CHECK:         scf.for
// CHECK:           %[[ACTIVE:.*]] = arith.cmpi ult, %{{.*}}, %{{.*}} : vector<8xindex>
// CHECK:           scf.if %{{.*}} {
// CHECK-NEXT:        arith.index_cast
// CHECK-NEXT:        %[[ALL:.*]] = vector.reduction <and>, %[[ACTIVE]] : vector<8xi1> into i1
// CHECK-NEXT:        scf.if %[[ALL]] -> (vector<8xf32>) {
// CHECK-NEXT:          vector.extract
// CHECK-NEXT:          llvm.getelementptr
// CHECK-NEXT:          llvm.load %{{.*}} : !llvm.ptr -> vector<8xf32>
func.func @masked_consecutive(%in: memref<?xf32>, %out: memref<?xf32>, %base: index, %range: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %active = arith.cmpi ult, %item, %range : index
    scf.if %active {
      %v = memref.load %in[%item] : memref<?xf32>
      memref.store %v, %out[%item] : memref<?xf32>
    }
  } {simplan.lanes}
  return
}

// -----

// A consecutive dividend (the lane plus a uniform value) divided by a
// uniform divisor: where the divisor is at least the lanes and the first
// lane's value neither lets the last one wrap nor (signed) is below zero,
// one scalar division of the first lane, and a compare per lane for the
// one multiple of the divisor the chunk may cross; elsewhere the chunk
// divides as before. A remainder and a division of the same operands (a
// row and a column) share the branch and its division. A constant divisor
// takes the same path unless it is a power of two (a shift) or the
// operands are 32-bit (LLVM multiplies by its reciprocal in vector lanes).
// CHECK-LABEL: func.func @consecutive_division
// CHECK:         scf.for
// CHECK:           %[[LANES:.*]] = arith.addi %{{.*}}, %{{.*}} : vector<8xindex>
// CHECK:           %[[X:.*]] = arith.addi %{{.*}}, %{{.*}} : vector<8xi64>
// CHECK:           %[[FIRST:.*]] = vector.extract %[[X]][0] : i64 from vector<8xi64>
// CHECK:           arith.cmpi sge, %[[D:.*]], %{{.*}} : i64
// CHECK:           %[[MAX:.*]] = arith.constant 9223372036854775800 : i64
// CHECK:           arith.cmpi sle, %[[FIRST]], %[[MAX]] : i64
// CHECK:           arith.cmpi sge, %[[FIRST]], %{{.*}} : i64
// CHECK:           scf.if %{{.*}} -> (vector<8xi64>) {
// CHECK-NEXT:        %[[Q:.*]] = arith.divui %[[FIRST]], %[[D]] : i64
// CHECK-NEXT:        %[[BASE:.*]] = arith.muli %[[Q]], %[[D]] : i64
// CHECK-NEXT:        %[[BASES:.*]] = vector.broadcast %[[BASE]] : i64 to vector<8xi64>
// CHECK-NEXT:        %[[R:.*]] = arith.subi %[[X]], %[[BASES]] : vector<8xi64>
// CHECK-NEXT:        %[[DS:.*]] = vector.broadcast %[[D]] : i64 to vector<8xi64>
// CHECK-NEXT:        %[[PAST:.*]] = arith.cmpi uge, %[[R]], %[[DS]] : vector<8xi64>
// CHECK-NEXT:        %[[ONE:.*]] = arith.constant 1 : i64
// CHECK-NEXT:        %[[NEXT:.*]] = arith.addi %[[Q]], %[[ONE]] : i64
// CHECK-NEXT:        %[[NEXTS:.*]] = vector.broadcast %[[NEXT]] : i64 to vector<8xi64>
// CHECK-NEXT:        %[[QS:.*]] = vector.broadcast %[[Q]] : i64 to vector<8xi64>
// CHECK-NEXT:        %[[QUOTIENT:.*]] = arith.select %[[PAST]], %[[NEXTS]], %[[QS]] : vector<8xi1>, vector<8xi64>
// CHECK-NEXT:        scf.yield %[[QUOTIENT]] : vector<8xi64>
// CHECK-NEXT:      } else {
// CHECK:             arith.divf
// CHECK:             arith.divsi %[[X]], %{{.*}} : vector<8xi64>
// CHECK:           }
// CHECK:           %[[IFIRST:.*]] = vector.extract %[[LANES]][0] : index from vector<8xindex>
// CHECK:           arith.cmpi uge, %[[N:.*]], %{{.*}} : index
// CHECK:           %[[IMAX:.*]] = arith.constant -8 : index
// CHECK:           arith.cmpi ule, %[[IFIRST]], %[[IMAX]] : index
// CHECK:           %[[PAIR:.*]]:2 = scf.if %{{.*}} -> (vector<8xindex>, vector<8xindex>) {
// CHECK-NEXT:        %[[IQ:.*]] = arith.divui %[[IFIRST]], %[[N]] : index
// CHECK:             %[[IR:.*]] = arith.subi %[[LANES]], %{{.*}} : vector<8xindex>
// CHECK-NEXT:        %[[NS:.*]] = vector.broadcast %[[N]] : index to vector<8xindex>
// CHECK-NEXT:        %[[IPAST:.*]] = arith.cmpi uge, %[[IR]], %[[NS]] : vector<8xindex>
// CHECK-NEXT:        %[[IRN:.*]] = arith.subi %[[IR]], %[[NS]] : vector<8xindex>
// CHECK-NEXT:        %[[REM:.*]] = arith.select %[[IPAST]], %[[IRN]], %[[IR]] : vector<8xi1>, vector<8xindex>
// CHECK:             %[[TURNS:.*]] = arith.select %[[IPAST]], %{{.*}}, %{{.*}} : vector<8xi1>, vector<8xindex>
// CHECK-NEXT:        scf.yield %[[REM]], %[[TURNS]] : vector<8xindex>, vector<8xindex>
// CHECK-NEXT:      } else {
// CHECK:             arith.remui %{{.*}} : vector<8xi64>
// CHECK:             arith.divui %{{.*}} : vector<8xi64>
// CHECK:           }
// CHECK:           arith.index_cast %[[PAIR]]#0
// CHECK-NOT:       arith.divui %{{.*}}, %[[N]] : index
// CHECK:           arith.index_cast %[[PAIR]]#1
// CHECK:           arith.divui %{{.*}}, %[[C100:.*]] : i64
// CHECK:           arith.remui %[[X]], %{{.*}} : vector<8xi64>
// CHECK:           arith.remui %{{.*}}, %{{.*}} : vector<8xi32>
// CHECK-NOT:       scf.if
// CHECK:           llvm.store
func.func @consecutive_division(%out: memref<?xi64>, %g: index, %base: i64,
                                %d: i64, %n: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c64 = arith.constant 64 : i64
  %c100 = arith.constant 100 : i64
  %c100_i32 = arith.constant 100 : i32
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %lane64 = arith.index_cast %lane : index to i64
    %x = arith.addi %lane64, %base : i64
    %q = arith.divsi %x, %d : i64
    %wrapped = arith.remui %lane, %n : index
    %wrapped64 = arith.index_cast %wrapped : index to i64
    %turns = arith.divui %lane, %n : index
    %turns64 = arith.index_cast %turns : index to i64
    %r100 = arith.remui %x, %c100 : i64
    %r64 = arith.remui %x, %c64 : i64
    %lane32 = arith.index_cast %lane : index to i32
    %r32 = arith.remui %lane32, %c100_i32 : i32
    %r32w = arith.extui %r32 : i32 to i64
    %s0 = arith.addi %q, %wrapped64 : i64
    %t0 = arith.addi %s0, %turns64 : i64
    %s1 = arith.addi %t0, %r100 : i64
    %s2 = arith.addi %s1, %r64 : i64
    %s3 = arith.addi %s2, %r32w : i64
    memref.store %s3, %out[%lane] : memref<?xi64>
  } {simplan.lanes}
  return
}

// -----

// A block's level read under a mask (an item guarded by `item < range`):
// a chunk whose every lane runs reads at its own indices; only a chunk
// with a lane that does not run replaces that lane's index by an active
// one's (the minimum across the lanes) before choosing between one load,
// two and the gathers.
// CHECK-LABEL: func.func @masked_block_index_loads
// CHECK:         scf.for
// CHECK:           %[[MASK:.*]] = arith.cmpi ult, %{{.*}}, %{{.*}} : vector<8xindex>
// CHECK:           scf.if
// CHECK:             %[[EVERY:.*]] = vector.reduction <and>, %[[MASK]] : vector<8xi1> into i1
// CHECK-NEXT:        scf.if %[[EVERY]] -> (vector<8xi64>) {
// CHECK-NOT:           vector.reduction <minsi>
// CHECK:               %[[FIRST:.*]] = vector.extract %[[INDEX:.*]][0] : i64 from vector<8xi64>
// CHECK:             } else {
// CHECK:               %[[SAFE:.*]] = vector.reduction <minsi>, %{{.*}} : vector<8xi64> into i64
// CHECK:               vector.extract %{{.*}}[0] : i64 from vector<8xi64>
// CHECK:             }
// CHECK:         return
func.func @masked_block_index_loads(%levels: memref<?xi64>, %out: memref<?xi64>, %half: index, %base: index, %g: index, %n: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c32 = arith.constant 32 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %item = arith.addi %base, %lane : index
    %inside = arith.cmpi ult, %item, %n : index
    scf.if %inside {
      %block = arith.divui %item, %c32 : index
      %at = arith.addi %half, %block : index
      %level = memref.load %levels[%at] : memref<?xi64>
      memref.store %level, %out[%item] : memref<?xi64>
    }
  } {simplan.lanes}
  return
}

// -----

// fpowi: LLVM's powi takes one integer exponent for a whole vector of
// bases, so each lane raises its own base to its own exponent.

//                An exponent per lane: --sim-lower-vector-ops unrolls it
//                later (lower-vector-ops.mlir), as LLVM's powi takes one.
// CHECK-LABEL: func.func @integer_power
// CHECK:         %[[BASES:.*]] = llvm.load {{.*}} -> vector<8xf32>
// CHECK:         %[[EXPONENTS:.*]] = llvm.load {{.*}} -> vector<8xi32>
// CHECK:         math.fpowi %[[BASES]], %[[EXPONENTS]] : vector<8xf32>, vector<8xi32>
func.func @integer_power(%x: memref<?xf32>, %n: memref<?xi32>, %out: memref<?xf32>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %b = memref.load %x[%lane] : memref<?xf32>
    %e = memref.load %n[%lane] : memref<?xi32>
    %p = math.fpowi %b, %e : f32, i32
    memref.store %p, %out[%lane] : memref<?xf32>
  } {simplan.lanes}
  return
}

// -----

// A window's sum (a vec4 carried by a loop over the offsets): the sum stays
// interleaved from one iteration to the next, as the loads give it, and is
// de-interleaved once after the loop, not each load in every iteration.
// CHECK-LABEL: func.func @window_sum
// CHECK:         scf.for
// CHECK:           %[[ZERO:.*]] = vector.shuffle {{.*}} : vector<4xf32>, vector<4xf32>
// CHECK:           %[[SUM:.*]] = scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args(%[[ACC:.*]] = %[[ZERO]]) -> (vector<32xf32>) {
// CHECK:             %[[V:.*]] = scf.if %{{.*}} -> (vector<32xf32>) {
// CHECK-NOT:         vector.shuffle %[[V]]
// CHECK:             %[[NEXT:.*]] = arith.addf %[[ACC]], %[[V]] : vector<32xf32>
// CHECK-NEXT:        scf.yield %[[NEXT]] : vector<32xf32>
// CHECK:           }
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [0, 4, 8, 12, 16, 20, 24, 28]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [1, 5, 9, 13, 17, 21, 25, 29]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [2, 6, 10, 14, 18, 22, 26, 30]
// CHECK-NEXT:      vector.shuffle %[[SUM]], %[[SUM]] [3, 7, 11, 15, 19, 23, 27, 31]
func.func @window_sum(%in: memref<?xvector<4xf32>>, %out: memref<?xvector<4xf32>>,
                      %last: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c-2 = arith.constant -2 : index
  %c3 = arith.constant 3 : index
  %zero = arith.constant dense<0.0> : vector<4xf32>
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %sum = scf.for %k = %c-2 to %c3 step %c1 iter_args(%acc = %zero) -> (vector<4xf32>) {
      %j = arith.addi %lane, %k : index
      %low = arith.maxsi %j, %c0 : index
      %at = arith.minsi %low, %last : index
      %v = memref.load %in[%at] : memref<?xvector<4xf32>>
      %next = arith.addf %acc, %v : vector<4xf32>
      scf.yield %next : vector<4xf32>
    }
    %x = vector.extract %sum[0] : f32 from vector<4xf32>
    %y = vector.broadcast %x : f32 to vector<4xf32>
    %r = arith.mulf %y, %sum : vector<4xf32>
    memref.store %r, %out[%lane] : memref<?xvector<4xf32>>
  } {simplan.lanes}
  return
}

// -----

// A carried vec4 that the body combines with a value held per element (a
// lane's own index) needs its parts in every iteration: it is carried as
// them, as before, not de-interleaved in every iteration.
// CHECK-LABEL: func.func @carried_parts
// CHECK:         scf.for
// CHECK:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args({{.*}}) -> (vector<8xf32>, vector<8xf32>, vector<8xf32>, vector<8xf32>) {
// CHECK-NOT:         vector<32xf32>
// CHECK:             scf.yield %{{.*}} : vector<8xf32>, vector<8xf32>, vector<8xf32>, vector<8xf32>
func.func @carried_parts(%out: memref<?xvector<4xf32>>, %rounds: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %zero = arith.constant dense<0.0> : vector<4xf32>
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %i64 = arith.index_cast %lane : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    %w = vector.broadcast %f : f32 to vector<4xf32>
    %sum = scf.for %k = %c0 to %rounds step %c1 iter_args(%acc = %zero) -> (vector<4xf32>) {
      %next = arith.addf %acc, %w : vector<4xf32>
      scf.yield %next : vector<4xf32>
    }
    memref.store %sum, %out[%lane] : memref<?xvector<4xf32>>
  } {simplan.lanes}
  return
}

// -----

// A loop body of pure ops whose widened elements are computed apart (a
// scene's rounds of a matrix product): op by op, each op's elements
// together; with chains-apart element by element, so that one element's
// values die before the next element's are made, instead of every
// element's at once (twice the registers AVX2 has, for a 4x4 product).
// CHECK-LABEL: func.func @element_chains
// CHECK:         scf.for
// CHECK:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args(%[[X0:.*]] = %{{.*}}, %[[X1:.*]] = %{{.*}}) -> (vector<8xf32>, vector<8xf32>) {
// CHECK-NEXT:        %[[P0:.*]] = arith.mulf %[[W:.*]], %[[X0]] : vector<8xf32>
// CHECK-NEXT:        %[[P1:.*]] = arith.mulf %[[W]], %[[X1]] : vector<8xf32>
// CHECK-NEXT:        %[[Q0:.*]] = arith.addf %[[P0]], %[[X0]] : vector<8xf32>
// CHECK-NEXT:        %[[Q1:.*]] = arith.addf %[[P1]], %[[X1]] : vector<8xf32>
// CHECK-NEXT:        scf.yield %[[Q0]], %[[Q1]] : vector<8xf32>, vector<8xf32>
// CHAINS-LABEL: func.func @element_chains
// CHAINS:         scf.for
// CHAINS:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args(%[[X0:.*]] = %{{.*}}, %[[X1:.*]] = %{{.*}}) -> (vector<8xf32>, vector<8xf32>) {
// CHAINS-NEXT:        %[[P0:.*]] = arith.mulf %[[W:.*]], %[[X0]] : vector<8xf32>
// CHAINS-NEXT:        %[[Q0:.*]] = arith.addf %[[P0]], %[[X0]] : vector<8xf32>
// CHAINS-NEXT:        %[[P1:.*]] = arith.mulf %[[W]], %[[X1]] : vector<8xf32>
// CHAINS-NEXT:        %[[Q1:.*]] = arith.addf %[[P1]], %[[X1]] : vector<8xf32>
// CHAINS-NEXT:        scf.yield %[[Q0]], %[[Q1]] : vector<8xf32>, vector<8xf32>
func.func @element_chains(%in: memref<?xvector<2xf32>>, %out: memref<?xvector<2xf32>>,
                          %rounds: index, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %v = memref.load %in[%lane] : memref<?xvector<2xf32>>
    %s = vector.extract %v[0] : f32 from vector<2xf32>
    %w = vector.broadcast %s : f32 to vector<2xf32>
    %r = scf.for %k = %c0 to %rounds step %c1 iter_args(%x = %v) -> (vector<2xf32>) {
      %p = arith.mulf %w, %x : vector<2xf32>
      %q = arith.addf %p, %x : vector<2xf32>
      scf.yield %q : vector<2xf32>
    }
    memref.store %r, %out[%lane] : memref<?xvector<2xf32>>
  } {simplan.lanes}
  return
}

// -----

// A read from one of two buffers, chosen by a condition that is the same
// for every lane (hip's halves, chosen by the clock): both sides load
// interleaved, so the choice is yielded interleaved and the window's sum
// stays so; a choice one side of which has its value only in parts (a
// lane's own index) is yielded in parts.
// CHECK-LABEL: func.func @uniform_choice
// CHECK:         scf.for
// CHECK:           scf.for %{{.*}} = %{{.*}} to %{{.*}} step %{{.*}} iter_args(%[[ACC:.*]] = %{{.*}}) -> (vector<32xf32>) {
// CHECK:             %[[V:.*]] = scf.if %{{.*}} -> (vector<32xf32>) {
// CHECK-NOT:         vector.shuffle %[[V]]
// CHECK:             arith.addf %[[ACC]], %[[V]] : vector<32xf32>
// CHECK:           scf.if %{{.*}} -> (vector<8xf32>, vector<8xf32>, vector<8xf32>, vector<8xf32>) {
func.func @uniform_choice(%a: memref<?xvector<4xf32>>, %b: memref<?xvector<4xf32>>,
                          %out: memref<?xvector<4xf32>>, %late: i1, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %c3 = arith.constant 3 : index
  %zero = arith.constant dense<0.0> : vector<4xf32>
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %sum = scf.for %k = %c0 to %c3 step %c1 iter_args(%acc = %zero) -> (vector<4xf32>) {
      %j = arith.addi %lane, %k : index
      %v = scf.if %late -> (vector<4xf32>) {
        %x = memref.load %b[%j] : memref<?xvector<4xf32>>
        scf.yield %x : vector<4xf32>
      } else {
        %x = memref.load %a[%j] : memref<?xvector<4xf32>>
        scf.yield %x : vector<4xf32>
      }
      %next = arith.addf %acc, %v : vector<4xf32>
      scf.yield %next : vector<4xf32>
    }
    %own = scf.if %late -> (vector<4xf32>) {
      %i64 = arith.index_cast %lane : index to i64
      %f = arith.sitofp %i64 : i64 to f32
      %w = vector.broadcast %f : f32 to vector<4xf32>
      scf.yield %w : vector<4xf32>
    } else {
      %x = memref.load %a[%lane] : memref<?xvector<4xf32>>
      scf.yield %x : vector<4xf32>
    }
    %r = arith.addf %sum, %own : vector<4xf32>
    memref.store %r, %out[%lane] : memref<?xvector<4xf32>>
  } {simplan.lanes}
  return
}

// -----

// The parts of an elementwise op on interleaved values come from its
// operands' parts where that takes no more de-interleaving: here the two
// loads are taken apart once (their elements are read), and the product and
// the sum, whose elements are read too, are computed element by element from
// those parts instead of being de-interleaved themselves (the interleaved
// product and sum are left unused).
// CHECK-LABEL: func.func @operand_parts
// CHECK:         scf.for %{{.*}} step %{{.*}} {
// CHECK:           %[[P:.*]] = llvm.load %{{.*}} -> vector<32xf32>
// CHECK-NEXT:      %[[P0:.*]] = vector.shuffle %[[P]], %[[P]] [0, 4, 8, 12, 16, 20, 24, 28]
// CHECK-NEXT:      %[[P1:.*]] = vector.shuffle %[[P]], %[[P]] [1, 5, 9, 13, 17, 21, 25, 29]
// CHECK-NEXT:      %[[P2:.*]] = vector.shuffle %[[P]], %[[P]] [2, 6, 10, 14, 18, 22, 26, 30]
// CHECK-NEXT:      %[[P3:.*]] = vector.shuffle %[[P]], %[[P]] [3, 7, 11, 15, 19, 23, 27, 31]
// CHECK:           %[[S:.*]] = llvm.load %{{.*}} -> vector<32xf32>
// CHECK-NEXT:      %[[S0:.*]] = vector.shuffle %[[S]], %[[S]] [0, 4, 8, 12, 16, 20, 24, 28]
// CHECK-NEXT:      %[[S1:.*]] = vector.shuffle %[[S]], %[[S]] [1, 5, 9, 13, 17, 21, 25, 29]
// CHECK-NEXT:      %[[S2:.*]] = vector.shuffle %[[S]], %[[S]] [2, 6, 10, 14, 18, 22, 26, 30]
// CHECK-NEXT:      %[[S3:.*]] = vector.shuffle %[[S]], %[[S]] [3, 7, 11, 15, 19, 23, 27, 31]
// CHECK-NEXT:      arith.mulf %[[P]], %[[S]] : vector<32xf32>
// CHECK-NEXT:      arith.mulf %[[P0]], %[[S0]] : vector<8xf32>
// CHECK-NEXT:      arith.mulf %[[P1]], %[[S1]] : vector<8xf32>
// CHECK-NEXT:      %[[PROD2:.*]] = arith.mulf %[[P2]], %[[S2]] : vector<8xf32>
// CHECK-NEXT:      arith.mulf %[[P3]], %[[S3]] : vector<8xf32>
// CHECK-NEXT:      arith.addf %[[P]], %[[S]] : vector<32xf32>
// CHECK-NEXT:      arith.addf %[[P0]], %[[S0]] : vector<8xf32>
// CHECK-NEXT:      arith.addf %[[P1]], %[[S1]] : vector<8xf32>
// CHECK-NEXT:      arith.addf %[[P2]], %[[S2]] : vector<8xf32>
// CHECK-NEXT:      %[[SUM3:.*]] = arith.addf %[[P3]], %[[S3]] : vector<8xf32>
// CHECK-NEXT:      %[[XY:.*]] = arith.addf %[[P0]], %[[S1]] : vector<8xf32>
// CHECK-NEXT:      %[[ZW:.*]] = arith.addf %[[PROD2]], %[[SUM3]] : vector<8xf32>
// CHECK-NEXT:      arith.addf %[[XY]], %[[ZW]] : vector<8xf32>
// CHECK-NOT:       vector.shuffle
// CHECK:         }
func.func @operand_parts(%a: memref<?xvector<4xf32>>, %b: memref<?xvector<4xf32>>,
                         %out: memref<?xf32>, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %p = memref.load %a[%lane] : memref<?xvector<4xf32>>
    %s = memref.load %b[%lane] : memref<?xvector<4xf32>>
    %prod = arith.mulf %p, %s : vector<4xf32>
    %sum = arith.addf %p, %s : vector<4xf32>
    %x = vector.extract %p[0] : f32 from vector<4xf32>
    %y = vector.extract %s[1] : f32 from vector<4xf32>
    %z = vector.extract %prod[2] : f32 from vector<4xf32>
    %w = vector.extract %sum[3] : f32 from vector<4xf32>
    %xy = arith.addf %x, %y : f32
    %zw = arith.addf %z, %w : f32
    %r = arith.addf %xy, %zw : f32
    memref.store %r, %out[%lane] : memref<?xf32>
  } {simplan.lanes}
  return
}

// -----

// Where the operands' parts would each take a de-interleaving of their own
// (an interpolation between two loads, whose elements nothing else reads),
// the result is de-interleaved instead: four shuffles, not eight. A scaling
// of it by a uniform value takes its parts from the result's (no more
// shuffles).
// CHECK-LABEL: func.func @result_parts
// CHECK:         scf.for %{{.*}} step %{{.*}} {
// CHECK:           %[[MIX:.*]] = arith.addf %{{.*}}, %{{.*}} : vector<32xf32>
// CHECK-NEXT:      %[[M0:.*]] = vector.shuffle %[[MIX]], %[[MIX]] [0, 4, 8, 12, 16, 20, 24, 28]
// CHECK-NEXT:      vector.shuffle %[[MIX]], %[[MIX]] [1, 5, 9, 13, 17, 21, 25, 29]
// CHECK-NEXT:      vector.shuffle %[[MIX]], %[[MIX]] [2, 6, 10, 14, 18, 22, 26, 30]
// CHECK-NEXT:      %[[M3:.*]] = vector.shuffle %[[MIX]], %[[MIX]] [3, 7, 11, 15, 19, 23, 27, 31]
// CHECK:           %[[H:.*]] = vector.broadcast %{{.*}} : f32 to vector<8xf32>
// CHECK:           %[[HALF3:.*]] = arith.mulf %[[M3]], %{{.*}} : vector<8xf32>
// CHECK:           arith.addf %[[M0]], %[[HALF3]] : vector<8xf32>
// CHECK-NOT:       vector.shuffle
// CHECK:         }
func.func @result_parts(%a: memref<?xvector<4xf32>>, %b: memref<?xvector<4xf32>>,
                        %out: memref<?xf32>, %w: f32, %g: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  %half = arith.constant dense<0.5> : vector<4xf32>
  // expected-remark @below {{lanes run 8 at a time}}
  scf.for %lane = %c0 to %g step %c1 {
    %p = memref.load %a[%lane] : memref<?xvector<4xf32>>
    %s = memref.load %b[%lane] : memref<?xvector<4xf32>>
    %ws = vector.broadcast %w : f32 to vector<4xf32>
    %wp = arith.mulf %ws, %p : vector<4xf32>
    %ss = arith.mulf %ws, %s : vector<4xf32>
    %mix = arith.addf %wp, %ss : vector<4xf32>
    %x = vector.extract %mix[0] : f32 from vector<4xf32>
    %scaled = arith.mulf %mix, %half : vector<4xf32>
    %y = vector.extract %scaled[3] : f32 from vector<4xf32>
    %r = arith.addf %x, %y : f32
    memref.store %r, %out[%lane] : memref<?xf32>
  } {simplan.lanes}
  return
}
