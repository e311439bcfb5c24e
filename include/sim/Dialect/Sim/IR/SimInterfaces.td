//===- SimInterfaces.td - sim dialect interfaces -----------*- tablegen -*-===//
//
// Interpolation functions are an attribute interface so that a new one (in
// this dialect or in another) plugs into the passes without touching them:
// the passes only ask an interpolation which buffers it needs at both ends of
// the big step and let it build its own arithmetic.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMINTERFACES_TD
#define SIM_DIALECT_SIM_IR_SIMINTERFACES_TD

include "mlir/IR/OpBase.td"

def Sim_InterpolationAttrInterface
    : AttrInterface<"InterpolationAttrInterface"> {
  let cppNamespace = "::mlir::sim";
  let description = [{
    An interpolation function reconstructs the value of a buffer at an
    intermediate time of a big step `[T, T + h]` from values at both ends
    (Eq. (2) of the paper). It may read auxiliary buffers at both ends as well
    (cubic Hermite reads a derivative buffer). Implementations must be exact
    at both ends: fraction 0 returns the value at `T` and fraction 1 the value
    at `T + h`, bit for bit, so that strategies agree when every big step is a
    single base step.
  }];

  let methods = [
    InterfaceMethod<[{
        Returns the order of accuracy p: interpolating a smooth signal over a
        big step of length h has an error in O(h^p).
      }],
      "unsigned", "getOrderOfAccuracy">,
    InterfaceMethod<[{
        Returns false when the buffer has no meaningful value between the
        ends of a big step (`#sim.none`, written `interp(none)`): no reader
        may need it at an intermediate time, and buildInterpolation must not
        be called.
      }],
      "bool", "isInterpolable", (ins), [{}], [{ return true; }]>,
    InterfaceMethod<[{
        Returns the buffers, besides the interpolated one, whose values at both
        ends of the big step the interpolation reads (for example a time
        derivative). They must have the interpolated buffer's element type.
      }],
      "::llvm::SmallVector<::mlir::FlatSymbolRefAttr>", "getAuxiliaryBuffers",
      (ins), [{}], [{ return {}; }]>,
    InterfaceMethod<[{
        Names the role of auxiliary buffer `index` for diagnostics, such as
        "derivative".
      }],
      "::llvm::StringRef", "getAuxiliaryBufferRole", (ins "unsigned":$index),
      [{}], [{ return "auxiliary"; }]>,
    InterfaceMethod<[{
        Builds the interpolated value. `atBegin` and `atEnd` hold the
        interpolated buffer's value followed by the auxiliary buffers' values
        (in the order of getAuxiliaryBuffers) at `T` and at `T + h`.
        `fraction` is the scalar position in [0, 1] inside the big step and
        `span` the scalar length h of the big step in time units; both have
        the element's scalar float type.
      }],
      "::mlir::Value", "buildInterpolation",
      (ins "::mlir::OpBuilder &":$builder, "::mlir::Location":$loc,
           "::mlir::ValueRange":$atBegin, "::mlir::ValueRange":$atEnd,
           "::mlir::Value":$fraction, "::mlir::Value":$span)>,
  ];
}

#endif // SIM_DIALECT_SIM_IR_SIMINTERFACES_TD
