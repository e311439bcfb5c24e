// RUN: sim-opt %s --split-input-file --verify-diagnostics --allow-unregistered-dialect

// Errors of #simplan.arg and of the simplan records on kernel functions
// (PlanDialect::verifyOperationAttribute).

// expected-error @+1 {{a 'buffer' argument names a symbol}}
"test.op"() {arg = #simplan.arg<buffer>} : () -> ()

// -----

// expected-error @+1 {{a 'range' argument takes no symbol}}
"test.op"() {arg = #simplan.arg<range @X>} : () -> ()

// -----

// expected-error @+1 {{unknown launch argument kind 'max_steps'}}
"test.op"() {arg = #simplan.arg<max_steps>} : () -> ()

// -----

// expected-error @+1 {{expected a symbol after the argument kind}}
"test.op"() {arg = #simplan.arg<param 3>} : () -> ()

// -----

// expected-error @+1 {{'simplan.shared' must be array<i64: per_thread, fixed> of two byte counts of at least 0, not array<i64: 4>}}
func.func @k() attributes {simplan.shared = array<i64: 4>} {
  return
}

// -----

// expected-error @+1 {{'simplan.shared' must be array<i64: per_thread, fixed> of two byte counts of at least 0, not array<i64: 4, -8>}}
func.func @k() attributes {simplan.shared = array<i64: 4, -8>} {
  return
}

// -----

// expected-error @+1 {{'simplan.shared' must be array<i64: per_thread, fixed> of two byte counts of at least 0, not [4, 8]}}
func.func @k() attributes {simplan.shared = [4, 8]} {
  return
}

// -----

// expected-error @+1 {{'simplan.clock_slots' must be a positive i64 slot count, not 0}}
func.func @k() attributes {simplan.clock_slots = 0 : i64} {
  return
}

// -----

// expected-error @+1 {{'simplan.clock_slots' must be a positive i64 slot count, not 12 : i32}}
func.func @k() attributes {simplan.clock_slots = 12 : i32} {
  return
}

// -----

// expected-error @+1 {{'simplan.group_arguments' must be an i64 count of trailing arguments, not -1}}
func.func @k() attributes {simplan.group_arguments = -1 : i64} {
  return
}

// -----

// expected-error @+1 {{'simplan.uneven_groups' must be a unit attribute}}
func.func @k() attributes {simplan.uneven_groups = true} {
  return
}

// -----

// expected-error @+1 {{'simplan.uneven_groups' is a record of a kernel function, but 'test.op' is not a function}}
"test.op"() {simplan.uneven_groups} : () -> ()

// -----

// expected-error @+1 {{'simplan.stride' is not an attribute of the simplan dialect}}
func.func @k() attributes {simplan.stride = 4 : i64} {
  return
}

// -----

// expected-error @+1 {{'simplan.clock_slots' is a record of a kernel function, but 'test.op' is not a function}}
"test.op"() {simplan.clock_slots = 12 : i64} : () -> ()

// -----

// expected-error @+1 {{'simplan.lanes' marks the loop over a group's lanes, but 'test.op' is not an scf.for}}
"test.op"() {simplan.lanes} : () -> ()

// -----

func.func @k(%n: index) {
  %c0 = arith.constant 0 : index
  %c1 = arith.constant 1 : index
  // expected-error @+1 {{'simplan.lanes' must be a unit attribute}}
  scf.for %i = %c0 to %n step %c1 {
  } {simplan.lanes = 1 : i64}
  return
}
