//===- SimOpsTest.cpp - the named accessors of sim operations -------------===//
//
// Lowerings and passes reach body arguments, writers and schedule positions
// only through named accessors (never `getArgument(N)` or a hand-rolled
// lookup). This checks that each accessor returns what its name says.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/Parser/Parser.h"

#include "gtest/gtest.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

constexpr const char *kScene = R"mlir(
sim.simulation @scene range(64) dt(1.0e-2 : f64) max_steps(3) {
  sim.buffer @X : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    sim.yield %t : f64
  }
  sim.buffer @Y : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.buffer @Z : f64 init {
  ^bb0(%i: index):
    %c = arith.constant 0.0 : f64
    sim.yield %c : f64
  }
  sim.component @Move writes(@X, @Y) num_steps {
  ^bb0(%i: index, %t: i64):
    %c = arith.constant 1 : i32
    sim.yield %c : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    sim.yield %x, %x : f64, f64
  }
  sim.component @Sink writes(@Z) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %x = sim.read @X[%i] : f64
    sim.yield %x : f64
  }
  sim.schedule [@Move]
  sim.observe [@Z]
}
)mlir";

class SimOpsTest : public ::testing::Test {
protected:
  SimOpsTest() { context.loadDialect<SimDialect, arith::ArithDialect>(); }

  SimulationOp parse(const char *source) {
    module = parseSourceString<ModuleOp>(source, &context);
    EXPECT_TRUE(module) << "the test scene does not parse";
    return *module->getOps<SimulationOp>().begin();
  }
  FlatSymbolRefAttr symbol(StringRef name) {
    return FlatSymbolRefAttr::get(&context, name);
  }

  MLIRContext context;
  OwningOpRef<ModuleOp> module;
};

TEST_F(SimOpsTest, ComponentBodyArguments) {
  SimulationOp simulation = parse(kScene);
  ComponentOp move = simulation.lookupComponent(symbol("Move"));
  Block &numSteps = move.getNumSteps().front();
  Block &evaluate = move.getEvaluate().front();
  EXPECT_EQ(move.getNumStepsItem(), numSteps.getArgument(0));
  EXPECT_EQ(move.getNumStepsTime(), numSteps.getArgument(1));
  EXPECT_EQ(move.getEvaluateItem(), evaluate.getArgument(0));
  EXPECT_EQ(move.getEvaluateTime(), evaluate.getArgument(1));
  EXPECT_EQ(move.getEvaluateSteps(), evaluate.getArgument(2));
  EXPECT_EQ(move.getEvaluateTimeStep(), evaluate.getArgument(3));
  // The types are those of the documented signatures.
  Builder b(&context);
  EXPECT_EQ(move.getNumStepsItem().getType(), b.getIndexType());
  EXPECT_EQ(move.getNumStepsTime().getType(), b.getI64Type());
  EXPECT_EQ(move.getEvaluateSteps().getType(), b.getI32Type());
  EXPECT_EQ(move.getEvaluateTimeStep().getType(), b.getF64Type());
}

TEST_F(SimOpsTest, BufferBodyArguments) {
  SimulationOp simulation = parse(kScene);
  BufferOp x = simulation.lookupBuffer(symbol("X"));
  EXPECT_EQ(x.getInitItem(), x.getInit().front().getArgument(0));
  EXPECT_EQ(x.getExactItem(), x.getExact().front().getArgument(0));
  EXPECT_EQ(x.getExactTime(), x.getExact().front().getArgument(1));
  EXPECT_EQ(x.getExactTime().getType(), Builder(&context).getF64Type());
}

TEST_F(SimOpsTest, WritersAndSchedulePositions) {
  SimulationOp simulation = parse(kScene);
  ComponentOp move = simulation.lookupComponent(symbol("Move"));
  ComponentOp sink = simulation.lookupComponent(symbol("Sink"));
  BufferOp y = simulation.lookupBuffer(symbol("Y"));
  EXPECT_EQ(simulation.getWriter(symbol("X")), move);
  EXPECT_EQ(simulation.getWriter(y), move);
  EXPECT_EQ(simulation.getWriter(symbol("Z")), sink);
  EXPECT_FALSE(simulation.getWriter(symbol("Nope")));

  // The user gave a prefix: only @Move has a recorded position.
  EXPECT_EQ(simulation.getSchedulePosition(move), 0u);
  EXPECT_EQ(simulation.getSchedulePosition(sink), std::nullopt);
  simulation.getScheduleOp().setOrderAttr(
      Builder(&context).getArrayAttr({symbol("Move"), symbol("Sink")}));
  EXPECT_EQ(simulation.getSchedulePosition(sink), 1u);
  simulation.getScheduleOp().erase();
  EXPECT_EQ(simulation.getSchedulePosition(move), std::nullopt);
}

} // namespace
