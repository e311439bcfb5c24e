//===- CPUKernels.cpp - CPU kernels to a shared object --------------------===//
//
// Upstream conversions take the kernels to the LLVM dialect and LLVM IR; this
// file adds what is ours: the `sim_cpu_<kernel>(void **params, ...)` entry
// points, which unpack the same argument array a CUDA launch takes (a memref
// is five values: allocated and aligned pointer, offset, size, stride), so
// the runtime calls every kernel the same way on both backends. The object
// is made in process by an LLVM TargetMachine for the host, then linked into
// a shared object with the system's ld.lld.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/CPUKernels.h"
#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Runtime/CpuLevels.h"

#include "mlir/Conversion/Passes.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/MemRef/Transforms/Passes.h"
#include "mlir/ExecutionEngine/OptUtils.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/Pass/PassManager.h"
#include "mlir/Target/LLVMIR/Dialect/Builtin/BuiltinToLLVMIRTranslation.h"
#include "mlir/Target/LLVMIR/Dialect/LLVMIR/LLVMToLLVMIRTranslation.h"
#include "mlir/Target/LLVMIR/Export.h"

#include "llvm/ADT/ScopeExit.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/IR/IRBuilder.h"
#include "llvm/IR/LegacyPassManager.h"
#include "llvm/IR/Module.h"
#include "llvm/MC/TargetRegistry.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/FileUtilities.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/Program.h"
#include "llvm/Support/Signals.h"
#include "llvm/Support/TargetSelect.h"
#include "llvm/Support/ThreadPool.h"
#include "llvm/Target/TargetMachine.h"
#include "llvm/TargetParser/Host.h"

#include <atomic>
#include <cstdlib>

using namespace mlir;
using namespace mlir::sim;

void mlir::sim::registerCPUKernelDialects(DialectRegistry &registry) {
  registerBuiltinDialectTranslation(registry);
  registerLLVMDialectTranslation(registry);
}

/// Adds `sim_cpu_<name>(ptr params, i64, i64, i64)` for kernel `name`: loads
/// each parameter of the kernel from params[i], passes the group arguments.
static void addEntryPoint(llvm::Module &module, llvm::Function &kernel) {
  llvm::LLVMContext &context = module.getContext();
  llvm::Type *ptr = llvm::PointerType::getUnqual(context);
  llvm::Type *i64 = llvm::Type::getInt64Ty(context);
  auto *type = llvm::FunctionType::get(llvm::Type::getVoidTy(context),
                                       {ptr, i64, i64, i64}, false);
  auto *entry = llvm::Function::Create(type, llvm::Function::ExternalLinkage,
                                       "sim_cpu_" + kernel.getName(), module);
  llvm::IRBuilder<> builder(llvm::BasicBlock::Create(context, "", entry));
  llvm::Value *params = entry->getArg(0);
  SmallVector<llvm::Value *> args;
  unsigned launchArgs = kernel.arg_size() - 3;
  for (unsigned index = 0; index < launchArgs; ++index) {
    llvm::Value *slot = builder.CreateConstGEP1_64(ptr, params, index);
    llvm::Value *address = builder.CreateLoad(ptr, slot);
    args.push_back(
        builder.CreateLoad(kernel.getArg(index)->getType(), address));
  }
  for (unsigned index = 1; index <= 3; ++index)
    args.push_back(entry->getArg(index));
  builder.CreateCall(&kernel, args);
  builder.CreateRetVoid();
  kernel.setLinkage(llvm::Function::InternalLinkage);
  // The kernel stays a function of its own, called once per launch.
  // Inlined into the entry point, the in-step chunk loop of
  // `own-index-none`'s lts slot kernel reloaded its run length from the
  // stack in every iteration, and ran 2.3x slower on an AMD EPYC with
  // AVX-512 (4096 items: 27 ms against 11.6 ms, hip 18 ms) than the same
  // loop without that reload, out of line (as every kernel of a --sim-ftz
  // bundle was already). Out of line, the paper and physics scenes run as
  // fast as before under every strategy (docs/benchmarks.md, "Kernels out
  // of line").
  kernel.addFnAttr(llvm::Attribute::NoInline);
}

/// Optimises `module` for instruction-set level `isa` and compiles and links
/// it into the bytes of a shared object.
static FailureOr<std::string> compileForIsa(llvm::Module &module, Location loc,
                                            StringRef isa, unsigned optLevel,
                                            StringRef linkerPath);

/// Lowers each of `modules` (func.funcs of upstream dialects; not changed)
/// to LLVM IR per level of `isas`, lets `finish(module index, IR)` add to it,
/// and compiles and links it into the bytes of a shared object whose
/// external functions are those of the module. Returns the objects of each
/// module in the order of `isas`.
static FailureOr<SmallVector<SmallVector<std::string>>> compileSharedObjects(
    ArrayRef<ModuleOp> modules, ArrayRef<std::string> isas, unsigned optLevel,
    bool flushSubnormals, bool kernels, StringRef linker,
    function_ref<LogicalResult(size_t, llvm::Module &)> finish) {
  if (modules.empty())
    return SmallVector<SmallVector<std::string>>();
  for (const std::string &isa : isas)
    if (!llvm::is_contained(getCPUIsaLevels(), isa))
      return emitError(modules.front()->getLoc())
             << "unknown CPU instruction-set level '" << isa
             << "' (known: " << llvm::join(getCPUIsaLevels(), ", ") << ")";
  llvm::InitializeNativeTarget();
  llvm::InitializeNativeTargetAsmPrinter();

  // The lanes a SIMD register of each level holds (f32), which is how many
  // lanes of a group the kernels run at once there: the widened values of a
  // vec4 scene stay in registers on AVX2 at 8 lanes and on AVX-512 at 16
  // (measured: 16 lanes spill on AVX2 and cost 1.3-1.4x). The levels below
  // AVX2 are fallbacks for old CPUs: their kernels keep scalar lanes and
  // libm's tanhf (the same bits), which compile 3-4 times faster than the
  // widened ones.
  auto lanesFor = [](StringRef isa) -> int64_t {
    if (isa == "x86-64-v4")
      return 16;
    if (isa == "x86-64-v3")
      return 8;
    return 1;
  };

  // To the LLVM dialect with upstream conversions, per level (the lanes
  // differ).
  MLIRContext *mlirContext = modules.front()->getContext();
  auto pipelineFor = [&](PassManager &pm, StringRef isa) {
    // No conversion lowers math.ipowi: multiplications, as on the GPU.
    pm.addPass(createSimExpandIntegerPowers());
    // Nor contract, outerproduct, multi_reduction, transpose or step: 1-D
    // vector ops, as on the GPU.
    pm.addPass(createSimLowerVectorOps());
    if (kernels && lanesFor(isa) > 1) {
      // A group's lanes side by side in SIMD registers, while the kernels
      // are still scf and vector ops.
      SimVectorizeLanesOptions lanes;
      lanes.width = lanesFor(isa);
      // AVX-512DQ converts vectors of i64 to and from f64 (vcvtqq2pd).
      lanes.wideIntConversions = isa == "x86-64-v4";
      // A round of a vec4 product keeps 32 vectors live when its four
      // element chains interleave: AVX2 has 16 registers, and chain by
      // chain its rounds take 101-109 instructions per 64 FMAs instead of
      // 151 (docs/benchmarks.md). AVX-512's 32 held them: there the order
      // stays (96 instructions against 103 chain by chain; not measured).
      lanes.chainsApart = isa == "x86-64-v3";
      pm.addPass(createSimVectorizeLanes(lanes));
      // A widened fpowi (an exponent per lane) as one fpowi per lane.
      pm.addPass(createSimLowerVectorOps());
      // f32 tanh as glibc computes it, in SIMD instructions instead of a
      // libm call per element (the same bits). Not in the reference
      // functions: they call libm itself, so the cross-check compares the
      // two.
      pm.addPass(createSimExpandTanh());
    }
    // vector.fma rounds once here as on the GPU (not llvm.intr.fmuladd).
    pm.addPass(createSimFusedMultiplyAdd());
    pm.addPass(createSCFToControlFlowPass());
    // Math ops with an LLVM intrinsic become it; the rest become libm calls,
    // one per element of a widened value: that split makes vector.extract
    // and vector.insert ops, so it runs before the vector ops are lowered.
    pm.addPass(createConvertMathToLLVMPass());
    pm.addPass(createConvertMathToLibmPass());
    pm.addPass(createConvertVectorToLLVMPass());
    pm.addPass(memref::createExpandStridedMetadataPass());
    pm.addPass(createFinalizeMemRefToLLVMConversionPass());
    pm.addPass(createArithToLLVMConversionPass());
    pm.addPass(createConvertIndexToLLVMPass());
    pm.addPass(createConvertFuncToLLVMPass());
    pm.addPass(createConvertControlFlowToLLVMPass());
    // The conversions above fold, and folding can make `ub.poison` (a
    // vector index that only becomes the poison index -1 there): LLVM's
    // poison, as on the GPU, rather than an op that LLVM IR has no
    // translation for.
    pm.addPass(createUBToLLVMConversionPass());
    pm.addPass(createReconcileUnrealizedCastsPass());
    if (flushSubnormals)
      pm.addPass(createSimFlushSubnormals());
  };

  // The pairs of a module and a level are independent (a copy of the
  // module, a pass manager, an LLVM context, a target machine each: passes
  // keep state while they run), so they compile side by side on threads
  // (--mlir-disable-threading: one after the other); their diagnostics come
  // in the order of the pairs. The dialects the pipelines make ops of are
  // loaded here first: loading one while another thread reads the
  // context's dialects is a race.
  size_t pairs = modules.size() * isas.size();
  SmallVector<std::unique_ptr<PassManager>> pipelines;
  DialectRegistry dependent;
  for (size_t pair = 0; pair < pairs; ++pair) {
    pipelines.push_back(std::make_unique<PassManager>(mlirContext));
    pipelineFor(*pipelines.back(), isas[pair % isas.size()]);
    pipelines.back()->getDependentDialects(dependent);
  }
  mlirContext->appendDialectRegistry(dependent);
  for (StringRef name : dependent.getDialectNames())
    mlirContext->getOrLoadDialect(name);

  SmallVector<SmallVector<std::string>> objects(
      modules.size(), SmallVector<std::string>(isas.size()));
  auto compilePair = [&](size_t pair) -> LogicalResult {
    size_t moduleIndex = pair / isas.size(), level = pair % isas.size();
    StringRef isa = isas[level];
    ModuleOp module = modules[moduleIndex];
    Location loc = module.getLoc();
    OwningOpRef<ModuleOp> copy(cast<ModuleOp>(module->clone()));
    (*copy)->removeAttr(SymbolTable::getSymbolAttrName());
    if (failed(pipelines[pair]->run(*copy)))
      return emitError(loc) << "could not lower the CPU kernels to LLVM";

    // To LLVM IR, with the entry points, and an object for the level.
    llvm::LLVMContext context;
    std::unique_ptr<llvm::Module> llvmModule =
        translateModuleToLLVMIR(*copy, context, "sim_cpu_kernels");
    if (!llvmModule)
      return emitError(loc) << "could not translate the CPU kernels to LLVM IR";
    if (failed(finish(moduleIndex, *llvmModule)))
      return failure();
    // A kernel with per-lane arrays allocates them dynamically, and LLVM
    // then keeps the caller's 16-byte stack alignment: the spill slots of
    // the SIMD levels' 32- and 64-byte registers lie across cache lines or
    // not depending on how deep the caller's stack is. A realigned frame
    // spills on whole lines (measured: gravity-like at L 8 on AVX-512).
    if (lanesFor(isa) > 1)
      for (llvm::Function &function : *llvmModule)
        if (!function.isDeclaration())
          function.addFnAttr("stackrealign");
    FailureOr<std::string> object =
        compileForIsa(*llvmModule, loc, isa, optLevel, linker);
    if (failed(object))
      return failure();
    objects[moduleIndex][level] = std::move(*object);
    return success();
  };
  if (!mlirContext->isMultithreadingEnabled() || pairs <= 1) {
    for (size_t pair = 0; pair < pairs; ++pair)
      if (failed(compilePair(pair)))
        return failure();
    return objects;
  }
  // A pool of their own: on the context's, a thread that waits for the
  // verifier's parallel work inside a pass takes the next pairs and holds
  // up the one it was compiling (measured: every pair on one thread).
  ParallelDiagnosticHandler diagnostics(mlirContext);
  std::atomic<size_t> next(0);
  std::atomic<bool> anyFailed(false);
  llvm::StdThreadPool pool(llvm::hardware_concurrency());
  size_t workers = std::min<size_t>(pairs, pool.getMaxConcurrency());
  for (size_t worker = 0; worker < workers; ++worker)
    pool.async([&] {
      while (!anyFailed) {
        size_t pair = next++;
        if (pair >= pairs)
          break;
        diagnostics.setOrderIDForThread(pair);
        if (failed(compilePair(pair)))
          anyFailed = true;
        diagnostics.eraseOrderIDForThread();
      }
    });
  pool.wait();
  if (anyFailed)
    return failure();
  return objects;
}

static FailureOr<std::string> compileForIsa(llvm::Module &module, Location loc,
                                            StringRef isa, unsigned optLevel,
                                            StringRef linkerPath) {
  // An object for the requested instruction-set level (not for this very
  // CPU, so that it runs on every machine of that level), position
  // independent.
  llvm::Triple triple(llvm::sys::getDefaultTargetTriple());
  std::string error;
  const llvm::Target *target =
      llvm::TargetRegistry::lookupTarget(triple, error);
  if (!target)
    return emitError(loc) << "no LLVM target for " << triple.str() << ": "
                          << error;
  // FP contraction stays at its default (only llvm.fmuladd may fuse, and the
  // kernels have none): at every level a multiply and an add round twice,
  // an fma once, so every level computes the same bits.
  llvm::TargetOptions targetOptions;
  std::unique_ptr<llvm::TargetMachine> machine(target->createTargetMachine(
      triple, isa, "", targetOptions, llvm::Reloc::PIC_));
  module.setDataLayout(machine->createDataLayout());
  module.setTargetTriple(triple);
  auto optimize = makeOptimizingTransformer(optLevel,
                                            /*sizeLevel=*/0, machine.get());
  if (llvm::Error failure = optimize(&module))
    return emitError(loc) << "LLVM optimisation failed: "
                          << llvm::toString(std::move(failure));

  SmallString<128> objectPath, libraryPath;
  int objectFd;
  if (llvm::sys::fs::createTemporaryFile("sim-cpu", "o", objectFd,
                                         objectPath) ||
      llvm::sys::fs::createTemporaryFile("sim-cpu", "so", libraryPath))
    return emitError(loc) << "could not create temporary files";
  llvm::FileRemover removeObject(objectPath), removeLibrary(libraryPath);
  // Also when a signal ends the tool midway (sim-run translating a .mlir
  // scene and stopped by Ctrl-C): LLVM's handler removes them, then dies.
  llvm::sys::RemoveFileOnSignal(objectPath);
  llvm::sys::RemoveFileOnSignal(libraryPath);
  auto forgetOnSignal = llvm::make_scope_exit([&] {
    llvm::sys::DontRemoveFileOnSignal(objectPath);
    llvm::sys::DontRemoveFileOnSignal(libraryPath);
  });
  {
    llvm::raw_fd_ostream object(objectFd, /*shouldClose=*/true);
    llvm::legacy::PassManager codegen;
    if (machine->addPassesToEmitFile(codegen, object, nullptr,
                                     llvm::CodeGenFileType::ObjectFile))
      return emitError(loc) << "the host target cannot emit objects";
    codegen.run(module);
  }

  // A shared object that needs libm (math bodies call it) and nothing else.
  std::string linker = linkerPath.str();
  if (linker.empty()) {
    for (StringRef candidate :
         {"/usr/lib/llvm-22/bin/ld.lld", "ld.lld-22", "ld.lld"}) {
      llvm::ErrorOr<std::string> found =
          llvm::sys::path::is_absolute(candidate)
              ? (llvm::sys::fs::can_execute(candidate)
                     ? llvm::ErrorOr<std::string>(candidate.str())
                     : std::make_error_code(
                           std::errc::no_such_file_or_directory))
              : llvm::sys::findProgramByName(candidate);
      if (found) {
        linker = *found;
        break;
      }
    }
  }
  if (linker.empty())
    return emitError(loc) << "no linker found to make the CPU kernels' "
                             "shared object (install lld-22)";
  SmallVector<StringRef> args = {linker, "-shared",   "--as-needed",
                                 "-o",   libraryPath, objectPath};
  if (llvm::sys::fs::exists("/lib/x86_64-linux-gnu/libm.so.6"))
    args.push_back("/lib/x86_64-linux-gnu/libm.so.6");
  std::string linkError;
  if (llvm::sys::ExecuteAndWait(linker, args, std::nullopt, {}, 0, 0,
                                &linkError) != 0)
    return emitError(loc) << "linking the CPU kernels failed"
                          << (linkError.empty() ? "" : ": ") << linkError;
  llvm::ErrorOr<std::unique_ptr<llvm::MemoryBuffer>> library =
      llvm::MemoryBuffer::getFile(libraryPath);
  if (!library)
    return emitError(loc) << "could not read the linked CPU kernels";
  return (*library)->getBuffer().str();
}

ArrayRef<StringRef> mlir::sim::getCPUIsaLevels() {
  // The x86-64 microarchitecture levels of the psABI; LLVM knows each as a
  // CPU name, and the runtime tests each with __builtin_cpu_supports.
  static const StringRef levels[] = {"x86-64", "x86-64-v2", "x86-64-v3",
                                     "x86-64-v4"};
  return levels;
}

std::string mlir::sim::getHostCPUIsa() {
  ArrayRef<StringRef> levels = getCPUIsaLevels();
  size_t cap = levels.size();
  if (const char *limit = std::getenv("SIM_CPU_ISA"); limit && *limit) {
    const auto *found = llvm::find(levels, StringRef(limit));
    if (found != levels.end())
      cap = size_t(found - levels.begin()) + 1;
  }
  // The check the runtime makes when it picks a bundle's level.
  for (size_t i = cap; i-- > 0;)
    if (::sim::bundle::cpuRunsLevel(levels[i].str()))
      return levels[i].str();
  return levels.front().str();
}

SmallVector<std::string, 3> mlir::sim::getDefaultCPUIsas() {
  // Generic code for any x86-64 (a fallback), AVX2 with FMA, and AVX-512,
  // where 16 lanes run at once (2.5x AVX2 on the paper scenes).
  return {"x86-64", "x86-64-v3", "x86-64-v4"};
}

FailureOr<std::string>
mlir::sim::compileCPUKernels(ModuleOp kernels,
                             const CPUKernelOptions &options) {
  FailureOr<SmallVector<std::string>> objects =
      compileCPUKernels(kernels, {options.isa}, options);
  if (failed(objects))
    return failure();
  return std::move(objects->front());
}

FailureOr<SmallVector<std::string>>
mlir::sim::compileCPUKernels(ModuleOp kernels, ArrayRef<std::string> isas,
                             const CPUKernelOptions &options) {
  FailureOr<SmallVector<SmallVector<std::string>>> objects =
      compileCPUKernels(ArrayRef<ModuleOp>(kernels), isas, options);
  if (failed(objects))
    return failure();
  return std::move(objects->front());
}

FailureOr<SmallVector<SmallVector<std::string>>>
mlir::sim::compileCPUKernels(ArrayRef<ModuleOp> modules,
                             ArrayRef<std::string> isas,
                             const CPUKernelOptions &options) {
  SmallVector<SmallVector<std::string>> names;
  for (ModuleOp kernels : modules) {
    names.emplace_back();
    for (auto func : kernels.getOps<func::FuncOp>()) {
      if (!func->hasAttr(simplan::PlanDialect::getGroupArgumentsAttrName()))
        return emitError(func.getLoc())
               << "is not a CPU kernel (run --sim-lower-to-cpu)";
      names.back().push_back(func.getSymName().str());
    }
  }
  return compileSharedObjects(
      modules, isas, options.optLevel, options.flushSubnormals,
      /*kernels=*/true, options.linker,
      [&](size_t index, llvm::Module &llvmModule) -> LogicalResult {
        for (const std::string &name : names[index]) {
          llvm::Function *kernel = llvmModule.getFunction(name);
          if (!kernel || kernel->arg_size() < 3)
            return emitError(modules[index]->getLoc())
                   << "lost CPU kernel '" << name << "' on the way to LLVM IR";
          addEntryPoint(llvmModule, *kernel);
        }
        return success();
      });
}

FailureOr<std::string>
mlir::sim::compileReferenceFunctions(ModuleOp reference,
                                     const CPUKernelOptions &options) {
  // The functions already have the C signatures of docs/Reference.md.
  FailureOr<SmallVector<SmallVector<std::string>>> objects =
      compileSharedObjects(ArrayRef<ModuleOp>(reference), {options.isa},
                           options.optLevel, options.flushSubnormals,
                           /*kernels=*/false, options.linker,
                           [](size_t, llvm::Module &) { return success(); });
  if (failed(objects))
    return failure();
  return std::move(objects->front().front());
}
