//===- CompileFuzzer.cpp - libFuzzer target of the compiler's front end ---===//
//
// Feeds arbitrary text to what sim-opt and sim-translate do with a scene
// before LLVM's code generators: the parser and verifier, the front end
// (--sim-front-end) for one strategy, then the lowering to GPU or CPU
// kernels and a plan, or the reference pipeline. The first byte picks the
// strategy and the path; the rest is the scene. Any input must end in a
// result or in diagnostics; a crash, an assertion, a hang or a sanitizer
// report is a bug (docs/Testing.md).
//
// Built with libFuzzer when SIM_ENABLE_FUZZERS is on; otherwise linked
// with runtime/fuzz/ReplayMain.cpp, which runs the kept corpus
// (test/Fuzz/corpus-compile) as a regression test.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Pipelines/Pipelines.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/UB/IR/UBOps.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/Parser/Parser.h"
#include "mlir/Pass/PassManager.h"

#include <cstdint>
#include <string>

using namespace mlir;

namespace {

const DialectRegistry &getRegistry() {
  static DialectRegistry registry = [] {
    DialectRegistry registry;
    registry.insert<sim::SimDialect, simplan::PlanDialect, arith::ArithDialect,
                    func::FuncDialect, gpu::GPUDialect, LLVM::LLVMDialect,
                    math::MathDialect, memref::MemRefDialect, scf::SCFDialect,
                    ub::UBDialect, vector::VectorDialect>();
    return registry;
  }();
  return registry;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0)
    return 0;
  uint8_t mode = data[0];
  std::string text(reinterpret_cast<const char *>(data + 1), size - 1);

  MLIRContext context(getRegistry(), MLIRContext::Threading::DISABLED);
  // Diagnostics are the expected answer to bad input: drop them.
  ScopedDiagnosticHandler quiet(&context,
                                [](Diagnostic &) { return success(); });
  OwningOpRef<ModuleOp> module = parseSourceString<ModuleOp>(text, &context);
  if (!module)
    return 0;

  PassManager pm(&context, ModuleOp::getOperationName());
  pm.enableVerifier(true);
  if ((mode >> 2) % 3 == 2) {
    sim::buildReferencePipeline(pm, sim::ReferenceOptions());
  } else {
    sim::FrontEndOptions frontEnd;
    frontEnd.strategy = sim::Strategy(mode % 4);
    frontEnd.groupSize = (mode & 0x80) ? 32 : 256;
    sim::buildFrontEndPipeline(pm, frontEnd);
    if ((mode >> 2) % 3 == 0) {
      sim::SimLowerToGPUOptions lowering;
      lowering.groupSize = frontEnd.groupSize;
      pm.addPass(sim::createSimLowerToGPU(lowering));
    } else {
      sim::SimLowerToCPUOptions lowering;
      lowering.groupSize = frontEnd.groupSize;
      pm.addPass(sim::createSimLowerToCPU(lowering));
    }
  }
  (void)pm.run(*module);
  return 0;
}
