//===- TranslationOptions.h - options of sim-translate ----------*- C++ -*-===//
//
// The command-line options of sim's translations (--sim-chip=...), shared by
// the PTX translations and the bundle writer. mlir-translate-style tools
// have no pipeline syntax, so what a pipeline option says is a translation
// option here. The options exist once per process and are registered by the
// first call to getTranslationOptions(), which registerSimTranslations()
// makes before the command line is parsed.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_TRANSLATIONOPTIONS_H
#define SIM_TARGET_TRANSLATIONOPTIONS_H

#include "sim/Dialect/Sim/IR/SimAttrs.h"

#include "llvm/Support/CommandLine.h"

#include <string>

namespace mlir {
class OpPassManager;
} // namespace mlir

namespace mlir::sim {

struct GPUTargetOptions;

/// Parses --sim-opt-level, refusing levels LLVM does not have on the
/// command line (the GPU back end refused them only after the front end
/// had run, once per strategy).
struct OptLevelParser : llvm::cl::parser<unsigned> {
  using llvm::cl::parser<unsigned>::parser;
  bool parse(llvm::cl::Option &option, llvm::StringRef argName,
             llvm::StringRef arg, unsigned &value);
};

/// Parses a strategy name of --sim-strategy and --sim-strategies, naming
/// the strategies there are when a name is none of them (LLVM's parser
/// says "Cannot find option named ''!" for an empty list).
struct StrategyParser : llvm::cl::parser<Strategy> {
  using llvm::cl::parser<Strategy>::parser;
  bool parse(llvm::cl::Option &option, llvm::StringRef argName,
             llvm::StringRef arg, Strategy &value);
};

/// The options of sim-translate's translations. Their defaults are those of
/// the pipelines' option structs (lib/Pipelines).
struct TranslationOptions {
  TranslationOptions();

  llvm::cl::OptionCategory category;
  /// --sim-strategy: the strategy of --sim-to-ptx.
  llvm::cl::opt<Strategy, false, StrategyParser> strategy;
  /// --sim-strategies: the strategies of --sim-to-bundle (empty: all five,
  /// without lts for a distributed bundle).
  llvm::cl::list<Strategy, bool, StrategyParser> strategies;
  /// --sim-group-size: threads per thread group.
  llvm::cl::opt<unsigned> groupSize;
  /// --sim-chip, --sim-features, --sim-opt-level, --sim-cuda-path: the GPU
  /// back end's target (the optimization level applies to CPU kernels too).
  llvm::cl::opt<std::string> chip;
  llvm::cl::opt<std::string> features;
  llvm::cl::opt<unsigned, false, OptLevelParser> optLevel;
  llvm::cl::opt<std::string> cudaPath;
  /// --sim-set-params: name=value pairs that --sim-set-params applies to
  /// the scene before it is compiled (max_steps, range, dt, parameters).
  llvm::cl::list<std::string> setParams;
  /// --sim-cpu-isas: the instruction-set levels of --sim-to-bundle's CPU
  /// kernels (empty: BundleOptions' default).
  llvm::cl::list<std::string> cpuIsas;
  /// --sim-ftz: flush subnormals to zero on every backend.
  llvm::cl::opt<bool> ftz;
  /// --sim-gpu-narrow-loops: 32-bit counters in the GPU kernels' loops.
  llvm::cl::opt<bool> gpuNarrowLoops;
  /// --sim-gpu-unroll: unroll factor of the GPU kernels' innermost loops.
  llvm::cl::opt<unsigned> gpuUnroll;
  /// --sim-distributed: plans for many processes.
  llvm::cl::opt<bool> distributed;
  /// --sim-cpu-levels-per-lane (hidden): the CPU kernels limit lts levels
  /// as the GPU kernels do, so that tests run the GPU's algorithm.
  llvm::cl::opt<bool> cpuLevelsPerLane;

  /// The GPU back end's target the flags describe.
  GPUTargetOptions getGPUTarget() const;
  /// Adds --sim-set-params with the values of --sim-set-params=... to `pm`
  /// (nested on every sim.simulation of a module), if any were given.
  void addSetParams(OpPassManager &pm) const;
};

/// Returns the process's translation options, registering them on the first
/// call.
const TranslationOptions &getTranslationOptions();

} // namespace mlir::sim

#endif // SIM_TARGET_TRANSLATIONOPTIONS_H
