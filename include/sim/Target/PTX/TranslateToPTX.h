//===- TranslateToPTX.h - scenes and gpu.modules to PTX ---------*- C++ -*-===//
//
// Declares the translations to PTX text of sim-translate.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_PTX_TRANSLATETOPTX_H
#define SIM_TARGET_PTX_TRANSLATETOPTX_H

namespace mlir::sim {

/// Registers `--sim-to-ptx` (a scene through buildSimToGPUPipeline) and
/// `--gpu-to-ptx` (gpu.modules through buildSimGPUToPTXPipeline), and their
/// options `--sim-strategy`, `--sim-group-size`, `--sim-chip`,
/// `--sim-features`, `--sim-opt-level` and `--sim-cuda-path`.
void registerToPTXTranslations();

} // namespace mlir::sim

#endif // SIM_TARGET_PTX_TRANSLATETOPTX_H
