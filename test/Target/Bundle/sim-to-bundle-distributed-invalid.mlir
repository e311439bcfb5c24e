// A distributed bundle records each buffer's halo in 32 bits and a rank
// holds at most 2^20 ghost items on each side: a window that reaches
// further is refused at the buffer, not truncated into a plan that reads
// outside the rank's storage. (Strategy simple fails first; it explains no
// sub-stepping verdict.)
//
// RUN: sim-translate --sim-to-bundle --sim-cpu-isas=host --sim-distributed %s --split-input-file --verify-diagnostics -o %t.simb

// expected-note @+1 {{while compiling the bundle's strategy 'simple'}}
sim.simulation @far range(64) dt(1.0e-2 : f32) max_steps(2) {
  // expected-error @+1 {{@X is read 1099511627776 items away from the reading item, and a distributed run holds at most 1048576 ghost items on each side of a rank's block: narrow the window, or compile without --sim-distributed}}
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %far = arith.constant 1099511627776 : index
    %j = arith.subi %i, %far : index
    %x = sim.read @X[%j] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}

// -----

// One past the limit, above the item.
// expected-note @+1 {{while compiling the bundle's strategy 'simple'}}
sim.simulation @just_past range(64) dt(1.0e-2 : f32) max_steps(2) {
  // expected-error @+1 {{@X is read 1048577 items away from the reading item}}
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @C writes(@X) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %far = arith.constant 1048577 : index
    %j = arith.addi %i, %far : index
    %x = sim.read @X[%j] : f32
    sim.yield %x : f32
  }
  sim.observe [@X]
}
