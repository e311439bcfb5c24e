// RUN: sim-opt %s --split-input-file --pass-pipeline='builtin.module(sim.simulation(sim-define-edge-cases))' | FileCheck %s

// A division by a divisor that may be 0 or -1 divides by 1 there and
// selects the defined result: 0 for 0, the negated dividend for -1.
// CHECK-LABEL: sim.component @SignedDivision
// CHECK:         %[[ZERO:.*]] = arith.constant 0 : i32
// CHECK:         %[[ONE:.*]] = arith.constant 1 : i32
// CHECK:         %[[BYZERO:.*]] = arith.cmpi eq, %[[D:.*]], %[[ZERO]] : i32
// CHECK:         %[[MINUS:.*]] = arith.constant -1 : i32
// CHECK:         %[[BYMINUS:.*]] = arith.cmpi eq, %[[D]], %[[MINUS]] : i32
// CHECK:         %[[UNSAFE:.*]] = arith.ori %[[BYZERO]], %[[BYMINUS]] : i1
// CHECK:         %[[SAFE:.*]] = arith.select %[[UNSAFE]], %[[ONE]], %[[D]] : i32
// CHECK:         %[[Q:.*]] = arith.divsi %[[X:.*]], %[[SAFE]] : i32
// CHECK:         %[[NEG:.*]] = arith.subi %[[ZERO]], %[[X]] : i32
// CHECK:         %[[M:.*]] = arith.select %[[BYMINUS]], %[[NEG]], %[[Q]] : i32
// CHECK:         %[[R:.*]] = arith.select %[[BYZERO]], %[[ZERO]], %[[M]] : i32
// CHECK:         arith.sitofp %[[R]] : i32 to f32
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.param @d = 3 : i32
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @SignedDivision writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = arith.index_cast %i : index to i32
    %d = sim.get_param @d : i32
    %q = arith.divsi %x, %d : i32
    %f = arith.sitofp %q : i32 to f32
    sim.yield %f : f32
  }
  sim.observe [@X]
}

// -----

// An unsigned remainder by 0 is the dividend; -1 is an ordinary divisor.
// CHECK-LABEL: sim.component @UnsignedRemainder
// CHECK:         %[[BYZERO:.*]] = arith.cmpi eq, %[[D:.*]], %{{.*}} : vector<2xi64>
// CHECK-NOT:     arith.ori
// CHECK:         %[[SAFE:.*]] = arith.select %[[BYZERO]], %{{.*}}, %[[D]] : vector<2xi1>, vector<2xi64>
// CHECK:         %[[R:.*]] = arith.remui %[[X:.*]], %[[SAFE]] : vector<2xi64>
// CHECK:         %[[DEF:.*]] = arith.select %[[BYZERO]], %[[X]], %[[R]] : vector<2xi1>, vector<2xi64>
// CHECK:         arith.uitofp %[[DEF]] : vector<2xi64> to vector<2xf64>
sim.simulation @s range(8) dt(1.0 : f64) max_steps(1) {
  sim.buffer @X : vector<2xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<7.0> : vector<2xf64>
    sim.yield %z : vector<2xf64>
  }
  sim.component @UnsignedRemainder writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %i64 = arith.index_cast %i : index to i64
    %x = vector.broadcast %i64 : i64 to vector<2xi64>
    %l = vector.broadcast %t : i64 to vector<2xi64>
    %r = arith.remui %x, %l : vector<2xi64>
    %f = arith.uitofp %r : vector<2xi64> to vector<2xf64>
    sim.yield %f : vector<2xf64>
  }
  sim.observe [@X]
}

// -----

// Constant divisors other than 0 and -1 and constant shifts below the
// width rule their cases out: nothing changes.
// CHECK-LABEL: sim.component @Constants
// CHECK-NOT:     arith.select
// CHECK:         arith.divsi %{{.*}}, %{{.*}} : i32
// CHECK-NEXT:    arith.remui
// CHECK-NEXT:    arith.shli
// CHECK-NEXT:    arith.sitofp
// CHECK-NEXT:    sim.yield
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @Constants writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %cm1 = arith.constant -1 : i32
    %c31 = arith.constant 31 : i32
    %q = arith.divsi %x, %c3 : i32
    %r = arith.remui %q, %cm1 : i32
    %s = arith.shli %r, %c31 : i32
    %f = arith.sitofp %s : i32 to f32
    sim.yield %f : f32
  }
  sim.observe [@X]
}

// -----

// A shift by the width or more: 0 from shli and shrui, the sign from
// shrsi (a shift by the width less one). Shifts of index values are left
// to the target.
// CHECK-LABEL: sim.component @Shifts
// CHECK:         %[[S:.*]] = arith.shrsi %[[X:.*]], %[[A:.*]] : i16
// CHECK:         %[[W:.*]] = arith.constant 16 : i16
// CHECK:         %[[IN:.*]] = arith.cmpi ult, %[[A]], %[[W]] : i16
// CHECK:         %[[W1:.*]] = arith.constant 15 : i16
// CHECK:         %[[SIGN:.*]] = arith.shrsi %[[X]], %[[W1]] : i16
// CHECK:         %[[DEF:.*]] = arith.select %[[IN]], %[[S]], %[[SIGN]] : i16
// CHECK:         arith.shli %[[DEF]]
// CHECK:         arith.cmpi ult
// CHECK:         %[[IDX:.*]] = arith.shli %{{.*}}, %{{.*}} : index
// CHECK-NOT:     arith.select
// CHECK:         sim.yield
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.param @a = 3 : i16
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @Shifts writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = arith.index_cast %i : index to i16
    %a = sim.get_param @a : i16
    %s = arith.shrsi %x, %a : i16
    %l = arith.shli %s, %a : i16
    %ai = arith.index_cast %a : i16 to index
    %si = arith.shli %i, %ai : index
    %r = arith.index_cast %si : index to i16
    %sum = arith.addi %l, %r : i16
    %f = arith.sitofp %sum : i16 to f32
    sim.yield %f : f32
  }
  sim.observe [@X]
}

// -----

// fptosi saturates: past 2^31 the largest i32, below -2^31 the smallest,
// NaN 0. fptoui of f16 to i32: every finite f16 fits, so only infinities
// saturate (the top is infinite: -1 or below gives 0).
// CHECK-LABEL: sim.component @Conversions
// CHECK:         %[[C:.*]] = arith.fptosi %[[X:.*]] : f32 to i32
// CHECK:         %[[TOP:.*]] = arith.constant 2.14748365E+9 : f32
// CHECK:         %[[HIGH:.*]] = arith.cmpf oge, %[[X]], %[[TOP]] : f32
// CHECK:         %[[BOTTOM:.*]] = arith.constant -2.14748365E+9 : f32
// CHECK:         %[[LOW:.*]] = arith.cmpf olt, %[[X]], %[[BOTTOM]] : f32
// CHECK:         %[[NAN:.*]] = arith.cmpf uno, %[[X]], %[[X]] : f32
// CHECK:         %[[MIN:.*]] = arith.constant -2147483648 : i32
// CHECK:         %[[D1:.*]] = arith.select %[[LOW]], %[[MIN]], %[[C]] : i32
// CHECK:         %[[MAX:.*]] = arith.constant 2147483647 : i32
// CHECK:         %[[D2:.*]] = arith.select %[[HIGH]], %[[MAX]], %[[D1]] : i32
// CHECK:         %[[D3:.*]] = arith.select %[[NAN]], %{{.*}}, %[[D2]] : i32
// CHECK:         arith.fptoui %{{.*}} : f16 to i32
// CHECK:         arith.constant 0x7C00 : f16
// CHECK:         arith.cmpf oge, %{{.*}}, %{{.*}} : f16
// CHECK:         arith.constant -1.000000e+00 : f16
// CHECK:         arith.cmpf ole, %{{.*}}, %{{.*}} : f16
// CHECK:         sim.yield
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @Conversions writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %s = arith.fptosi %x : f32 to i32
    %h = arith.truncf %x : f32 to f16
    %u = arith.fptoui %h : f16 to i32
    %sum = arith.addi %s, %u : i32
    %f = arith.sitofp %sum : i32 to f32
    sim.yield %f : f32
  }
  sim.observe [@X]
}

// -----

// A loop whose step may not be positive runs to its lower bound then.
// CHECK-LABEL: sim.component @Loop
// CHECK:         %[[POS:.*]] = arith.cmpi sgt, %[[STEP:.*]], %{{.*}} : index
// CHECK:         %[[UB:.*]] = arith.select %[[POS]], %[[HI:.*]], %[[LO:.*]] : index
// CHECK:         scf.for %{{.*}} = %[[LO]] to %[[UB]] step %[[STEP]]
// CHECK:         arith.cmpi ne, %[[USTEP:.*]], %{{.*}} : i32
// CHECK:         scf.for unsigned
sim.simulation @s range(8) dt(1.0 : f32) max_steps(1) {
  sim.param @step = 1 : index
  sim.param @ustep = 1 : i32
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %z = arith.constant 7.0 : f32
    sim.yield %z : f32
  }
  sim.component @Loop writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %step = sim.get_param @step : index
    %lo = arith.constant 0 : index
    %hi = arith.constant 4 : index
    %r = scf.for %k = %lo to %hi step %step iter_args(%a = %x) -> f32 {
      %b = arith.addf %a, %x : f32
      scf.yield %b : f32
    }
    %ustep = sim.get_param @ustep : i32
    %ulo = arith.constant 0 : i32
    %uhi = arith.constant 4 : i32
    %u = scf.for unsigned %k = %ulo to %uhi step %ustep iter_args(%a = %r) -> f32 : i32 {
      %b = arith.addf %a, %x : f32
      scf.yield %b : f32
    }
    sim.yield %u : f32
  }
  sim.observe [@X]
}
