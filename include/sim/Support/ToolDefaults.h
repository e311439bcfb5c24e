//===- ToolDefaults.h - defaults shared by the sim tools --------*- C++ -*-===//
//
// Defaults the sim tools (sim-opt, sim-translate) set on upstream MLIR
// options before the upstream main parses the command line. Header-only: a
// tool includes it and calls setToolDefaults() first thing in main.
//
// MLIRContext prints the whole operation an error is attached to
// (--mlir-print-op-on-diagnostic, on by default upstream). For our passes that
// operation is a sim.simulation, so every error was followed by a dump of the
// whole scene in generic form, burying the message and its notes. The sim
// tools default the option to false; a user can still turn it on.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_SUPPORT_TOOLDEFAULTS_H
#define SIM_SUPPORT_TOOLDEFAULTS_H

#include "mlir/IR/MLIRContext.h"
#include "llvm/Support/CommandLine.h"
#include "llvm/Support/FileSystem.h"

#include <cstdio>
#include <string>
#include <vector>

namespace mlir::sim {

/// The upstream option that makes MLIRContext attach the operation to every
/// diagnostic (registered by registerMLIRContextCLOptions).
inline constexpr const char *kPrintOpOnDiagnosticOption =
    "mlir-print-op-on-diagnostic";

/// Returns the registered --mlir-print-op-on-diagnostic option, or null when
/// it is not registered. MLIRContext declares it as `cl::opt<bool>`.
inline llvm::cl::opt<bool> *getPrintOpOnDiagnosticOption() {
  registerMLIRContextCLOptions();
  auto &options = llvm::cl::getRegisteredOptions();
  auto it = options.find(kPrintOpOnDiagnosticOption);
  if (it == options.end())
    return nullptr;
  return static_cast<llvm::cl::opt<bool> *>(it->second);
}

/// Sets the sim tools' defaults of upstream options; call it in main before
/// MlirOptMain or mlirTranslateMain parses the command line. Contexts created
/// afterwards do not print the operation on diagnostics unless the user
/// passes --mlir-print-op-on-diagnostic.
inline void setToolDefaults() {
  if (llvm::cl::opt<bool> *option = getPrintOpOnDiagnosticOption())
    option->setInitialValue(false);
}

/// mlirTranslateMain enables printing the operation on every context it
/// creates unless --verify-diagnostics is given, whatever the option says. A
/// translation calls this on its context first so that the option (and its
/// default from setToolDefaults) holds there too. MlirOptMain needs no call.
inline void applyPrintOpOnDiagnosticOption(MLIRContext *context) {
  if (llvm::cl::opt<bool> *option = getPrintOpOnDiagnosticOption())
    context->printOpOnDiagnostic(option->getValue());
}

/// The positional arguments (input files) and the `-o` values (`-o FILE`,
/// `-o=FILE`, `--o=FILE`) of a sim tool's command line. Options of the sim
/// tools take their values after `=`; only `-o` takes the next argument.
struct ToolFiles {
  std::vector<llvm::StringRef> inputs, outputs;
};
inline ToolFiles getToolFiles(int argc, char **argv) {
  ToolFiles files;
  for (int i = 1; i < argc; ++i) {
    llvm::StringRef arg(argv[i]);
    if (arg == "-o" || arg == "--o") {
      if (i + 1 < argc)
        files.outputs.push_back(argv[++i]);
      continue;
    }
    if (arg.consume_front("-o=") || arg.consume_front("--o=")) {
      files.outputs.push_back(arg);
      continue;
    }
    if (!arg.starts_with("-"))
      files.inputs.push_back(arg);
  }
  return files;
}

/// What is wrong with an input of sim-opt or sim-translate that is one of
/// sim-run's binary files (a bundle, a checkpoint): the MLIR parser would
/// print their bytes in its error. Empty when no input is one.
inline std::string describeRuntimeFileInput(int argc, char **argv) {
  for (llvm::StringRef input : getToolFiles(argc, argv).inputs) {
    std::FILE *file = std::fopen(input.str().c_str(), "rb");
    if (!file)
      continue;
    char magic[8] = {};
    size_t read = std::fread(magic, 1, sizeof magic, file);
    std::fclose(file);
    if (read != sizeof magic)
      continue;
    llvm::StringRef start(magic, sizeof magic);
    if (start == llvm::StringRef("SIMBNDL\0", 8))
      return "'" + input.str() +
             "' is a sim bundle (.simb), not MLIR: run it with sim-run";
    if (start == llvm::StringRef("SIMCKPT\0", 8))
      return "'" + input.str() +
             "' is a sim-run checkpoint (.simc), not MLIR: continue it with "
             "sim-run <bundle> --restart";
  }
  return "";
}

/// What is wrong with an output file that is one of the input files:
/// upstream's mains open the output before they run, replace it with the
/// result, and delete it when the run fails, so the scene would be lost or
/// turned into a bundle. Empty when none is.
inline std::string describeOutputOverInput(int argc, char **argv) {
  ToolFiles files = getToolFiles(argc, argv);
  for (llvm::StringRef output : files.outputs)
    for (llvm::StringRef input : files.inputs)
      if (llvm::sys::fs::equivalent(input, output))
        return "the output '" + output.str() + "' is the input '" +
               input.str() +
               "': it would be replaced by the result, or deleted if the "
               "run fails; write the output to another file";
  return "";
}

} // namespace mlir::sim

#endif // SIM_SUPPORT_TOOLDEFAULTS_H
