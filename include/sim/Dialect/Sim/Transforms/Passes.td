//===- Passes.td - sim dialect passes ----------------------*- tablegen -*-===//
//
// The passes of the sim compiler's front end. docs/Passes.md is generated
// from this file; the pipeline they form is described in docs/Pipeline.md.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD
#define SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD

include "mlir/Pass/PassBase.td"

def SimSetParams : Pass<"sim-set-params", "::mlir::sim::SimulationOp"> {
  let summary = "Override scene parameters without editing the scene";
  let description = [{
    Sets `sim.param` defaults and the simulation's `range`, `dt` and
    `max_steps` from a list of `name=value` pairs. Unknown names and values
    that do not parse as the parameter's type are errors.

    ```
    sim-opt scene.mlir --sim-set-params="values=range=16384,L=64"
    ```
  }];
  let options = [
    ListOption<"values", "values", "std::string",
               "name=value pairs; names are range, dt, max_steps or a "
               "sim.param of the scene">,
  ];
}

#endif // SIM_DIALECT_SIM_TRANSFORMS_PASSES_TD
