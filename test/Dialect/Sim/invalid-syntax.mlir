// RUN: sim-opt %s --split-input-file --verify-diagnostics

// Errors of the custom parsers: read roles, boundary rules, load versions,
// interpolation attributes, symbol lists and clause order.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{custom op 'sim.read' expected a read role (own, interpolate or back_edge), but got 'sideways'}}
    %x = sim.read @B[%i] sideways : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // A type keyword where the role goes is read as a role.
    // expected-error @+1 {{custom op 'sim.read' expected a read role (own, interpolate or back_edge), but got 'f32'}}
    %x = sim.read @B[%i] f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.buffer' expected a boundary rule (clamp, wrap or zero), but got 'mirror'}}
  sim.buffer @B : f32 boundary(mirror) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.buffer' expected a boundary rule (clamp, wrap or zero)}}
  sim.buffer @B : f32 boundary() init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.buffer' expected a boundary rule (clamp, wrap or zero)}}
  sim.buffer @B : f32 boundary(1) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{expected ')'}}
  sim.buffer @B : f32 boundary(wrap init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

// Each clause at most once (either order is fine).
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{the buffer has two boundary clauses}}
  sim.buffer @B : f32 boundary(wrap) interp(#sim.linear) boundary(zero) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{the buffer has two interp clauses}}
  sim.buffer @B : f32 interp(#sim.cubic) interp(#sim.linear) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.buffer' expected an interpolation function such as #sim.linear, #sim.cubic or #sim.hermite<@derivative>, or none, but got #sim<boundary wrap>}}
  sim.buffer @B : f32 interp(#sim<boundary wrap>) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{unknown attribute `quadratic` in dialect `sim`}}
  sim.buffer @B : f32 interp(#sim.quadratic) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+2 {{invalid kind of attribute specified}}
  // expected-error @+1 {{failed to parse Sim_HermiteInterpAttr parameter 'derivative' which is to be a `::mlir::FlatSymbolRefAttr`}}
  sim.buffer @X : f32 interp(#sim.hermite<"V">) init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.buffer' 'sim.buffer' op attribute 'boundary' failed to satisfy constraint: rule for reads outside the item range}}
  sim.buffer @B : f32 attributes {boundary = 1 : i32} init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{custom op 'sim.load' expected the copy to load (source, snapshot, target or local), but got 'middle'}}
    %x = sim.load middle @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{custom op 'sim.load' expected the copy to load (source, snapshot, target or local)}}
    %x = sim.load @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{expected '('}}
  sim.component @C writes @B evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.component' expected valid '@'-identifier for symbol name}}
  sim.component @C writes(B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    sim.yield
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.component' expected valid '@'-identifier for symbol name}}
  sim.component @C writes(@B,) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    sim.yield
  }
}

// -----

// num_steps comes before evaluate.
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  // expected-error @+1 {{custom op 'sim.component' expected 'evaluate'}}
  sim.component @C writes(@B) {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

// expected-error @+1 {{custom op 'sim.simulation' expected 'dt'}}
sim.simulation @s range(16) max_steps(1) {
}

// -----

// expected-error @+1 {{integer constant out of range for attribute}}
sim.simulation @s range(99999999999999999999) dt(1.0 : f32) max_steps(1) {
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{expected '='}}
  sim.param @L 3 : i32
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{expected ','}}
    %T = sim.big_step : i64
    %x = sim.read @B[%i] : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{custom op 'sim.observe' invalid kind of attribute specified}}
  sim.observe @B
}

// -----

// Unquoted, hip-cache would lex as `hip` followed by `-cache`; the rest of
// an attribute body is never silently dropped.
// expected-error @+1 {{unexpected '-cache' after the attribute value 'strategy hip'; a value spelled with '-' is written in quotes, as in #sim<strategy "hip-cache">}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {strategy = #sim<strategy hip-cache>} {
}

// -----

// expected-error @+1 {{unexpected 'in_kernel' after the attribute value 'parity none'}}
sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) attributes {p = #sim<parity none in_kernel>} {
}

// -----

// A name used before its definition resolves to a definition inside a
// buffer's init; the exact body then fails to parse. The init is freed with
// the failed op, and the use outside it must not point into it (the
// parser's cleanup wrote to freed memory, and aborted sim-translate on
// scenes utils/mutate-scenes.py made). valgrind reports it; ASan does not,
// since the write happens inside Debian's uninstrumented MLIR library.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  %early = arith.addf %late, %late : f32
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %late = arith.constant 0.0 : f32
    sim.yield %late : f32
  } exact {
  ^bb0(%i: index, %t: f64):
    // expected-error @+1 {{custom op 'arith.cmpi' expected string or keyword containing one of the following enum values}}
    %x = arith.cmpi %t, %t : f64
    sim.yield %x : f32
  }
}

// -----

// The same through a component's num_steps and a failing evaluate body.

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  %early = arith.addi %late, %late : i32
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@B) num_steps {
  ^bb0(%i: index, %t: i64):
    %late = arith.constant 1 : i32
    sim.yield %late : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    // expected-error @+1 {{custom op 'arith.cmpi' expected string or keyword containing one of the following enum values}}
    %x = arith.cmpi %dt, %dt : f32
    sim.yield %x : f32
  }
}

// -----

sim.simulation @s range(16) dt(1.0 : f32) max_steps(1) {
  // expected-error @+1 {{the buffer is declared constant twice}}
  sim.buffer @K : f32 constant boundary(zero) constant init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
}
