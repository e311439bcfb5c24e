//===- DependencyAnalysisTest.cpp - the analysis API ----------------------===//
//
// Parses small scenes and checks what DependencyAnalysis and computeSchedule
// report through their C++ API: access patterns, writers, producers, the
// sub-step hazard, schedules, roles and step bounds.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/Parser/Parser.h"

#include "gtest/gtest.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

/// A scene with every access pattern: own items, a constant offset, a loop
/// window, a window through an i32 index computation, and a gather.
constexpr const char *kScene = R"mlir(
sim.simulation @scene range(64) dt(1.0e-2 : f32) max_steps(3) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.buffer @B : f32 init {
  ^bb0(%i: index):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.buffer @C : f32 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f32
    sim.yield %c : f32
  }
  sim.component @First writes(@A) num_steps {
  ^bb0(%i: index, %t: i64):
    %c1 = arith.constant 1 : index
    %j = arith.subi %i, %c1 : index
    %c = sim.read @C[%j] : f32
    %n = arith.fptosi %c : f32 to i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %a = sim.read @A[%i] : f32
    sim.yield %a : f32
  }
  sim.component @Second writes(@B) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %lo = arith.constant -3 : index
    %hi = arith.constant 2 : index
    %one = arith.constant 1 : index
    %zero = arith.constant 0.0 : f32
    %sum = scf.for %k = %lo to %hi step %one iter_args(%acc = %zero) -> f32 {
      %j = arith.addi %k, %i : index
      %a = sim.read @A[%j] : f32
      %s = arith.addf %acc, %a : f32
      scf.yield %s : f32
    }
    %i32 = arith.index_cast %i : index to i32
    %c5 = arith.constant 5 : i32
    %j32 = arith.addi %i32, %c5 : i32
    %j = arith.index_cast %j32 : i32 to index
    %b = sim.read @B[%j] : f32
    %r = arith.addf %sum, %b : f32
    sim.yield %r : f32
  }
  sim.component @Third writes(@C) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c2 = arith.constant 2 : index
    %j = arith.muli %i, %c2 : index
    %b = sim.read @B[%j] : f32
    sim.yield %b : f32
  }
  sim.schedule [@First]
  sim.observe [@C]
}
)mlir";

class DependencyAnalysisTest : public ::testing::Test {
protected:
  DependencyAnalysisTest() {
    context.loadDialect<SimDialect, arith::ArithDialect, scf::SCFDialect>();
  }

  SimulationOp parse(const char *source) {
    module = parseSourceString<ModuleOp>(source, &context);
    EXPECT_TRUE(module) << "the test scene does not parse";
    return *module->getOps<SimulationOp>().begin();
  }

  ComponentOp component(SimulationOp simulation, StringRef name) {
    return simulation.lookupComponent(FlatSymbolRefAttr::get(&context, name));
  }
  BufferOp buffer(SimulationOp simulation, StringRef name) {
    return simulation.lookupBuffer(FlatSymbolRefAttr::get(&context, name));
  }

  MLIRContext context;
  OwningOpRef<ModuleOp> module;
};

TEST_F(DependencyAnalysisTest, AccessPatternJoinAndPrint) {
  EXPECT_EQ(AccessPattern::own().str(), "i");
  EXPECT_EQ(AccessPattern::window(-4, 4).str(), "i-4..i+4");
  EXPECT_EQ(AccessPattern::window(2, 2).str(), "i+2");
  EXPECT_EQ(AccessPattern::gather().str(), "gather");
  EXPECT_TRUE(AccessPattern::window(0, 0).isOwn());
  EXPECT_EQ(AccessPattern::own().join(AccessPattern::window(2, 3)),
            AccessPattern::window(0, 3));
  EXPECT_EQ(AccessPattern::window(-1, 1).join(AccessPattern::window(2, 5)),
            AccessPattern::window(-1, 5));
  EXPECT_TRUE(AccessPattern::own().join(AccessPattern::gather()).isGather());
}

TEST_F(DependencyAnalysisTest, ClassifiesReads) {
  SimulationOp simulation = parse(kScene);
  DependencyAnalysis analysis(simulation);
  ComponentOp first = component(simulation, "First");
  ComponentOp second = component(simulation, "Second");
  ComponentOp third = component(simulation, "Third");
  BufferOp a = buffer(simulation, "A");
  BufferOp b = buffer(simulation, "B");
  BufferOp c = buffer(simulation, "C");

  EXPECT_EQ(analysis.getWriter(a), first);
  EXPECT_EQ(analysis.getWriter(c), third);
  ASSERT_EQ(analysis.getReads().size(), 6u);

  EXPECT_EQ(*analysis.getReadPattern(first, c), AccessPattern::window(-1, -1));
  EXPECT_EQ(*analysis.getReadPattern(first, a), AccessPattern::own());
  // The loop window, with the induction variable on the left of the add.
  EXPECT_EQ(*analysis.getReadPattern(second, a), AccessPattern::window(-3, 1));
  // Through an i32 computation and index casts: a gather, since the narrow
  // sum may wrap where the range passes 2^31 (docs/Model.md).
  EXPECT_TRUE(analysis.getReadPattern(second, b)->isGather());
  EXPECT_TRUE(analysis.getReadPattern(third, b)->isGather());
  EXPECT_FALSE(analysis.getReadPattern(third, a).has_value());

  // Bodies are kept apart: First reads C only in num_steps.
  ArrayRef<BufferAccess> accesses = analysis.getAccesses(first);
  ASSERT_EQ(accesses.size(), 2u);
  EXPECT_EQ(accesses[0].body, BodyKind::NumSteps);
  EXPECT_EQ(accesses[0].buffer, c);
  EXPECT_EQ(accesses[1].body, BodyKind::Evaluate);

  // Init bodies are analysed too.
  ArrayRef<BufferAccess> initAccesses = analysis.getAccesses(b);
  ASSERT_EQ(initAccesses.size(), 1u);
  EXPECT_EQ(initAccesses[0].body, BodyKind::Init);
  EXPECT_EQ(initAccesses[0].buffer, a);
  EXPECT_TRUE(initAccesses[0].pattern.isOwn());
}

TEST_F(DependencyAnalysisTest, ProducersAndHazards) {
  SimulationOp simulation = parse(kScene);
  DependencyAnalysis analysis(simulation);
  ComponentOp first = component(simulation, "First");
  ComponentOp second = component(simulation, "Second");
  ComponentOp third = component(simulation, "Third");

  EXPECT_EQ(analysis.getProducers(first), SmallVector<ComponentOp>{third});
  EXPECT_EQ(analysis.getProducers(second), SmallVector<ComponentOp>{first});
  EXPECT_EQ(analysis.getProducers(third), SmallVector<ComponentOp>{second});

  EXPECT_EQ(analysis.findSubStepHazard(first), nullptr);
  const BufferAccess *hazard = analysis.findSubStepHazard(second);
  ASSERT_NE(hazard, nullptr);
  EXPECT_EQ(hazard->buffer, buffer(simulation, "B"));
  EXPECT_EQ(analysis.findSubStepHazard(third), nullptr);
}

TEST_F(DependencyAnalysisTest, ScheduleRolesAndBounds) {
  SimulationOp simulation = parse(kScene);
  DependencyAnalysis analysis(simulation);
  ComponentOp first = component(simulation, "First");
  ComponentOp second = component(simulation, "Second");
  ComponentOp third = component(simulation, "Third");

  FailureOr<Schedule> schedule =
      computeSchedule(analysis, getUserOrder(simulation));
  ASSERT_TRUE(succeeded(schedule));
  EXPECT_EQ(SmallVector<ComponentOp>(schedule->getOrder()),
            (SmallVector<ComponentOp>{first, second, third}));
  EXPECT_EQ(schedule->getRole(first, third), ReadRole::back_edge);
  EXPECT_EQ(schedule->getRole(second, first), ReadRole::interpolate);
  EXPECT_EQ(schedule->getRole(second, second), ReadRole::own);
  EXPECT_EQ(schedule->getHipStepBounds(analysis),
            SmallVector<ComponentOp>{first});
  EXPECT_EQ(schedule->getTraditionalStepBounds(),
            SmallVector<ComponentOp>{first});

  // Without a first component the cycle cannot be cut.
  EXPECT_TRUE(failed(computeSchedule(analysis, {}, /*emitDiagnostics=*/false)));
  // A different first component gives a different, equally valid step.
  FailureOr<Schedule> fromThird =
      computeSchedule(analysis, {third}, /*emitDiagnostics=*/false);
  ASSERT_TRUE(succeeded(fromThird));
  EXPECT_EQ(SmallVector<ComponentOp>(fromThird->getOrder()),
            (SmallVector<ComponentOp>{third, first, second}));
  // @Third reads through the back edge but has no num_steps: it never
  // bounds a step.
  EXPECT_TRUE(fromThird->getHipStepBounds(analysis).empty());
  // An order that contradicts a dependency is rejected.
  EXPECT_TRUE(failed(computeSchedule(analysis, {first, third, second},
                                     /*emitDiagnostics=*/false)));
}

} // namespace
