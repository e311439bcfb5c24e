// RUN: split-file %s %t
// RUN: sim-opt %t/no-equals.mlir --sim-set-params="values=L" --verify-diagnostics
// RUN: sim-opt %t/no-name.mlir --sim-set-params="values==3" --verify-diagnostics
// RUN: sim-opt %t/unknown-name.mlir --sim-set-params="values=Lx=3" --verify-diagnostics
// RUN: sim-opt %t/unknown-name-buffer.mlir --sim-set-params="values=B=3" --verify-diagnostics
// RUN: sim-opt %t/unknown-name-no-params.mlir --sim-set-params="values=L=3" --verify-diagnostics
// RUN: sim-opt %t/unknown-after-valid.mlir --sim-set-params="values=L=8,steps=2" --verify-diagnostics
// RUN: sim-opt %t/unknown-after-valid.mlir --sim-set-params="values=L = 8, steps = 2" --verify-diagnostics
// RUN: sim-opt %t/no-equals-spaced.mlir --sim-set-params="values=L=8, L" --verify-diagnostics
// RUN: sim-opt %t/empty-entry.mlir --sim-set-params="values=L=8," --verify-diagnostics
// RUN: sim-opt %t/empty-entry.mlir --sim-set-params="values=L=8, ,k=1" --verify-diagnostics
// RUN: not sim-opt %t/empty-entry.mlir --sim-set-params="L=8" 2>&1 | FileCheck %s --check-prefix=NO-VALUES
// RUN: sim-opt %t/int-not-a-number.mlir --sim-set-params="values=L=four" --verify-diagnostics
// RUN: sim-opt %t/int-from-float.mlir --sim-set-params="values=L=1.5" --verify-diagnostics
// RUN: sim-opt %t/int-empty.mlir --sim-set-params="values=L=" --verify-diagnostics
// RUN: sim-opt %t/int-binary.mlir --sim-set-params="values=L=0b101" --verify-diagnostics
// RUN: sim-opt %t/float-not-a-number.mlir --sim-set-params="values=k=fast" --verify-diagnostics
// RUN: sim-opt %t/range-not-a-number.mlir --sim-set-params="values=range=16k" --verify-diagnostics
// RUN: sim-opt %t/dt-not-a-number.mlir --sim-set-params="values=dt=small" --verify-diagnostics
// RUN: sim-opt %t/range-zero.mlir --sim-set-params="values=range=0" --verify-diagnostics
// RUN: sim-opt %t/range-negative.mlir --sim-set-params="values=range=-4" --verify-diagnostics
// RUN: sim-opt %t/range-too-wide.mlir --sim-set-params="values=range=18446744073709551615" --verify-diagnostics
// RUN: sim-opt %t/range-above-limit.mlir --sim-set-params="values=range=1099511627777" --verify-diagnostics
// RUN: sim-opt %t/max-steps-above-limit.mlir --sim-set-params="values=max_steps=1048577" --verify-diagnostics
// RUN: sim-opt %t/max-steps-zero.mlir --sim-set-params="values=max_steps=0" --verify-diagnostics
// RUN: sim-opt %t/max-steps-too-wide.mlir --sim-set-params="values=max_steps=4294967295" --verify-diagnostics
// RUN: sim-opt %t/dt-zero.mlir --sim-set-params="values=dt=0" --verify-diagnostics
// RUN: sim-opt %t/dt-negative.mlir --sim-set-params="values=dt=-1.0e-3" --verify-diagnostics
// RUN: sim-opt %t/dt-inf.mlir --sim-set-params="values=dt=inf" --verify-diagnostics
// RUN: sim-opt %t/dt-nan.mlir --sim-set-params="values=dt=nan" --verify-diagnostics
// RUN: sim-opt %t/dt-underflow.mlir --sim-set-params="values=dt=1e-50" --verify-diagnostics
// RUN: sim-opt %t/i8-too-wide.mlir --sim-set-params="values=b=256" --verify-diagnostics
// RUN: sim-opt %t/i8-unsigned-decimal.mlir --sim-set-params="values=b=255" --verify-diagnostics
// RUN: sim-opt %t/i32-unsigned-decimal.mlir --sim-set-params="values=L=2147483648" --verify-diagnostics
// RUN: sim-opt %t/i8-too-negative.mlir --sim-set-params="values=b=-129" --verify-diagnostics
// RUN: sim-opt %t/i8-hex-too-wide.mlir --sim-set-params="values=b=0xFFFF" --verify-diagnostics
// RUN: sim-opt %t/i32-hex-too-wide.mlir --sim-set-params="values=L=0x1FFFFFFFF" --verify-diagnostics
// RUN: sim-opt %t/index-too-wide.mlir --sim-set-params="values=N=99999999999999999999" --verify-diagnostics
// RUN: sim-opt %t/f32-overflow.mlir --sim-set-params="values=k=1e40" --verify-diagnostics
// RUN: sim-opt %t/after-front-end.mlir --sim-set-params="values=max_steps=128" --verify-diagnostics

// Errors of --sim-set-params, one input per option value (split-file), each
// checked with --verify-diagnostics. Every error is reported at the
// simulation and stops the pass, except one in the option string itself,
// which is found before there is any IR: the option is values=..., and the
// message says so.
// NO-VALUES: error: <Pass-Options-Parser>: no such option L; --sim-set-params takes its overrides as values=name=value,name=value,... (for example --sim-set-params="values=range=16384,L=64")

//--- no-equals.mlir
// expected-error @+1 {{expects a parameter override of the form name=value, but got 'L'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- no-name.mlir
// expected-error @+1 {{expects a parameter override of the form name=value, but got '=3'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- unknown-name.mlir
// expected-error @+1 {{has no parameter named 'Lx'; it has range, dt, max_steps, L, k, b, N}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- unknown-name-buffer.mlir
// expected-error @+1 {{has no parameter named 'B'; it has range, dt, max_steps, L, k, b, N}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- unknown-name-no-params.mlir
// expected-error @+1 {{has no parameter named 'L'; it has range, dt, max_steps}}
sim.simulation @s range(16) dt(1.0 : f64) max_steps(1) {
}

//--- unknown-after-valid.mlir
// expected-error @+1 {{has no parameter named 'steps'; it has range, dt, max_steps, L, k, b, N}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- int-not-a-number.mlir
// expected-error @+1 {{cannot set parameter 'L': 'four' is not a valid 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- int-from-float.mlir
// expected-error @+1 {{cannot set parameter 'L': '1.5' is not a valid 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- int-empty.mlir
// expected-error @+1 {{cannot set parameter 'L': '' is not a valid 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- int-binary.mlir
// expected-error @+1 {{cannot set parameter 'L': '0b101' is not a valid 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- float-not-a-number.mlir
// expected-error @+1 {{cannot set parameter 'k': 'fast' is not a valid 'f32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- range-not-a-number.mlir
// expected-error @+1 {{cannot set parameter 'range': '16k' is not an integer from 1 to 1099511627776}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- dt-not-a-number.mlir
// expected-error @+1 {{cannot set parameter 'dt': 'small' is not a valid 'f64'}}
sim.simulation @s range(16) dt(1.0 : f64) max_steps(1) {
}

//--- range-zero.mlir
// expected-error @+1 {{cannot set parameter 'range' to 0: it must be at least 1}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- range-negative.mlir
// expected-error @+1 {{cannot set parameter 'range' to -4: it must be at least 1}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- range-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'range': '18446744073709551615' is not an integer from 1 to 1099511627776}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- max-steps-zero.mlir
// expected-error @+1 {{cannot set parameter 'max_steps' to 0: it must be at least 1}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- max-steps-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'max_steps' to 4294967295: it must be at most 1048576}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- dt-zero.mlir
// expected-error @+1 {{cannot set parameter 'dt' to 0: it must be positive and finite}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- dt-negative.mlir
// expected-error @+1 {{cannot set parameter 'dt' to -1.0e-3: it must be positive and finite}}
sim.simulation @s range(16) dt(1.0 : f64) max_steps(1) {
}

//--- dt-inf.mlir
// expected-error @+1 {{cannot set parameter 'dt' to inf: it must be positive and finite}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- dt-nan.mlir
// expected-error @+1 {{cannot set parameter 'dt' to nan: it must be positive and finite}}
sim.simulation @s range(16) dt(1.0 : f64) max_steps(1) {
}

//--- dt-underflow.mlir
// expected-error @+1 {{cannot set parameter 'dt': '1e-50' is out of range for 'f32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i8-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'b': '256' is out of range for 'i8'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i8-unsigned-decimal.mlir
// expected-error @+1 {{cannot set parameter 'b': '255' is out of range for 'i8'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i32-unsigned-decimal.mlir
// expected-error @+1 {{cannot set parameter 'L': '2147483648' is out of range for 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i8-too-negative.mlir
// expected-error @+1 {{cannot set parameter 'b': '-129' is out of range for 'i8'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i8-hex-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'b': '0xFFFF' is out of range for 'i8'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- i32-hex-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'L': '0x1FFFFFFFF' is out of range for 'i32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- index-too-wide.mlir
// expected-error @+1 {{cannot set parameter 'N': '99999999999999999999' is out of range for 'index'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- f32-overflow.mlir
// expected-error @+1 {{cannot set parameter 'k': '1e40' is out of range for 'f32'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
  sim.param @b = 1 : i8
  sim.param @N = 1 : index
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

//--- range-above-limit.mlir
// expected-error @+1 {{cannot set parameter 'range' to 1099511627777: it must be at most 1099511627776}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
}

//--- max-steps-above-limit.mlir
// expected-error @+1 {{cannot set parameter 'max_steps' to 1048577: it must be at most 1048576}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
}

//--- after-front-end.mlir
// After the front end the plan holds decisions made from the values
// (step_cap from max_steps): new values would not reach them.
// expected-error @+1 {{has been through the front end already (a memory plan for strategy 'hip'), which decided from its values; set them on the scene as written, before --sim-front-end}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(64) attributes {step_cap = 64 : i32, strategy = #sim<strategy hip>} {
}

//--- no-equals-spaced.mlir
// expected-error @+1 {{expects a parameter override of the form name=value, but got 'L'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
}

//--- empty-entry.mlir
// A comma too many, at the end or between two entries.
// expected-error @+1 {{expects a parameter override of the form name=value, but got an empty entry; remove the extra comma}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.param @L = 4 : i32
  sim.param @k = 2.5 : f32
}
