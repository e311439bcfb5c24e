// RUN: sim-opt %s | FileCheck %s --check-prefix=NONE
// RUN: sim-opt %s --sim-set-params | FileCheck %s --check-prefix=NONE
// RUN: sim-opt %s --sim-set-params="values=range=16384" | FileCheck %s --check-prefix=RANGE
// RUN: sim-opt %s --sim-set-params="values=dt=2.5e-4" | FileCheck %s --check-prefix=DT
// RUN: sim-opt %s --sim-set-params="values=max_steps=8" | FileCheck %s --check-prefix=STEPS
// RUN: sim-opt %s --sim-set-params="values=L=64" | FileCheck %s --check-prefix=INT
// RUN: sim-opt %s --sim-set-params="values=k=0.75" | FileCheck %s --check-prefix=FLOAT
// RUN: sim-opt %s --sim-set-params="values=L=0x40,N=0xFF,b=0x7f" | FileCheck %s --check-prefix=HEX
// RUN: sim-opt %s --sim-set-params="values=L=-3,b=-128" | FileCheck %s --check-prefix=NEG
// RUN: sim-opt %s --sim-set-params="values=b=0xFF" | FileCheck %s --check-prefix=UNSIGNED
// RUN: sim-opt %s --sim-set-params="values=range=16,dt=0.5,max_steps=2,L=7,k=1.5e+01,N=3,L=9" | FileCheck %s --check-prefix=MANY
// RUN: sim-opt %s --sim-set-params="values = range = 16 , dt=0.5,  max_steps =2, L= 7 ,k = 1.5e+01, N=3 ,L=9 " | FileCheck %s --check-prefix=MANY
// RUN: sim-opt %s --sim-set-params=" values= L=64, k=0.75" | FileCheck %s --check-prefix=SPACED
// RUN: sim-opt %s --pass-pipeline="builtin.module(sim.simulation(sim-set-params{values=L = 64, k = 0.75}))" | FileCheck %s --check-prefix=SPACED

// Overrides apply to every simulation of the module, each value converted to
// the type of the attribute or parameter it sets: @single has an f32 time
// step and 32-bit parameters, @double an f64 one and 64-bit parameters.

// NONE-LABEL: sim.simulation @single range(1024) dt(7.812500e-03 : f32) max_steps(4) {
// NONE-NEXT:    sim.param @L = 16 : i32
// NONE-NEXT:    sim.param @k = 2.500000e+00 : f32
// NONE-NEXT:    sim.param @N = 1 : index
// NONE-NEXT:    sim.param @b = 1 : i8
// NONE-LABEL: sim.simulation @double range(512) dt(1.000000e-03 : f64) max_steps(1) {
// NONE-NEXT:    sim.param @L = 16 : i64
// NONE-NEXT:    sim.param @k = 2.500000e+00 : f64
// NONE-NEXT:    sim.param @N = 1 : index
// NONE-NEXT:    sim.param @b = 1 : i8

// RANGE-LABEL: sim.simulation @single range(16384) dt(7.812500e-03 : f32) max_steps(4) {
// RANGE-NEXT:    sim.param @L = 16 : i32
// RANGE-LABEL: sim.simulation @double range(16384) dt(1.000000e-03 : f64) max_steps(1) {

// DT-LABEL: sim.simulation @single range(1024) dt(2.500000e-04 : f32) max_steps(4) {
// DT-LABEL: sim.simulation @double range(512) dt(2.500000e-04 : f64) max_steps(1) {

// STEPS-LABEL: sim.simulation @single range(1024) dt(7.812500e-03 : f32) max_steps(8) {
// STEPS-LABEL: sim.simulation @double range(512) dt(1.000000e-03 : f64) max_steps(8) {

// INT-LABEL: sim.simulation @single range(1024) dt(7.812500e-03 : f32) max_steps(4) {
// INT-NEXT:    sim.param @L = 64 : i32
// INT-NEXT:    sim.param @k = 2.500000e+00 : f32
// INT-LABEL: sim.simulation @double
// INT-NEXT:    sim.param @L = 64 : i64
// INT-NEXT:    sim.param @k = 2.500000e+00 : f64

// FLOAT-LABEL: sim.simulation @single
// FLOAT-NEXT:    sim.param @L = 16 : i32
// FLOAT-NEXT:    sim.param @k = 7.500000e-01 : f32
// FLOAT-LABEL: sim.simulation @double
// FLOAT-NEXT:    sim.param @L = 16 : i64
// FLOAT-NEXT:    sim.param @k = 7.500000e-01 : f64

// HEX-LABEL: sim.simulation @single
// HEX-NEXT:    sim.param @L = 64 : i32
// HEX-NEXT:    sim.param @k = 2.500000e+00 : f32
// HEX-NEXT:    sim.param @N = 255 : index
// HEX-NEXT:    sim.param @b = 127 : i8
// HEX-LABEL: sim.simulation @double
// HEX-NEXT:    sim.param @L = 64 : i64

// NEG-LABEL: sim.simulation @single
// NEG-NEXT:    sim.param @L = -3 : i32
// NEG:         sim.param @b = -128 : i8
// NEG-LABEL: sim.simulation @double
// NEG-NEXT:    sim.param @L = -3 : i64
// NEG:         sim.param @b = -128 : i8

// A hexadecimal value gives the bits: it may use the whole unsigned range
// of the width (a decimal one only the signed range, see the invalid tests).
// UNSIGNED-LABEL: sim.simulation @single
// UNSIGNED:         sim.param @b = -1 : i8

// Whitespace around names, `=` and commas is not part of them (MLIR's
// option parser would end the option at the first blank).
// SPACED-LABEL: sim.simulation @single
// SPACED-NEXT:    sim.param @L = 64 : i32
// SPACED-NEXT:    sim.param @k = 7.500000e-01 : f32
// SPACED-LABEL: sim.simulation @double
// SPACED-NEXT:    sim.param @L = 64 : i64
// SPACED-NEXT:    sim.param @k = 7.500000e-01 : f64

// Several overrides at once, also with blanks around names, `=` and commas;
// a name given twice takes the last value.
// MANY-LABEL: sim.simulation @single range(16) dt(5.000000e-01 : f32) max_steps(2) {
// MANY-NEXT:    sim.param @L = 9 : i32
// MANY-NEXT:    sim.param @k = 1.500000e+01 : f32
// MANY-NEXT:    sim.param @N = 3 : index
// MANY-NEXT:    sim.param @b = 1 : i8
// MANY-LABEL: sim.simulation @double range(16) dt(5.000000e-01 : f64) max_steps(2) {
// MANY-NEXT:    sim.param @L = 9 : i64
// MANY-NEXT:    sim.param @k = 1.500000e+01 : f64
// MANY-NEXT:    sim.param @N = 3 : index
// MANY-NEXT:    sim.param @b = 1 : i8

sim.simulation @single range(1024) dt(7.8125e-3 : f32) max_steps(4) {
  sim.param @L = 16 : i32
  sim.param @k = 2.5 : f32
  sim.param @N = 1 : index
  sim.param @b = 1 : i8
}

sim.simulation @double range(512) dt(1.0e-3 : f64) max_steps(1) {
  sim.param @L = 16 : i64
  sim.param @k = 2.5 : f64
  sim.param @N = 1 : index
  sim.param @b = 1 : i8
}
