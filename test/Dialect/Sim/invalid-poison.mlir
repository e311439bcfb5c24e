// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Bodies compute defined values: the constructs that make a poison value are
// errors at their operation. -1 is the vector dialect's poison index, not the
// last element; folding would turn the op into `ub.poison`.

// A static poison position.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    // expected-error @+1 {{'vector.extract' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
    %x = vector.extract %v[-1] : f32 from vector<4xf32>
    %r = vector.broadcast %x : f32 to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// A dynamic position that is the constant -1 (canonicalization would make it
// static, then fold the op into ub.poison).
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %m1 = arith.constant -1 : index
    // expected-error @+1 {{'vector.extract' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
    %x = vector.extract %v[%m1] : f32 from vector<4xf32>
    %r = vector.broadcast %x : f32 to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// A dynamic position that is a constant out of range.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %c4 = arith.constant 4 : index
    // expected-error @+1 {{'vector.extract' op uses the index 4, which is out of range, so its result is undefined; use an index from 0 to 3}}
    %x = vector.extract %v[%c4] : f32 from vector<4xf32>
    %r = vector.broadcast %x : f32 to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// vector.insert at the poison position.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %one = arith.constant 1.0 : f32
    // expected-error @+1 {{'vector.insert' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
    %r = vector.insert %one, %v[-1] : f32 into vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// vector.insert at a dynamic position that is the constant -1.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %one = arith.constant 1.0 : f32
    %m1 = arith.constant -1 : index
    // expected-error @+1 {{'vector.insert' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
    %r = vector.insert %one, %v[%m1] : f32 into vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// The poison index in the second dimension of a position, inside a loop.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    %m = vector.broadcast %v : vector<4xf32> to vector<2x4xf32>
    %lo = arith.constant 0 : index
    %hi = arith.constant 2 : index
    %step = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %step iter_args(%acc = %zero) -> (f32) {
      // expected-error @+1 {{'vector.extract' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
      %x = vector.extract %m[%k, -1] : f32 from vector<2x4xf32>
      %next = arith.addf %acc, %x : f32
      scf.yield %next : f32
    }
    %r = vector.broadcast %sum : f32 to vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// A poison entry in a shuffle mask.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    // expected-error @+1 {{'vector.shuffle' op uses the poison mask entry -1, so its result is undefined (-1 is not the last element); use a mask entry from 0 to 7}}
    %r = vector.shuffle %v, %v [0, 1, -1, 7] : vector<4xf32>, vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// ub.poison itself.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %v = sim.read @B[%i] : vector<4xf32>
    // expected-error @+1 {{'ub.poison' op makes a poison value, which would leave what the body computes undefined; compute a defined value instead}}
    %p = ub.poison : f32
    %r = vector.insert %p, %v[0] : f32 into vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
}

// -----

// Every body is checked: an init body.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    // expected-error @+1 {{'vector.extract' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 3}}
    %x = vector.extract %zero[-1] : f32 from vector<4xf32>
    sim.yield %x : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A num_steps body.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'ub.poison' op makes a poison value, which would leave what the body computes undefined; compute a defined value instead}}
    %n = ub.poison : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A total body.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<2xf64> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<2xf64>
    sim.yield %zero : vector<2xf64>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : vector<2xf64>
    sim.yield %x : vector<2xf64>
  }
  sim.total @E : f64 {
  ^bb0(%i: index):
    %x = sim.read @B[%i] : vector<2xf64>
    // expected-error @+1 {{'vector.extract' op uses the poison index -1, so its result is undefined (-1 is not the last element); use an index from 0 to 1}}
    %e = vector.extract %x[-1] : f64 from vector<2xf64>
    sim.yield %e : f64
  }
}

// -----

// A position computed at run time indexes only the innermost dimension: an
// n-D vector is an LLVM array of 1-D vectors, indexed by constants.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : vector<4xf32>
    %m = vector.broadcast %x : vector<4xf32> to vector<3x4xf32>
    %c3 = arith.constant 3 : index
    %r = arith.remui %i, %c3 : index
    // expected-error @+1 {{'vector.extract' op indexes dimension 0 of 'vector<3x4xf32>' with a value computed at run time, which no backend lowers; only the innermost dimension may be indexed so: vector.shape_cast the vector to 1-D and index the element there}}
    %row = vector.extract %m[%r] : vector<4xf32> from vector<3x4xf32>
    sim.yield %row : vector<4xf32>
  }
}

// -----

// The same for an insert; the innermost dimension may be dynamic.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : vector<4xf32> init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<4xf32>
    sim.yield %zero : vector<4xf32>
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : vector<4xf32>
    %m = vector.broadcast %x : vector<4xf32> to vector<3x4xf32>
    %c4 = arith.constant 4 : index
    %k = arith.remui %i, %c4 : index
    %e = vector.extract %m[1, %k] : f32 from vector<3x4xf32>
    // expected-error @+1 {{'vector.insert' op indexes dimension 0 of 'vector<3x4xf32>' with a value computed at run time}}
    %n2 = vector.insert %e, %m[%k, 0] : f32 into vector<3x4xf32>
    %row = vector.extract %n2[2] : vector<4xf32> from vector<3x4xf32>
    sim.yield %row : vector<4xf32>
  }
}
