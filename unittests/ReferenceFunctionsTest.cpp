//===- ReferenceFunctionsTest.cpp - the reference executor's ABI ----------===//
//
// Compiles the body functions --sim-lower-to-reference makes of a scene,
// loads them and calls them through a recording context, as the runtime's
// reference executor does (docs/Reference.md): every view read and parameter
// goes through a callback with the model's indices, element lanes are packed
// (a vector<3xf32> is 12 bytes, and nothing past them is written), and
// evaluate writes its k-th value to outs[k].
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Target/CPUKernels.h"

#include "mlir/AsmParser/AsmParser.h"
#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Parser/Parser.h"
#include "mlir/Pass/PassManager.h"
#include "mlir/Support/DebugStringHelper.h"

#include "gtest/gtest.h"

#include <cstring>
#include <dlfcn.h>
#include <unistd.h>
#include <vector>

using namespace mlir;
using namespace mlir::sim;

namespace {

/// `sim_ref_context` of docs/Reference.md.
struct Context {
  void *executor;
  void (*read)(void *, int32_t, int64_t, void *);
  void (*param)(void *, int32_t, void *);
};

/// Answers reads with `100 * buffer + item + lane / 10` and records them.
struct Recorder {
  std::vector<std::pair<int32_t, int64_t>> reads;
  std::vector<int32_t> params;

  static void read(void *self, int32_t buffer, int64_t item, void *out) {
    auto *recorder = static_cast<Recorder *>(self);
    recorder->reads.push_back({buffer, item});
    float lanes[3];
    for (int lane = 0; lane < 3; ++lane)
      lanes[lane] = 100.0f * buffer + item + lane / 10.0f;
    // Buffer 0 is f32, buffer 1 vector<3xf32>.
    std::memcpy(out, lanes, buffer == 0 ? 4 : 12);
  }
  static void param(void *self, int32_t index, void *out) {
    auto *recorder = static_cast<Recorder *>(self);
    recorder->params.push_back(index);
    if (index == -1) { // range
      int64_t range = 40;
      std::memcpy(out, &range, 8);
    } else if (index == -3) { // max_steps
      int32_t maxSteps = 6;
      std::memcpy(out, &maxSteps, 4);
    } else { // @scale, f32
      float scale = 0.5f;
      std::memcpy(out, &scale, 4);
    }
  }
};

constexpr const char *kScene = R"mlir(
sim.simulation @abi range(8) dt(2.5e-1 : f32) max_steps(6) {
  sim.param @scale = 2.0 : f32
  sim.buffer @S : f32 init {
  ^bb0(%i: index):
    %one = arith.constant 1 : index
    %j = arith.addi %i, %one : index
    %v = sim.read @V[%j] : vector<3xf32>
    %x = vector.extract %v[2] : f32 from vector<3xf32>
    sim.yield %x : f32
  }
  sim.buffer @V : vector<3xf32> init {
  ^bb0(%i: index):
    %z = arith.constant dense<7.0> : vector<3xf32>
    sim.yield %z : vector<3xf32>
  }
  sim.component @Step writes(@S, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %range = sim.get_param @range : i64
    %max = sim.get_param @max_steps : i32
    %r = arith.trunci %range : i64 to i32
    %n = arith.addi %r, %max : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %s = sim.read @S[%i] : f32
    %scale = sim.get_param @scale : f32
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %hs = arith.mulf %h, %scale : f32
    %next = arith.addf %s, %hs : f32
    %v = sim.read @V[%i] : vector<3xf32>
    %tv = arith.sitofp %t : i64 to f32
    %tb = vector.broadcast %tv : f32 to vector<3xf32>
    %nv = arith.addf %v, %tb : vector<3xf32>
    sim.yield %next, %nv : f32, vector<3xf32>
  }
  sim.observe [@S]
}
)mlir";

class ReferenceFunctionsTest : public ::testing::Test {
protected:
  void SetUp() override {
    registry.insert<SimDialect, arith::ArithDialect, func::FuncDialect,
                    LLVM::LLVMDialect, math::MathDialect, scf::SCFDialect,
                    vector::VectorDialect>();
    registerCPUKernelDialects(registry);
    context.appendDialectRegistry(registry);
    context.loadAllAvailableDialects();

    OwningOpRef<ModuleOp> module =
        parseSourceString<ModuleOp>(kScene, &context);
    ASSERT_TRUE(module);
    PassManager pm(&context);
    buildReferencePipeline(pm, ReferenceOptions());
    ASSERT_TRUE(succeeded(pm.run(*module)));
    ModuleOp reference = *module->getOps<ModuleOp>().begin();
    auto model =
        reference->getAttrOfType<DictionaryAttr>(kReferenceModelAttrName);
    ASSERT_TRUE(model);
    Attribute expected = parseAttribute(
        "{params = [\"scale\"], buffers = [\"S\", \"V\"], components = "
        "[{name = \"Step\", sub_stepping = #sim<sub_stepping in_kernel>, "
        "num_steps = true, writes = array<i64: 0, 1>, reads = array<i64: 0, "
        "1>, stepping = {simple = {advance = #sim<advance whole_step>, "
        "estimates = false}, traditional = {advance = #sim<advance "
        "whole_step>, estimates = true}, hip = {advance = #sim<advance "
        "group_substeps>, estimates = false}, \"hip-cache\" = {advance = "
        "#sim<advance group_substeps>, estimates = false}, lts = {advance = "
        "#sim<advance group_substeps>, estimates = false}}}], totals = [], "
        "step_caps = {simple = 1, traditional = 6, hip = 6, \"hip-cache\" = "
        "6, lts = 6}}",
        &context);
    ASSERT_TRUE(expected);
    EXPECT_EQ(model, expected) << "the model is " << debugString(model);
    FailureOr<std::string> library = compileReferenceFunctions(reference);
    ASSERT_TRUE(succeeded(library));
    char path[] = "/tmp/sim-reference-test-XXXXXX";
    int fd = mkstemp(path);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(write(fd, library->data(), library->size()),
              static_cast<ssize_t>(library->size()));
    close(fd);
    handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    unlink(path);
    ASSERT_TRUE(handle) << dlerror();
  }
  void TearDown() override {
    if (handle)
      dlclose(handle);
  }

  template <typename Fn> Fn lookup(const char *name) {
    void *symbol = dlsym(handle, name);
    EXPECT_TRUE(symbol) << name;
    return reinterpret_cast<Fn>(symbol);
  }

  DialectRegistry registry;
  MLIRContext context;
  void *handle = nullptr;
  Recorder recorder;
  Context ctx{&recorder, &Recorder::read, &Recorder::param};
};

TEST_F(ReferenceFunctionsTest, InitReadsThroughTheCallback) {
  auto init =
      lookup<void (*)(const Context *, int64_t, void *)>("sim_ref_init_0");
  ASSERT_TRUE(init);
  float out = 0;
  init(&ctx, 3, &out);
  // S[3] = lane 2 of V[4].
  ASSERT_EQ(recorder.reads.size(), 1u);
  EXPECT_EQ(recorder.reads[0], std::make_pair(int32_t(1), int64_t(4)));
  EXPECT_FLOAT_EQ(out, 104.2f);
}

TEST_F(ReferenceFunctionsTest, VectorElementsArePacked) {
  auto init =
      lookup<void (*)(const Context *, int64_t, void *)>("sim_ref_init_1");
  ASSERT_TRUE(init);
  float out[4] = {0, 0, 0, -1.0f};
  init(&ctx, 0, out);
  EXPECT_EQ(out[0], 7.0f);
  EXPECT_EQ(out[2], 7.0f);
  EXPECT_EQ(out[3], -1.0f) << "wrote past the 12 bytes of a vector<3xf32>";
}

TEST_F(ReferenceFunctionsTest, NumStepsReadsBuiltinParameters) {
  auto numSteps = lookup<int32_t (*)(const Context *, int64_t, int64_t)>(
      "sim_ref_num_steps_0");
  ASSERT_TRUE(numSteps);
  EXPECT_EQ(numSteps(&ctx, 5, 9), 46); // range 40 + max_steps 6
  EXPECT_EQ(recorder.params, (std::vector<int32_t>{-1, -3}));
  EXPECT_TRUE(recorder.reads.empty());
}

TEST_F(ReferenceFunctionsTest, EvaluateWritesEveryOutput) {
  auto evaluate = lookup<void (*)(const Context *, int64_t, int64_t, int32_t,
                                  double, void *const *)>("sim_ref_evaluate_0");
  ASSERT_TRUE(evaluate);
  float s = 0;
  float v[4] = {0, 0, 0, -1.0f};
  void *outs[] = {&s, v};
  evaluate(&ctx, 2, 10, 3, 0.25, outs);
  // S[2] + 3 * 0.25 * 0.5, and V[2] + t per lane.
  EXPECT_FLOAT_EQ(s, 2.0f + 0.375f);
  EXPECT_FLOAT_EQ(v[0], 112.0f);
  EXPECT_FLOAT_EQ(v[1], 112.1f);
  EXPECT_FLOAT_EQ(v[2], 112.2f);
  EXPECT_EQ(v[3], -1.0f);
  ASSERT_EQ(recorder.reads.size(), 2u);
  EXPECT_EQ(recorder.reads[0], std::make_pair(int32_t(0), int64_t(2)));
  EXPECT_EQ(recorder.reads[1], std::make_pair(int32_t(1), int64_t(2)));
  EXPECT_EQ(recorder.params, (std::vector<int32_t>{0}));
}

} // namespace
