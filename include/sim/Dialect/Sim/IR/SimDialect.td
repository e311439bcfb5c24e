//===- SimDialect.td - the sim dialect definition ----------*- tablegen -*-===//
//
// The `sim` dialect describes component-based simulations with adaptive,
// multi-rate time steps (see docs/Model.md and the paper in
// shared/paper/adaptive-time-steps-gpu.txt).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMDIALECT_TD
#define SIM_DIALECT_SIM_IR_SIMDIALECT_TD

include "mlir/IR/DialectBase.td"

def Sim_Dialect : Dialect {
  let name = "sim";
  let cppNamespace = "::mlir::sim";
  let summary = "Component-based simulations with adaptive, multi-rate time steps";
  let description = [{
    A `sim.simulation` holds double-buffered state buffers (`sim.buffer`), the
    components that advance them (`sim.component`), scene parameters
    (`sim.param`), an optional user schedule (`sim.schedule`) and the observed
    outputs (`sim.observe`). Components read state only through view reads
    (`sim.read @B[%j]`: "buffer B at item j at my current local time"), so
    the compiler can decide, per read, whether the value comes from the start
    of the big step, from the end of it, from an interpolation in between, or
    from the component's own sub-step state.

    Time is an integer count of base steps. A big step of `m` base steps is
    chosen per strategy (`simple`, `traditional`, `hip`); inside it every
    component advances its own buffers from `T` to `T + m` in sub-steps of
    `n` base steps.

    ```mlir
    sim.simulation @decay range(1024) dt(1.0e-2 : f32) max_steps(4) {
      sim.buffer @X : f32 interp(#sim.linear) init {
      ^bb0(%i: index):
        %one = arith.constant 1.0 : f32
        sim.yield %one : f32
      }
      sim.component @Decay writes(@X) evaluate {
      ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
        %x = sim.read @X[%i] : f32
        %nf = arith.sitofp %n : i32 to f32
        %h = arith.mulf %nf, %dt : f32
        %dx = arith.mulf %h, %x : f32
        %next = arith.subf %x, %dx : f32
        sim.yield %next : f32
      }
      sim.observe [@X]
    }
    ```
  }];
  let extraClassDeclaration = [{
    /// Registers the attributes (defined next to their storage classes).
    void registerAttributes();

    /// Parses `#sim.<mnemonic>...` and `#sim<...>` attributes and rejects
    /// text left after them (the generated parser alone would read
    /// `#sim<strategy hip-cache>` as `hip` and ignore the rest).
    ::mlir::Attribute parseAttribute(::mlir::DialectAsmParser &parser,
                                     ::mlir::Type type) const override;
    void printAttribute(::mlir::Attribute attr,
                        ::mlir::DialectAsmPrinter &printer) const override;
  }];
}

#endif // SIM_DIALECT_SIM_IR_SIMDIALECT_TD
