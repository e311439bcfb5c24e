//===- PlanDialect.td - the simplan dialect definition -----*- tablegen -*-===//
//
// The host side of a lowered simulation: what the runtime allocates, which
// kernels it launches in which order with which arguments, and how a big step
// repeats. docs/Plan.md explains how a runtime executes it.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_PLAN_IR_PLANDIALECT_TD
#define SIM_DIALECT_PLAN_IR_PLANDIALECT_TD

include "mlir/IR/DialectBase.td"

def Plan_Dialect : Dialect {
  let name = "simplan";
  let cppNamespace = "::mlir::simplan";
  let summary = "The host plan of a lowered simulation";
  let description = [{
    `--sim-lower-to-gpu` turns a `sim.simulation` into kernels (a
    `gpu.module`) and a `simplan.plan`: the host side of Algorithm 2 and of
    the baselines. A plan names the buffers to allocate, the scene
    parameters, the device-resident clock, and three phases of kernel
    launches: `init` (once), `step` (one big step, repeated until the clock
    reaches the end of the run) and `finish` (once, after the last big step).
    Every decision that depends on the state (the size of the next big step,
    the number of sub-steps) is taken on the device and kept in the clock, so
    the host never reads a value back between big steps and can launch many
    big steps ahead.

    Every kernel the lowering makes records, as discardable attributes of
    its function, what each launch of it must agree with:
    `simplan.shared = array<i64: per_thread, fixed>` (its dynamic shared
    memory) and `simplan.clock_slots = N : i64` (the clock it addresses); a
    CPU kernel also has `simplan.group_arguments = 3 : i64` (its trailing
    group arguments). The bundle writer copies them into the bundle, where
    the runtime checks every launch against them.

    ```mlir
    simplan.plan @decay strategy("hip") kernels(@decay_kernels) range(1024)
        dt(1.0e-2 : f32) max_steps(4) step_cap(4) group_size(256)
        clock_slots(14) histogram(9) {
      simplan.buffer @X : f32 stride(4) observed
      simplan.phase init {
        simplan.launch @decay_kernels::@init_X items
            [#simplan.arg<clock>, #simplan.arg<buffer @X>, #simplan.arg<range>]
      }
      ...
    }
    ```
  }];
  let dependentDialects = ["::mlir::sim::SimDialect"];
  let useDefaultAttributePrinterParser = 1;
  let hasOperationAttrVerify = 1;
  let extraClassDeclaration = [{
    void registerAttributes();
    /// On a kernel function: the number of trailing arguments that are not
    /// launch arguments (a CPU kernel's first group, end group and group
    /// size).
    static ::llvm::StringRef getGroupArgumentsAttrName() {
      return "simplan.group_arguments";
    }
    /// On a kernel function: the dynamic shared memory every launch of it
    /// needs, `array<i64: per_thread, fixed>` (bytes: `per_thread * group
    /// size + fixed`), as the lowering planned its caches.
    static ::llvm::StringRef getSharedAttrName() { return "simplan.shared"; }
    /// On a kernel function: the number of clock slots (`i64`) it was
    /// compiled for, the plan's `clock_slots`.
    static ::llvm::StringRef getClockSlotsAttrName() {
      return "simplan.clock_slots";
    }
    /// On a kernel function: a unit attribute where the work of its groups
    /// differs widely within a launch and between launches (a slot kernel
    /// of local time steps: only the blocks whose sub-step starts at the
    /// slot evaluate), so that a runtime splitting a launch over threads
    /// deals it in finer parts (docs/Runtime.md, "Backends").
    static ::llvm::StringRef getUnevenGroupsAttrName() {
      return "simplan.uneven_groups";
    }
    /// On an `scf.for` of a CPU kernel: the loop over the lanes of a group
    /// in one phase, whose iterations are independent (the threads of a GPU
    /// block between two barriers), so --sim-vectorize-lanes may run them
    /// in SIMD lanes.
    static ::llvm::StringRef getLanesAttrName() { return "simplan.lanes"; }
  }];
}

#endif // SIM_DIALECT_PLAN_IR_PLANDIALECT_TD
