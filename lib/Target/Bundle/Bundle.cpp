//===- Bundle.cpp - scenes to .simb bundles -------------------------------===//
//
// The bundle writer (docs/Bundle.md). Per strategy it clones the scene, runs
// the front end, and from that one result makes both kernel sets:
//
//   front end ─┬─ --sim-lower-to-gpu ── plan text
//              │                    └─ buildSimGPUToPTXPipeline ── PTX
//              └─ --sim-lower-to-cpu ── compileCPUKernels ── shared object
//
// The two lowerings make the same simplan.plan; the writer checks that they
// do, since the runtime runs the one plan with either kernel set. The scene
// section comes from the simulation as written (before pruning), so it lists
// every parameter and buffer a user can name.
//
// The text sections are written from the IR op by op; they are the contract
// with the runtime (runtime/src/TextFormat.cpp), which holds no MLIR.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/Bundle.h"
#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Target/CPUKernels.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/Pass/PassManager.h"
#include "llvm/ADT/SetVector.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/ADT/StringSet.h"
#include "llvm/Support/EndianStream.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Format.h"
#include "llvm/Support/MathExtras.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

//===----------------------------------------------------------------------===//
// The container
//===----------------------------------------------------------------------===//

/// Section kinds and the scene's strategy field (docs/Bundle.md, "Layout").
enum class SectionKind : uint32_t {
  scene = 1,
  plan = 2,
  ptx = 3,
  cpu = 4,
  referenceModel = 5,
  referenceLibrary = 6,
};
constexpr uint32_t kNoStrategy = 0xffffffffu;
constexpr uint32_t kVersion = 1;
constexpr uint64_t kHeaderSize = 24;
constexpr uint64_t kEntrySize = 32;

/// The strategy field of a section: the order of docs/Bundle.md, which is
/// also the order of the Strategy enum.
uint32_t getStrategyNumber(Strategy strategy) {
  switch (strategy) {
  case Strategy::simple:
    return 0;
  case Strategy::traditional:
    return 1;
  case Strategy::hip:
    return 2;
  case Strategy::hip_cache:
    return 3;
  }
  llvm_unreachable("unknown strategy");
}

struct Section {
  SectionKind kind;
  uint32_t strategy;
  std::string contents;
};

/// Writes the header, the section table and the contents, each starting at
/// a multiple of 8 (zero padding between them).
void writeContainer(ArrayRef<Section> sections, raw_ostream &os) {
  using llvm::support::endian::write;
  constexpr auto little = llvm::endianness::little;
  SmallVector<uint64_t> offsets;
  uint64_t end = kHeaderSize + kEntrySize * sections.size();
  for (const Section &section : sections) {
    uint64_t offset = llvm::alignTo(end, 8);
    offsets.push_back(offset);
    end = offset + section.contents.size();
  }

  os << StringRef("SIMBNDL\0", 8);
  write<uint32_t>(os, kVersion, little);
  write<uint32_t>(os, sections.size(), little);
  write<uint64_t>(os, end, little);
  for (auto [section, offset] : llvm::zip_equal(sections, offsets)) {
    write<uint32_t>(os, static_cast<uint32_t>(section.kind), little);
    write<uint32_t>(os, section.strategy, little);
    write<uint64_t>(os, offset, little);
    write<uint64_t>(os, section.contents.size(), little);
    write<uint64_t>(os, 0, little);
  }
  uint64_t position = kHeaderSize + kEntrySize * sections.size();
  for (auto [section, offset] : llvm::zip_equal(sections, offsets)) {
    os.write_zeros(offset - position);
    os << section.contents;
    position = offset + section.contents.size();
  }
}

//===----------------------------------------------------------------------===//
// Values and names
//===----------------------------------------------------------------------===//

/// A float that reads back exactly (as f64, or as f32 with strtof: the
/// decimal is within a double's rounding of the float).
void writeFloat(raw_ostream &os, double value) {
  os << llvm::format("%.17g", value);
}

/// `f32`, `f64`, `vector<4xf32>`: as MLIR prints them, which is the format's
/// spelling.
std::string getTypeText(Type type) {
  std::string text;
  llvm::raw_string_ostream os(text);
  type.print(os);
  return text;
}

/// The format's name of an interpolation, or failure for one it has none
/// for.
FailureOr<std::string> getInterpolationText(InterpolationAttrInterface interp) {
  if (isa<LinearInterpAttr>(interp))
    return std::string("linear");
  if (isa<CubicInterpAttr>(interp))
    return std::string("cubic");
  if (isa<NoneInterpAttr>(interp))
    return std::string("none");
  if (auto hermite = dyn_cast<HermiteInterpAttr>(interp))
    return ("hermite:" + hermite.getDerivative().getValue()).str();
  return failure();
}

} // namespace

//===----------------------------------------------------------------------===//
// The scene section
//===----------------------------------------------------------------------===//

LogicalResult mlir::sim::writeSceneText(SimulationOp simulation,
                                        ArrayRef<Strategy> strategies,
                                        raw_ostream &os) {
  os << "scene " << simulation.getSymName() << " range "
     << simulation.getRange() << " dt "
     << getTypeText(simulation.getTimeStepType()) << " ";
  writeFloat(os, simulation.getTimeStep());
  os << " max_steps " << simulation.getMaxSteps() << "\n";

  for (ParamOp param : simulation.getParams()) {
    auto value = cast<TypedAttr>(param.getValue());
    Type type = value.getType();
    if (!type.isInteger(32) && !type.isInteger(64) && !type.isIndex() &&
        !type.isF32() && !type.isF64())
      return param.emitOpError()
             << "has type " << type
             << ", which a bundle cannot hold (parameters are i32, i64, "
                "index, f32 or f64)";
    os << "param " << param.getSymName() << " " << getTypeText(type) << " ";
    if (auto integer = dyn_cast<IntegerAttr>(value))
      os << integer.getValue().getSExtValue();
    else
      writeFloat(os, cast<FloatAttr>(value).getValueAsDouble());
    os << "\n";
  }

  llvm::SmallDenseSet<StringRef> observed;
  if (ObserveOp observe = simulation.getObserveOp())
    for (auto name : observe.getBuffers().getAsRange<FlatSymbolRefAttr>())
      observed.insert(name.getValue());
  for (BufferOp buffer : simulation.getBuffers()) {
    FailureOr<std::string> interp =
        getInterpolationText(buffer.getInterpolation());
    if (failed(interp))
      return buffer.emitOpError()
             << "interpolates with " << buffer.getInterpolation()
             << ", which the bundle format has no name for (linear, cubic, "
                "hermite or none)";
    os << "buffer " << buffer.getSymName() << " "
       << getTypeText(buffer.getElementType()) << " interp " << *interp
       << " boundary " << stringifyBoundary(buffer.getBoundary());
    if (observed.contains(buffer.getSymName()))
      os << " observed";
    if (!buffer.getExact().empty())
      os << " exact";
    os << "\n";
  }

  os << "strategies";
  for (Strategy strategy : strategies)
    os << " " << stringifyStrategy(strategy);
  os << "\n";
  return success();
}

//===----------------------------------------------------------------------===//
// The plan section
//===----------------------------------------------------------------------===//

namespace {

/// One `#simplan.arg` as the format spells it.
LogicalResult writeArg(simplan::LaunchOp launch, simplan::ArgAttr arg,
                       raw_ostream &os) {
  switch (arg.getKind()) {
  case simplan::ArgKind::clock:
  case simplan::ArgKind::range:
  case simplan::ArgKind::dt:
  case simplan::ArgKind::time:
    os << simplan::stringifyArgKind(arg.getKind());
    return success();
  case simplan::ArgKind::buffer:
  case simplan::ArgKind::snapshot:
  case simplan::ArgKind::exact:
  case simplan::ArgKind::param:
  case simplan::ArgKind::total:
    if (!arg.getName())
      return launch.emitOpError() << "passes " << arg << " without a name";
    os << simplan::stringifyArgKind(arg.getKind()) << ":"
       << arg.getName().getValue();
    return success();
  }
  llvm_unreachable("unknown launch argument kind");
}

/// The launches, repeats and ends of a phase or repeat body.
LogicalResult writeLaunches(Block &block, raw_ostream &os) {
  for (Operation &op : block) {
    if (auto repeat = dyn_cast<simplan::RepeatOp>(op)) {
      os << "repeat " << repeat.getCount() << "\n";
      if (failed(writeLaunches(repeat.getBody().front(), os)))
        return failure();
      os << "end\n";
      continue;
    }
    auto launch = dyn_cast<simplan::LaunchOp>(op);
    if (!launch)
      return op.emitOpError("cannot be written to a bundle's plan");
    os << "launch " << launch.getKernel().getLeafReference().getValue() << " "
       << simplan::stringifyLaunchShape(launch.getShape()) << " for "
       << launch.getComponent().value_or("-") << " shared "
       << launch.getSharedPerThread() << " " << launch.getSharedFixed()
       << " args";
    for (auto arg : launch.getArgs().getAsRange<simplan::ArgAttr>()) {
      os << " ";
      if (failed(writeArg(launch, arg, os)))
        return failure();
    }
    os << "\n";
  }
  return success();
}

} // namespace

LogicalResult mlir::sim::writePlanText(simplan::PlanOp plan, raw_ostream &os) {
  os << "plan " << plan.getStrategy() << " group_size " << plan.getGroupSize()
     << " clock_slots " << plan.getClockSlots() << " histogram "
     << plan.getHistogramSlot() << "\n";
  for (Operation &op : plan.getBlock()) {
    if (isa<simplan::ParamOp>(op))
      continue; // The scene section lists every parameter with its type.
    if (auto buffer = dyn_cast<simplan::BufferOp>(op)) {
      os << "buffer " << buffer.getSymName() << " "
         << getTypeText(buffer.getElementType()) << " stride "
         << buffer.getStride();
      if (buffer.getSnapshot())
        os << " snapshot";
      if (buffer.getObserved())
        os << " observed";
      if (buffer.getExact())
        os << " exact";
      os << "\n";
    } else if (auto component = dyn_cast<simplan::ComponentOp>(op)) {
      os << "component " << component.getSymName() << " evaluations "
         << component.getEvaluations() << " writes";
      for (auto name : component.getWrites().getAsRange<FlatSymbolRefAttr>())
        os << " " << name.getValue();
      os << "\n";
    } else if (auto total = dyn_cast<simplan::TotalOp>(op)) {
      os << "total " << total.getSymName() << " "
         << getTypeText(total.getType()) << "\n";
    } else if (auto phase = dyn_cast<simplan::PhaseOp>(op)) {
      os << "phase " << simplan::stringifyPhaseKind(phase.getKind()) << "\n";
      if (failed(writeLaunches(phase.getBody().front(), os)))
        return failure();
      os << "end\n";
    } else {
      return op.emitOpError("cannot be written to a bundle's plan");
    }
  }
  return success();
}

//===----------------------------------------------------------------------===//
// Compiling one strategy
//===----------------------------------------------------------------------===//

namespace {

/// What the check of the GPU back end says when a kernel calls a libdevice
/// function and there is no libdevice (lib/Target/PTX/Transforms/
/// CheckTarget.cpp).
constexpr StringLiteral kNeedsLibdevice =
    "this operation needs the libdevice function '";

/// The sections of one strategy, and why it has no PTX when it has none.
struct StrategyCode {
  std::string plan, ptx, cpu;
  /// The libdevice functions the kernels call when the PTX could not be
  /// made for want of libdevice, and where the first one is called.
  SmallVector<std::string> missingLibdevice;
  std::optional<Location> firstLibdeviceCall;
};

class BundleWriter {
public:
  BundleWriter(ModuleOp module, SimulationOp simulation,
               const BundleOptions &options)
      : module(module), simulation(simulation), options(options),
        context(module.getContext()) {}

  /// Compiles `strategy` into `code`; any error carries a note that names
  /// the strategy.
  LogicalResult compile(Strategy strategy, StrategyCode &code) {
    ScopedDiagnosticHandler note(context, [&](Diagnostic &diag) {
      if (diag.getSeverity() == DiagnosticSeverity::Error)
        diag.attachNote(simulation.getLoc())
            << "while compiling the bundle's strategy '"
            << stringifyStrategy(strategy)
            << "' (--sim-strategies chooses the strategies)";
      return failure(); // Not handled: the next handler reports it.
    });

    OwningOpRef<ModuleOp> frontEnd(module.clone());
    {
      PassManager pm(context, ModuleOp::getOperationName());
      FrontEndOptions frontEndOptions;
      frontEndOptions.strategy = strategy;
      frontEndOptions.groupSize = options.groupSize;
      buildFrontEndPipeline(pm, frontEndOptions);
      if (failed(runPipeline(pm, *frontEnd)))
        return failure();
    }

    // GPU kernels and the plan, then the PTX.
    OwningOpRef<ModuleOp> gpu(frontEnd->clone());
    simplan::PlanOp plan;
    {
      PassManager pm(context, ModuleOp::getOperationName());
      SimLowerToGPUOptions lowering;
      lowering.groupSize = options.groupSize;
      pm.addPass(createSimLowerToGPU(lowering));
      if (failed(runPipeline(pm, *gpu)))
        return failure();
      FailureOr<simplan::PlanOp> found = getPlan(*gpu);
      if (failed(found))
        return failure();
      plan = *found;
      llvm::raw_string_ostream os(code.plan);
      if (failed(writePlanText(plan, os)))
        return failure();
    }
    if (failed(compilePTX(*gpu, plan, code)))
      return failure();

    // CPU kernels: the same plan, and a shared object.
    OwningOpRef<ModuleOp> cpu(frontEnd->clone());
    frontEnd = nullptr;
    {
      PassManager pm(context, ModuleOp::getOperationName());
      SimLowerToCPUOptions lowering;
      lowering.groupSize = options.groupSize;
      pm.addPass(createSimLowerToCPU(lowering));
      if (failed(runPipeline(pm, *cpu)))
        return failure();
    }
    FailureOr<simplan::PlanOp> cpuPlan = getPlan(*cpu);
    if (failed(cpuPlan))
      return failure();
    std::string cpuPlanText;
    llvm::raw_string_ostream cpuPlanOS(cpuPlanText);
    if (failed(writePlanText(*cpuPlan, cpuPlanOS)))
      return failure();
    if (cpuPlanText != code.plan)
      return emitError(simulation.getLoc())
             << "the GPU and the CPU lowerings made different plans; the "
                "bundle needs one plan for both kernel sets";
    auto kernels = dyn_cast_or_null<ModuleOp>(
        SymbolTable::lookupSymbolIn(*cpu, cpuPlan->getKernelsAttr()));
    if (!kernels)
      return cpuPlan->emitOpError()
             << "names the kernels " << cpuPlan->getKernelsAttr()
             << ", which are not a module of CPU kernels";
    CPUKernelOptions cpuOptions;
    cpuOptions.optLevel = options.target.optLevel;
    FailureOr<std::string> library = compileCPUKernels(kernels, cpuOptions);
    if (failed(library))
      return failure();
    code.cpu = std::move(*library);
    return success();
  }

  /// Compiles the reference executor's part (docs/Reference.md): the model
  /// text and the shared object of the body functions, from the scheduled
  /// IR. It shares no lowering with the strategies' kernels.
  LogicalResult compileReference(std::string &model, std::string &library) {
    ScopedDiagnosticHandler note(context, [&](Diagnostic &diag) {
      if (diag.getSeverity() == DiagnosticSeverity::Error)
        diag.attachNote(simulation.getLoc())
            << "while compiling the bundle's reference functions";
      return failure();
    });
    OwningOpRef<ModuleOp> scheduled(module.clone());
    PassManager pm(context, ModuleOp::getOperationName());
    buildReferencePipeline(pm, ReferenceOptions());
    if (failed(runPipeline(pm, *scheduled)))
      return failure();
    auto modules = scheduled->getOps<ModuleOp>();
    if (modules.empty() || std::next(modules.begin()) != modules.end())
      return emitError(simulation.getLoc())
             << "the reference lowering made no single module of functions";
    ModuleOp reference = *modules.begin();
    auto text = reference->getAttrOfType<StringAttr>(kReferenceModelAttrName);
    if (!text)
      return reference.emitError() << "has no reference model text";
    model = text.getValue().str();
    CPUKernelOptions cpuOptions;
    cpuOptions.optLevel = options.target.optLevel;
    FailureOr<std::string> compiled =
        compileReferenceFunctions(reference, cpuOptions);
    if (failed(compiled))
      return failure();
    library = std::move(*compiled);
    return success();
  }

private:
  /// Runs `pm` on `op`. Some upstream passes report an error and still
  /// succeed (gpu-module-to-binary without a toolkit), so any error fails.
  LogicalResult runPipeline(PassManager &pm, ModuleOp op) {
    bool reportedError = false;
    ScopedDiagnosticHandler errors(context, [&](Diagnostic &diag) {
      reportedError |= diag.getSeverity() == DiagnosticSeverity::Error;
      return failure();
    });
    if (failed(applyPassManagerCLOptions(pm)))
      return failure();
    return failure(failed(pm.run(op)) || reportedError);
  }

  /// The one plan a lowering made of the one simulation.
  FailureOr<simplan::PlanOp> getPlan(ModuleOp lowered) {
    auto plans = lowered.getOps<simplan::PlanOp>();
    if (plans.empty() || std::next(plans.begin()) != plans.end())
      return emitError(simulation.getLoc())
             << "the lowering made no single simplan.plan of the simulation";
    return *plans.begin();
  }

  /// Runs the GPU back end on the lowered module `gpu` and takes the PTX of
  /// the plan's kernels. Without libdevice, kernels that call math functions
  /// cannot be made: that leaves the strategy without PTX (the caller
  /// warns), any other error fails.
  LogicalResult compilePTX(ModuleOp gpu, simplan::PlanOp plan,
                           StrategyCode &code) {
    PassManager pm(context, ModuleOp::getOperationName());
    buildSimGPUToPTXPipeline(pm, options.target);

    // Held back until it is known whether they are only libdevice's.
    SmallVector<Diagnostic> held;
    LogicalResult result = success();
    {
      ScopedDiagnosticHandler hold(context, [&](Diagnostic &diag) {
        held.push_back(std::move(diag));
        return success();
      });
      result = runPipeline(pm, gpu);
    }
    bool onlyLibdevice = failed(result) && !held.empty();
    for (Diagnostic &diag : held)
      if (diag.getSeverity() == DiagnosticSeverity::Error &&
          !StringRef(diag.str()).starts_with(kNeedsLibdevice))
        onlyLibdevice = false;
    if (onlyLibdevice) {
      for (Diagnostic &diag : held) {
        StringRef function =
            StringRef(diag.str()).drop_front(kNeedsLibdevice.size());
        code.missingLibdevice.push_back(
            function.take_until([](char c) { return c == '\''; }).str());
        if (!code.firstLibdeviceCall)
          code.firstLibdeviceCall = diag.getLocation();
      }
      return success();
    }
    for (Diagnostic &diag : held)
      context->getDiagEngine().emit(std::move(diag));
    if (failed(result))
      return failure();

    auto binary = dyn_cast_or_null<gpu::BinaryOp>(
        SymbolTable::lookupSymbolIn(gpu, plan.getKernelsAttr()));
    if (!binary || binary.getObjectsAttr().size() != 1)
      return plan.emitOpError()
             << "names the kernels " << plan.getKernelsAttr()
             << ", which the GPU back end did not compile to one gpu.binary";
    auto object = dyn_cast<gpu::ObjectAttr>(binary.getObjectsAttr()[0]);
    if (!object || object.getFormat() != gpu::CompilationTarget::Assembly)
      return binary.emitError()
             << "expected PTX (an object in assembly format), got "
             << binary.getObjectsAttr()[0];
    code.ptx = object.getObject().getValue().str();
    // docs/Bundle.md: the PTX is NUL-terminated.
    code.ptx.push_back('\0');
    return success();
  }

  ModuleOp module;
  SimulationOp simulation;
  const BundleOptions &options;
  MLIRContext *context;
};

} // namespace

//===----------------------------------------------------------------------===//
// The bundle
//===----------------------------------------------------------------------===//

void mlir::sim::registerBundleDependencies(DialectRegistry &registry) {
  registry.insert<SimDialect, simplan::PlanDialect, arith::ArithDialect,
                  math::MathDialect, scf::SCFDialect, vector::VectorDialect>();
  registerGPUToPTXDependencies(registry);
  registerCPUKernelDialects(registry);
}

LogicalResult mlir::sim::writeBundle(ModuleOp module,
                                     const BundleOptions &options,
                                     raw_ostream &os) {
  DialectRegistry registry;
  registerBundleDependencies(registry);
  module.getContext()->appendDialectRegistry(registry);

  auto simulations = module.getOps<SimulationOp>();
  if (simulations.empty())
    return module.emitError()
           << "there is no sim.simulation to write to a bundle";
  if (std::next(simulations.begin()) != simulations.end()) {
    InFlightDiagnostic diag =
        (*std::next(simulations.begin())).emitError()
        << "a bundle holds one scene; this is a second sim.simulation";
    diag.attachNote((*simulations.begin()).getLoc()) << "the first one";
    return diag;
  }
  SimulationOp simulation = *simulations.begin();

  if (options.strategies.empty())
    return emitError(simulation.getLoc())
           << "a bundle needs at least one strategy";
  for (auto [index, strategy] : llvm::enumerate(options.strategies))
    if (llvm::is_contained(ArrayRef(options.strategies).take_front(index),
                           strategy))
      return emitError(simulation.getLoc())
             << "strategy '" << stringifyStrategy(strategy)
             << "' is asked for twice";
  if (options.groupSize <= 0)
    return emitError(simulation.getLoc())
           << "the group size must be positive, not " << options.groupSize;

  SmallVector<Section> sections;
  {
    std::string scene;
    llvm::raw_string_ostream sceneOS(scene);
    if (failed(writeSceneText(simulation, options.strategies, sceneOS)))
      return failure();
    sections.push_back({SectionKind::scene, kNoStrategy, std::move(scene)});
  }

  // Every strategy runs the front end, and both lowerings run after it: a
  // remark or warning about the scene would come up to eight times. Each is
  // reported once.
  llvm::StringSet<> reported;
  ScopedDiagnosticHandler once(module.getContext(), [&](Diagnostic &diag) {
    if (diag.getSeverity() == DiagnosticSeverity::Error)
      return failure();
    std::string key;
    llvm::raw_string_ostream os(key);
    os << diag.getLocation() << ": " << diag;
    for (const Diagnostic &note : diag.getNotes())
      os << "\n" << note.getLocation() << ": " << note;
    // Handled (dropped) when it was reported before.
    return success(!reported.insert(key).second);
  });

  BundleWriter writer(module, simulation, options);
  SmallVector<Strategy> withoutPTX;
  llvm::SetVector<StringRef> missingLibdevice;
  std::optional<Location> firstLibdeviceCall;
  SmallVector<StrategyCode> codes(options.strategies.size());
  for (auto [strategy, code] : llvm::zip_equal(options.strategies, codes)) {
    if (failed(writer.compile(strategy, code)))
      return failure();
    uint32_t number = getStrategyNumber(strategy);
    sections.push_back({SectionKind::plan, number, std::move(code.plan)});
    if (code.ptx.empty()) {
      withoutPTX.push_back(strategy);
      missingLibdevice.insert(code.missingLibdevice.begin(),
                              code.missingLibdevice.end());
      if (!firstLibdeviceCall)
        firstLibdeviceCall = code.firstLibdeviceCall;
    } else {
      sections.push_back({SectionKind::ptx, number, std::move(code.ptx)});
    }
    sections.push_back({SectionKind::cpu, number, std::move(code.cpu)});
  }

  std::string model, library;
  if (failed(writer.compileReference(model, library)))
    return failure();
  sections.push_back(
      {SectionKind::referenceModel, kNoStrategy, std::move(model)});
  sections.push_back(
      {SectionKind::referenceLibrary, kNoStrategy, std::move(library)});

  if (!withoutPTX.empty()) {
    InFlightDiagnostic warning =
        emitWarning(firstLibdeviceCall.value_or(simulation.getLoc()))
        << "the bundle has no PTX for strateg"
        << (withoutPTX.size() == 1 ? "y " : "ies ");
    llvm::interleaveComma(withoutPTX, warning, [&](Strategy strategy) {
      warning << "'" << stringifyStrategy(strategy) << "'";
    });
    warning << ": the kernels call the libdevice function"
            << (missingLibdevice.size() == 1 ? " " : "s ");
    llvm::interleaveComma(missingLibdevice, warning);
    warning << ", but there is no libdevice at '"
            << getLibdevicePath(options.target.cudaPath)
            << "'; they run on the CPU only (give the CUDA toolkit's root "
               "with --sim-cuda-path or $CUDA_HOME)";
  }

  writeContainer(sections, os);
  return success();
}
