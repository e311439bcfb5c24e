// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Bodies compute with integers of at most 64 bits, f16, f32 and f64: wider
// integers and other floats stopped LLVM's back ends with a fatal error, and
// bf16 needs compiler-rt routines the CPU kernels do not link. An error at
// the first operation that uses such a type.

// A 128-bit product in a component.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{'arith.index_cast' op computes with 'i128', which no backend supports; use integers of at most 64 bits, f16, f32 or f64}}
    %w = arith.index_cast %i : index to i128
    %sq = arith.muli %w, %w : i128
    %f = arith.uitofp %sq : i128 to f32
    sim.yield %f : f32
  }
}

// -----

// f128 in an init body.
sim.simulation @s range(16) dt(1.0e-2 : f64) max_steps(1) {
  sim.buffer @B : f64 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    // expected-error @+1 {{'arith.extf' op computes with 'f128', which no backend supports}}
    %q = arith.extf %one : f64 to f128
    %r = arith.truncf %q : f128 to f64
    sim.yield %r : f64
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @B[%i] : f64
    sim.yield %x : f64
  }
}

// -----

// A vector of bf16 in num_steps.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(4) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    // expected-error @+1 {{'arith.constant' op computes with 'bf16', which no backend supports}}
    %h = arith.constant dense<2.0> : vector<2xbf16>
    %e = vector.extract %h[0] : bf16 from vector<2xbf16>
    %n = arith.fptosi %e : bf16 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// A scalable vector's length is the hardware's: LLVM stopped with "Scalarization of scalable vectors is not supported".
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    // expected-error @+1 {{'vector.broadcast' op computes with the scalable vector type 'vector<[4]xf32>', which no backend supports; use a vector of fixed length}}
    %v = vector.broadcast %x : f32 to vector<[4]xf32>
    %m = vector.reduction <add>, %v : vector<[4]xf32> into f32
    sim.yield %m : f32
  }
}

// -----

// LLVM's powi takes a 32-bit exponent: x86's back end stopped with "POWI
// exponent does not match sizeof(int)", without a location.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    // expected-error @+1 {{'math.fpowi' op raises to an exponent of type 'i64', which no backend lowers (LLVM's powi takes an i32 exponent); convert the exponent to i32 with arith.trunci or arith.extsi}}
    %p = math.fpowi %x, %t : f32, i64
    sim.yield %p : f32
  }
}

// -----

// f16 and i16 are fine.
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    %h = arith.truncf %x : f32 to f16
    %k = arith.fptosi %h : f16 to i16
    %g = arith.sitofp %k : i16 to f16
    %r = arith.extf %g : f16 to f32
    sim.yield %r : f32
  }
}

// -----

// A body cannot call a function of the module (sim.simulation is a symbol
// table, so func.call's own verifier said "'helper' does not reference a
// valid function").
func.func @helper(%a: f32) -> f32 {
  %s = arith.addf %a, %a : f32
  return %s : f32
}
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    // expected-error @+1 {{'func.call' op calls a function, which a body cannot: its kernels are compiled without the module's functions; write the function's operations in the body itself}}
    %d = func.call @helper(%x) : (f32) -> f32
    sim.yield %d : f32
  }
}

// -----

// Nor the GPU's own operations: a body computes one item, and each backend
// maps items to threads itself (these failed late, in the CPU kernels'
// translation, with "unsupported GPU operation").
sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    // expected-error @+1 {{'gpu.barrier' op is a GPU operation, which a body cannot hold: a body computes one item, and each backend maps items to threads and groups itself}}
    gpu.barrier
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0e-2 : f32) max_steps(1) {
  // expected-error @+3 {{'gpu.thread_id' op is a GPU operation}}
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %tid = gpu.thread_id x
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
}
