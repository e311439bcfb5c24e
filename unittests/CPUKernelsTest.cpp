//===- CPUKernelsTest.cpp - running the lowered kernels on the CPU --------===//
//
// Lowers scenes with the front end and --sim-lower-to-cpu, compiles the CPU
// kernels into a shared object, loads it and runs the plan with a minimal
// launcher written from docs/Plan.md. The kernels are the same algorithms as
// the GPU kernels (lib/Conversion/SimCommon, SimulationLowering.h), so this
// checks those algorithms without a GPU: every run ends exactly at its end,
// strategies agree with `simple` when every big step is one base step,
// sub-steps follow the group minimum, and the grid-wide rounds ping-pong and
// copy correctly.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/CPUKernels.h"
#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"
#include "sim/Pipelines/Pipelines.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Parser/Parser.h"
#include "mlir/Pass/PassManager.h"

#include "gtest/gtest.h"

#include <cmath>
#include <cstring>
#include <dlfcn.h>
#include <fstream>
#include <map>
#include <unistd.h>

using namespace mlir;
using namespace mlir::sim;

namespace {

using KernelFn = void (*)(void **, int64_t, int64_t, int64_t);

/// A plan being run on the CPU: the clock, both halves of every buffer and
/// the parameters, and the loaded kernels.
class CPURun {
public:
  CPURun(simplan::PlanOp plan, void *library, int64_t groupSize)
      : plan(plan), library(library), groupSize(groupSize),
        range(plan.getRange()) {
    clock.assign(plan.getClockSlots(), 0);
    for (auto buffer : plan.getBlock().getOps<simplan::BufferOp>()) {
      std::string name = buffer.getSymName().str();
      buffers[name].assign(2 * range * buffer.getStride(), 0);
      if (buffer.getSnapshot())
        snapshots[name].assign(range * buffer.getStride(), 0);
      strides[name] = buffer.getStride();
    }
    for (auto param : plan.getBlock().getOps<simplan::ParamOp>())
      setParam(param.getSymName(), cast<TypedAttr>(param.getValue()));
    dt = cast<FloatAttr>(plan.getDt()).getValueAsDouble();
    dtIsF32 = cast<FloatAttr>(plan.getDt()).getType().isF32();
  }

  void setParam(StringRef name, TypedAttr value) {
    uint64_t bits = 0;
    if (auto f = dyn_cast<FloatAttr>(value)) {
      if (f.getType().isF32()) {
        float v = f.getValueAsDouble();
        std::memcpy(&bits, &v, 4);
      } else {
        double v = f.getValueAsDouble();
        std::memcpy(&bits, &v, 8);
      }
    } else {
      bits = cast<IntegerAttr>(value).getValue().getSExtValue();
    }
    params[name.str()] = bits;
  }

  void phase(simplan::PhaseKind kind) {
    for (auto op : plan.getBlock().getOps<simplan::PhaseOp>())
      if (op.getKind() == kind)
        runBlock(op.getBody().front());
  }

  /// docs/Plan.md: set the end, launch big steps until the clock reaches
  /// it, then commit the last one.
  void run(int64_t steps) {
    clock[3] = clock[0] + clock[1] + steps;
    int guard = 0;
    while (clock[0] + clock[1] < clock[3] && ++guard < 100000)
      phase(simplan::PhaseKind::step);
    ASSERT_LT(guard, 100000) << "the clock never reached the end";
    phase(simplan::PhaseKind::finish);
  }

  /// Item `item`, lane `lane` of buffer `name`'s current state.
  double value(StringRef name, int64_t item, int lane = 0) {
    const std::vector<char> &data = buffers[name.str()];
    int64_t stride = strides[name.str()];
    size_t offset = (clock[2] * range + item) * stride;
    bool isF32 = scalarIsF32(name);
    if (isF32) {
      float v;
      std::memcpy(&v, &data[offset + 4 * lane], 4);
      return v;
    }
    double v;
    std::memcpy(&v, &data[offset + 8 * lane], 8);
    return v;
  }

  std::vector<int64_t> clock;

private:
  bool scalarIsF32(StringRef name) {
    for (auto buffer : plan.getBlock().getOps<simplan::BufferOp>())
      if (buffer.getSymName() == name)
        return getElementTypeOrSelf(buffer.getElementType()).isF32();
    return true;
  }

  void runBlock(Block &block) {
    for (Operation &op : block) {
      if (auto repeat = dyn_cast<simplan::RepeatOp>(op)) {
        for (uint64_t i = 0; i < repeat.getCount(); ++i)
          runBlock(repeat.getBody().front());
      } else if (auto launch = dyn_cast<simplan::LaunchOp>(op)) {
        this->launch(launch);
      }
    }
  }

  void launch(simplan::LaunchOp launch) {
    std::string symbol =
        ("sim_cpu_" + launch.getKernel().getLeafReference().getValue()).str();
    auto fn = reinterpret_cast<KernelFn>(dlsym(library, symbol.c_str()));
    ASSERT_NE(fn, nullptr) << symbol;
    // Storage for every value a pointer in `args` points to.
    std::vector<std::array<uint64_t, 5>> storage;
    storage.reserve(launch.getArgs().size());
    std::vector<void *> args;
    auto memref = [&](void *data, int64_t size) {
      storage.push_back({reinterpret_cast<uint64_t>(data),
                         reinterpret_cast<uint64_t>(data), 0,
                         static_cast<uint64_t>(size), 1});
      for (uint64_t &field : storage.back())
        args.push_back(&field);
    };
    auto scalar = [&](uint64_t bits) {
      storage.push_back({bits, 0, 0, 0, 0});
      args.push_back(&storage.back()[0]);
    };
    for (auto arg : launch.getArgs().getAsRange<simplan::ArgAttr>()) {
      std::string name =
          arg.getName() ? arg.getName().getValue().str() : std::string();
      switch (arg.getKind()) {
      case simplan::ArgKind::clock:
        memref(clock.data(), clock.size());
        break;
      case simplan::ArgKind::buffer:
        memref(buffers[name].data(), 2 * range);
        break;
      case simplan::ArgKind::snapshot:
        memref(snapshots[name].data(), range);
        break;
      case simplan::ArgKind::param:
        scalar(params[name]);
        break;
      case simplan::ArgKind::range:
        scalar(range);
        break;
      case simplan::ArgKind::dt: {
        uint64_t bits = 0;
        if (dtIsF32) {
          float v = dt;
          std::memcpy(&bits, &v, 4);
        } else {
          std::memcpy(&bits, &dt, 8);
        }
        scalar(bits);
        break;
      }
      default:
        FAIL() << "unexpected launch argument";
      }
    }
    if (launch.getShape() == simplan::LaunchShape::single)
      fn(args.data(), 0, 1, 1);
    else
      fn(args.data(), 0, (range + groupSize - 1) / groupSize, groupSize);
  }

  simplan::PlanOp plan;
  void *library;
  int64_t groupSize, range;
  double dt;
  bool dtIsF32;
  std::map<std::string, std::vector<char>> buffers, snapshots;
  std::map<std::string, int64_t> strides;
  std::map<std::string, uint64_t> params;
};

class CPUKernelsTest : public ::testing::Test {
protected:
  CPUKernelsTest() {
    registry
        .insert<SimDialect, simplan::PlanDialect, arith::ArithDialect,
                math::MathDialect, scf::SCFDialect, vector::VectorDialect,
                func::FuncDialect, memref::MemRefDialect, LLVM::LLVMDialect>();
    registerCPUKernelDialects(registry);
    context.appendDialectRegistry(registry);
    context.loadAllAvailableDialects();
  }

  ~CPUKernelsTest() override {
    for (auto &[handle, path] : libraries) {
      dlclose(handle);
      unlink(path.c_str());
    }
  }

  /// Lowers `scene` for `strategy` into its module of CPU kernels (null when
  /// that fails).
  ModuleOp lowerToKernels(StringRef scene, Strategy strategy,
                          int64_t groupSize = 4) {
    OwningOpRef<ModuleOp> &module =
        modules.emplace_back(parseSourceString<ModuleOp>(scene, &context));
    if (!module)
      return nullptr;
    PassManager pm(&context);
    FrontEndOptions options;
    options.strategy = strategy;
    buildFrontEndPipeline(pm, options);
    SimLowerToCPUOptions cpuOptions;
    cpuOptions.groupSize = groupSize;
    pm.addPass(createSimLowerToCPU(cpuOptions));
    if (failed(pm.run(*module)))
      return nullptr;
    return *module->getOps<ModuleOp>().begin();
  }

  /// Lowers `scene` for `strategy` and loads its CPU kernels.
  std::unique_ptr<CPURun> lower(StringRef scene, Strategy strategy,
                                int64_t groupSize = 4) {
    ModuleOp kernels = lowerToKernels(scene, strategy, groupSize);
    if (!kernels)
      return nullptr;
    OwningOpRef<ModuleOp> &module = modules.back();
    FailureOr<std::string> library = compileCPUKernels(kernels);
    if (failed(library))
      return nullptr;
    char path[] = "/tmp/sim-cpu-test-XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0 || write(fd, library->data(), library->size()) !=
                      static_cast<ssize_t>(library->size()))
      return nullptr;
    close(fd);
    void *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      return nullptr;
    libraries.push_back({handle, path});
    auto plan = *module->getOps<simplan::PlanOp>().begin();
    return std::make_unique<CPURun>(plan, handle, groupSize);
  }

  DialectRegistry registry;
  MLIRContext context;
  /// Every lowered scene stays alive with the runs that read its plan.
  std::vector<OwningOpRef<ModuleOp>> modules;
  std::vector<std::pair<void *, std::string>> libraries;
};

/// Two components: @Lead (x += dt * y, bounded by its num_steps @lead) and
/// @Follow (y relaxes towards x at its neighbour, sub-steps of @follow).
/// Items have different step counts when @mixed is set: item i takes
/// 1 + (i % 3) steps in @Follow.
constexpr const char *kChain = R"mlir(
sim.simulation @chain range(10) dt(1.0e-1 : f32) max_steps(4) {
  sim.param @lead = 1 : i32
  sim.param @follow = 1 : i32
  sim.param @mixed = 0 : i32
  sim.buffer @X : f32 init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.buffer @Y : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f32
    sim.yield %one : f32
  }
  sim.component @Lead writes(@X) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = sim.get_param @lead : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.read @X[%i] : f32
    %y = sim.read @Y[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %dx = arith.mulf %h, %y : f32
    %next = arith.addf %x, %dx : f32
    sim.yield %next : f32
  }
  sim.component @Follow writes(@Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %n = sim.get_param @follow : i32
    %mixed = sim.get_param @mixed : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %r = arith.remsi %i32, %c3 : i32
    %per = arith.addi %r, %c1 : i32
    %zero = arith.constant 0 : i32
    %use = arith.cmpi ne, %mixed, %zero : i32
    %s = arith.select %use, %per, %n : i32
    sim.yield %s : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %j = arith.addi %i, %c1 : index
    %x = sim.read @X[%j] : f32
    %y = sim.read @Y[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %d = arith.subf %x, %y : f32
    %dy = arith.mulf %h, %d : f32
    %next = arith.addf %y, %dy : f32
    sim.yield %next : f32
  }
  sim.schedule [@Lead]
  sim.observe [@X, @Y]
}
)mlir";

const Strategy kStrategies[] = {Strategy::simple, Strategy::traditional,
                                Strategy::hip, Strategy::hip_cache};

TEST_F(CPUKernelsTest, EveryStrategyEndsExactlyAtTheEnd) {
  for (Strategy strategy : kStrategies) {
    std::unique_ptr<CPURun> run = lower(kChain, strategy);
    ASSERT_TRUE(run) << stringifyStrategy(strategy).str();
    run->setParam("lead", IntegerAttr::get(IntegerType::get(&context, 32), 3));
    run->phase(simplan::PhaseKind::init);
    run->run(10);
    EXPECT_EQ(run->clock[0], 10) << stringifyStrategy(strategy).str();
    EXPECT_EQ(run->clock[1], 0);
    run->run(7);
    EXPECT_EQ(run->clock[0], 17) << stringifyStrategy(strategy).str();
  }
}

TEST_F(CPUKernelsTest, StrategiesEqualSimpleWhenEveryBigStepIsOneBaseStep) {
  std::unique_ptr<CPURun> simple = lower(kChain, Strategy::simple);
  ASSERT_TRUE(simple);
  simple->phase(simplan::PhaseKind::init);
  simple->run(12);
  for (Strategy strategy : kStrategies) {
    std::unique_ptr<CPURun> run = lower(kChain, strategy);
    ASSERT_TRUE(run);
    run->phase(simplan::PhaseKind::init);
    run->run(12);
    for (int64_t item = 0; item < 10; ++item) {
      EXPECT_EQ(run->value("X", item), simple->value("X", item))
          << stringifyStrategy(strategy).str() << " item " << item;
      EXPECT_EQ(run->value("Y", item), simple->value("Y", item))
          << stringifyStrategy(strategy).str() << " item " << item;
    }
  }
}

TEST_F(CPUKernelsTest, BigStepsFollowTheBoundingComponent) {
  std::unique_ptr<CPURun> run = lower(kChain, Strategy::hip);
  ASSERT_TRUE(run);
  run->setParam("lead", IntegerAttr::get(IntegerType::get(&context, 32), 3));
  run->phase(simplan::PhaseKind::init);
  run->run(10);
  // Big steps of 3, 3, 3 and the last one clamped to 1.
  EXPECT_EQ(run->clock[5], 4);
  int64_t histogram = 8 + 2; // two evaluation counters, no sub-step clock
  EXPECT_EQ(run->clock[histogram + 3], 3);
  EXPECT_EQ(run->clock[histogram + 1], 1);
  // @Lead evaluates once per big step; @Follow (num_steps 1) every base step.
  EXPECT_EQ(run->clock[8], 4 * 10);
  EXPECT_EQ(run->clock[9], 10 * 10);
}

TEST_F(CPUKernelsTest, SubStepsTakeTheGroupMinimum) {
  // Groups of 4 items; @Follow wants 1 + i % 3 steps, so every group that
  // holds an item i = 0 mod 3 takes single steps. Group 2 (items 8, 9) wants
  // 3 and 1: single steps too. With max_steps 4 and @lead 4: each big step
  // of 4 has 4 sub-steps of 1 for every group, like simple.
  std::unique_ptr<CPURun> hip = lower(kChain, Strategy::hip);
  ASSERT_TRUE(hip);
  hip->setParam("lead", IntegerAttr::get(IntegerType::get(&context, 32), 4));
  hip->setParam("mixed", IntegerAttr::get(IntegerType::get(&context, 32), 1));
  hip->phase(simplan::PhaseKind::init);
  hip->run(8);
  EXPECT_EQ(hip->clock[5], 2);
  EXPECT_EQ(hip->clock[9], 8 * 10) << "every item evaluated every base step";
  for (int64_t item = 0; item < 10; ++item)
    EXPECT_TRUE(std::isfinite(hip->value("Y", item)));
}

/// @Drive moves @U linearly in time (so linear interpolation of it is
/// exact); @Smooth integrates the mean of @U over the window i-1..i+1 (a
/// cache under hip-cache) with sub-steps of 1 inside big steps of max_steps.
constexpr const char *kSmooth = R"mlir(
sim.simulation @smooth range(10) dt(1.0e-1 : f32) max_steps(4) {
  sim.buffer @U : f32 boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %x = arith.sitofp %i32 : i32 to f32
    sim.yield %x : f32
  }
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.component @Drive writes(@U) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %u = sim.read @U[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %next = arith.addf %u, %h : f32
    sim.yield %next : f32
  }
  sim.component @Smooth writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : i32
    sim.yield %c1 : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -1 : index
    %hi = arith.constant 2 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> (f32) {
      %j = arith.addi %i, %k : index
      %u = sim.read @U[%j] : f32
      %next = arith.addf %acc, %u : f32
      scf.yield %next : f32
    }
    %third = arith.constant 0.333333343 : f32
    %mean = arith.mulf %sum, %third : f32
    %s = sim.read @S[%i] : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %ds = arith.mulf %h, %mean : f32
    %next = arith.addf %s, %ds : f32
    sim.yield %next : f32
  }
  sim.schedule [@Drive]
  sim.observe [@S]
}
)mlir";

TEST_F(CPUKernelsTest, CachingNeverChangesResults) {
  std::unique_ptr<CPURun> hip = lower(kSmooth, Strategy::hip);
  std::unique_ptr<CPURun> cached = lower(kSmooth, Strategy::hip_cache);
  ASSERT_TRUE(hip && cached);
  for (CPURun *run : {hip.get(), cached.get()}) {
    run->phase(simplan::PhaseKind::init);
    run->run(11);
  }
  EXPECT_EQ(cached->clock[0], 11);
  for (int64_t item = 0; item < 10; ++item)
    EXPECT_EQ(cached->value("S", item), hip->value("S", item)) << item;
}

TEST_F(CPUKernelsTest, HipInterpolatesWhenBigStepsAreLong) {
  // Big steps of 4: @Smooth takes 4 sub-steps in each and reads @U
  // interpolated at the end of each sub-step. @U is linear in time, so the
  // interpolation is exact and hip matches simple up to rounding; reading
  // @U at T or at T + m instead would be off by up to 3 base steps of drift.
  std::unique_ptr<CPURun> simple = lower(kSmooth, Strategy::simple);
  std::unique_ptr<CPURun> hip = lower(kSmooth, Strategy::hip);
  ASSERT_TRUE(simple && hip);
  for (CPURun *run : {simple.get(), hip.get()}) {
    run->phase(simplan::PhaseKind::init);
    run->run(12);
  }
  EXPECT_EQ(hip->clock[5], 3) << "three big steps of 4";
  EXPECT_EQ(hip->clock[9], 12 * 10) << "@Smooth still sub-steps every step";
  for (int64_t item = 0; item < 10; ++item)
    EXPECT_NEAR(hip->value("S", item), simple->value("S", item),
                1e-5 * std::abs(simple->value("S", item)))
        << item;
}

TEST_F(CPUKernelsTest, ModulesAndLevelsCompileSideBySideToTheSameBytes) {
  // Every pair of a module and a level compiles on a thread of its own; the
  // objects are those of one after the other, in the order asked for.
  SmallVector<ModuleOp> kernels = {lowerToKernels(kChain, Strategy::simple),
                                   lowerToKernels(kChain, Strategy::hip)};
  ASSERT_TRUE(kernels[0] && kernels[1]);
  SmallVector<std::string> isas = {"x86-64", "x86-64-v3"};
  FailureOr<SmallVector<SmallVector<std::string>>> together =
      compileCPUKernels(kernels, isas);
  ASSERT_TRUE(succeeded(together));
  context.disableMultithreading();
  for (auto [index, module] : llvm::enumerate(kernels)) {
    FailureOr<SmallVector<std::string>> alone = compileCPUKernels(module, isas);
    ASSERT_TRUE(succeeded(alone));
    ASSERT_EQ(alone->size(), 2u);
    for (size_t level = 0; level < 2; ++level)
      EXPECT_TRUE((*together)[index][level] == (*alone)[level])
          << "module " << index << " level " << isas[level];
  }
  context.enableMultithreading();
  EXPECT_FALSE((*together)[0][0] == (*together)[1][0]);
}

TEST_F(CPUKernelsTest, AFailedLinkOnThreadsIsAnErrorNotACrash) {
  SmallVector<ModuleOp> kernels = {lowerToKernels(kChain, Strategy::simple),
                                   lowerToKernels(kChain, Strategy::hip)};
  ASSERT_TRUE(kernels[0] && kernels[1]);
  std::vector<std::string> errors;
  ScopedDiagnosticHandler collect(&context, [&](Diagnostic &diag) {
    if (diag.getSeverity() == DiagnosticSeverity::Error)
      errors.push_back(diag.str());
    return success();
  });
  CPUKernelOptions options;
  options.linker = "/nonexistent/ld.lld";
  EXPECT_TRUE(failed(compileCPUKernels(
      kernels, {"x86-64", "x86-64-v3", "x86-64-v4"}, options)));
  ASSERT_FALSE(errors.empty());
  for (const std::string &error : errors)
    EXPECT_NE(error.find("linking the CPU kernels failed"), std::string::npos)
        << error;
}

TEST_F(CPUKernelsTest, SymbolsThatAreNotIdentifiersRunLikeOrdinaryOnes) {
  // The kernels get escaped names (`init_x__201`, exported as
  // `sim_cpu_init_x__201`); the plan and the results keep the symbols.
  std::string quoted = kChain;
  for (auto [from, to] : {std::pair<StringRef, StringRef>{"@X", "@\"x 1\""},
                          {"@Y", "@\"y.2-$\""},
                          {"@Lead", "@\"\xce\x94 lead\""},
                          {"@Follow", "@follow_"}}) {
    for (size_t at = quoted.find(from.str()); at != std::string::npos;
         at = quoted.find(from.str(), at + to.size()))
      quoted.replace(at, from.size(), to.str());
  }
  for (Strategy strategy : kStrategies) {
    std::unique_ptr<CPURun> plain = lower(kChain, strategy);
    std::unique_ptr<CPURun> run = lower(quoted, strategy);
    ASSERT_TRUE(plain && run) << stringifyStrategy(strategy).str();
    for (CPURun *each : {plain.get(), run.get()}) {
      each->setParam("lead",
                     IntegerAttr::get(IntegerType::get(&context, 32), 3));
      each->setParam("mixed",
                     IntegerAttr::get(IntegerType::get(&context, 32), 1));
      each->phase(simplan::PhaseKind::init);
      each->run(9);
    }
    EXPECT_EQ(run->clock, plain->clock) << stringifyStrategy(strategy).str();
    for (int64_t item = 0; item < 10; ++item) {
      EXPECT_EQ(run->value("x 1", item), plain->value("X", item))
          << stringifyStrategy(strategy).str() << " item " << item;
      EXPECT_EQ(run->value("y.2-$", item), plain->value("Y", item))
          << stringifyStrategy(strategy).str() << " item " << item;
    }
  }
}

} // namespace
