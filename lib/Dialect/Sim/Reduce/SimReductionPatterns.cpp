//===- SimReductionPatterns.cpp - sim-reduce's patterns for scenes --------===//
//
// The reduction tree deletes ranges of operations and keeps a deletion when
// the test script still calls the scene interesting. In a scene one deletion
// rarely works alone: a buffer and its writer must go together (every buffer
// has one writer), and a component that others read cannot go while they
// read it.
// These patterns make the steps a person takes by hand when reducing a scene
// (each leaves a scene that verifies, and the tree keeps it only when it is
// still interesting):
//
//  - a component goes with the buffers it writes: the reads of those buffers
//    elsewhere become zeros, and the observe and schedule lists drop them
//    (one component at a time, each removal tested);
//  - an observed buffer leaves the observe list (one at a time, tested), so
//    that sim-prune (--opt-reduction-pass) can remove what only it needed;
//  - a parameter goes, its reads replaced by its value (one at a time,
//    tested);
//  - the range shrinks to one block of 32 items, enough for every boundary
//    rule and window to keep its shape in most reports.
//
// All of them are patterns on the sim.simulation, which change only what
// is inside it: the reduction tree holds pointers to the operations of the
// region it reduces, and a pattern on one of them (a component) that erased
// another (its buffer) would leave one dangling. So the steps that must be
// tested one at a time test a copy of the module themselves.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/Reduce/SimReductionPatterns.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/DialectRegistry.h"
#include "mlir/IR/PatternMatch.h"
#include "mlir/IR/SymbolTable.h"
#include "mlir/Reducer/ReductionPatternInterface.h"
#include "mlir/Reducer/Tester.h"
#include "llvm/ADT/SmallPtrSet.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

/// The range a scene shrinks to: one block of local time steps.
constexpr int64_t kReducedRange = 32;

/// `list` without the symbols in `removed`.
ArrayAttr without(Builder &b, ArrayAttr list,
                  const llvm::SmallPtrSetImpl<Attribute> &removed) {
  SmallVector<Attribute> kept;
  for (Attribute name : list)
    if (!removed.contains(cast<FlatSymbolRefAttr>(name).getAttr()))
      kept.push_back(name);
  return b.getArrayAttr(kept);
}

/// Erases `component` of `simulation` together with the buffers it writes.
/// Reads of those buffers in other components, buffers' bodies and totals
/// become zeros of their type; the observe and schedule lists drop the names.
/// Fails without a change when a buffer is named anywhere else (another
/// buffer's interpolation, a lowered load) or a read has a type without a
/// zero.
LogicalResult eraseComponentWithBuffers(RewriterBase &rewriter,
                                        SimulationOp simulation,
                                        ComponentOp component) {
  Region &scene = simulation.getBody();
  llvm::SmallPtrSet<Attribute, 4> bufferNames;
  SmallVector<BufferOp> buffers;
  for (auto name : component.getWrites().getAsRange<FlatSymbolRefAttr>()) {
    BufferOp buffer = simulation.lookupBuffer(name);
    if (!buffer)
      return failure();
    buffers.push_back(buffer);
    bufferNames.insert(name.getAttr());
  }

  // Every use of a written buffer outside the component must be a read that
  // can become a zero, or an entry of the observe list.
  SmallVector<std::pair<ReadOp, TypedAttr>> reads;
  for (BufferOp buffer : buffers) {
    std::optional<SymbolTable::UseRange> uses =
        SymbolTable::getSymbolUses(buffer, &scene);
    if (!uses)
      return failure();
    for (const SymbolTable::SymbolUse &use : *uses) {
      Operation *user = use.getUser();
      if (component->isAncestor(user) || isa<ObserveOp>(user))
        continue;
      auto read = dyn_cast<ReadOp>(user);
      if (!read)
        return failure();
      TypedAttr zero = rewriter.getZeroAttr(read.getType());
      if (!zero)
        return failure();
      reads.push_back({read, zero});
    }
  }
  // The component itself may be named by the schedule only.
  std::optional<SymbolTable::UseRange> componentUses =
      SymbolTable::getSymbolUses(component, &scene);
  if (!componentUses)
    return failure();
  for (const SymbolTable::SymbolUse &use : *componentUses)
    if (!isa<ScheduleOp>(use.getUser()))
      return failure();

  for (auto [read, zero] : reads) {
    rewriter.setInsertionPoint(read);
    rewriter.replaceOpWithNewOp<arith::ConstantOp>(read, zero);
  }
  if (ObserveOp observe = simulation.getObserveOp()) {
    ArrayAttr kept = without(rewriter, observe.getBuffers(), bufferNames);
    if (kept.empty())
      rewriter.eraseOp(observe);
    else
      rewriter.modifyOpInPlace(observe, [&] { observe.setBuffersAttr(kept); });
  }
  if (ScheduleOp schedule = simulation.getScheduleOp()) {
    llvm::SmallPtrSet<Attribute, 1> componentName;
    componentName.insert(component.getSymNameAttr());
    ArrayAttr order = without(rewriter, schedule.getOrder(), componentName);
    if (order.empty()) {
      rewriter.eraseOp(schedule);
    } else {
      rewriter.modifyOpInPlace(schedule, [&] {
        schedule.setOrderAttr(order);
        if (ArrayAttr bounded = schedule.getBoundedByAttr())
          schedule.setBoundedByAttr(without(rewriter, bounded, componentName));
      });
    }
  }
  for (BufferOp buffer : buffers)
    rewriter.eraseOp(buffer);
  rewriter.eraseOp(component);
  return success();
}

/// Drops `buffer` from the observe list of `simulation` (sim-prune then
/// removes what only it needed).
LogicalResult dropObserved(RewriterBase &rewriter, SimulationOp simulation,
                           FlatSymbolRefAttr buffer) {
  ObserveOp observe = simulation.getObserveOp();
  if (!observe || observe.getBuffers().size() < 2)
    return failure();
  llvm::SmallPtrSet<Attribute, 1> removed;
  removed.insert(buffer.getAttr());
  rewriter.modifyOpInPlace(observe, [&] {
    observe.setBuffersAttr(without(rewriter, observe.getBuffers(), removed));
  });
  return success();
}

/// Replaces every read of `param` with the value the scene gives it and
/// erases it. Fails without a change when a read asks for another type.
LogicalResult inlineParam(RewriterBase &rewriter, SimulationOp simulation,
                          ParamOp param) {
  std::optional<SymbolTable::UseRange> uses =
      SymbolTable::getSymbolUses(param, &simulation.getBody());
  if (!uses)
    return failure();
  SmallVector<GetParamOp> reads;
  for (const SymbolTable::SymbolUse &use : *uses) {
    auto read = dyn_cast<GetParamOp>(use.getUser());
    if (!read || read.getType() != param.getValue().getType())
      return failure();
    reads.push_back(read);
  }
  for (GetParamOp read : reads) {
    rewriter.setInsertionPoint(read);
    rewriter.replaceOpWithNewOp<arith::ConstantOp>(read, param.getValue());
  }
  rewriter.eraseOp(param);
  return success();
}

/// Removes components (each with the buffers it writes), observed outputs
/// and parameters (their reads become their values) one at a time, keeping
/// each removal the test still calls interesting. Deleting a component alone or
/// a buffer alone leaves a scene that does not verify, and the reduction tree
/// deletes ranges of sibling operations, so it cannot find these steps itself;
/// a pattern on the simulation may erase what is inside it, which one on a
/// component may not (the tree holds pointers to the component's siblings).
struct RemoveSceneParts : OpRewritePattern<SimulationOp> {
  RemoveSceneParts(MLIRContext *context, const Tester &tester)
      : OpRewritePattern(context), tester(tester) {}

  LogicalResult matchAndRewrite(SimulationOp simulation,
                                PatternRewriter &rewriter) const override {
    auto module = dyn_cast_or_null<ModuleOp>(simulation->getParentOp());
    if (!module)
      return failure();
    bool changed = false;
    // Tries `step` on a copy of the module; applies it to the scene when
    // the copy stays interesting.
    auto tryStep =
        [&](llvm::function_ref<LogicalResult(RewriterBase &, SimulationOp)>
                step) {
          OwningOpRef<ModuleOp> copy = module.clone();
          auto copied = cast<SimulationOp>(
              SymbolTable::lookupSymbolIn(*copy, simulation.getSymNameAttr()));
          IRRewriter copyRewriter(copy->getContext());
          if (failed(step(copyRewriter, copied)) ||
              tester.isInteresting(*copy).first !=
                  Tester::Interestingness::True)
            return;
          if (succeeded(step(rewriter, simulation)))
            changed = true;
        };
    SmallVector<StringAttr> components;
    for (ComponentOp component : simulation.getBody().getOps<ComponentOp>())
      components.push_back(component.getSymNameAttr());
    for (StringAttr name : components)
      tryStep([&](RewriterBase &stepRewriter, SimulationOp scene) {
        auto component = dyn_cast_or_null<ComponentOp>(
            SymbolTable::lookupSymbolIn(scene, name));
        if (!component)
          return failure();
        return eraseComponentWithBuffers(stepRewriter, scene, component);
      });
    if (ObserveOp observe = simulation.getObserveOp()) {
      auto observed =
          llvm::to_vector(observe.getBuffers().getAsRange<FlatSymbolRefAttr>());
      for (FlatSymbolRefAttr name : observed)
        tryStep([&](RewriterBase &stepRewriter, SimulationOp scene) {
          return dropObserved(stepRewriter, scene, name);
        });
    }
    SmallVector<StringAttr> params;
    for (ParamOp param : simulation.getParams())
      params.push_back(param.getSymNameAttr());
    for (StringAttr name : params)
      tryStep([&](RewriterBase &stepRewriter, SimulationOp scene) {
        auto param =
            dyn_cast_or_null<ParamOp>(SymbolTable::lookupSymbolIn(scene, name));
        if (!param)
          return failure();
        return inlineParam(stepRewriter, scene, param);
      });
    return success(changed);
  }

  const Tester &tester;
};

/// The range shrinks to one block of local time steps.
struct ShrinkRange : OpRewritePattern<SimulationOp> {
  using OpRewritePattern::OpRewritePattern;

  LogicalResult matchAndRewrite(SimulationOp simulation,
                                PatternRewriter &rewriter) const override {
    if (simulation.getRange() <= kReducedRange)
      return failure();
    rewriter.modifyOpInPlace(simulation, [&] {
      simulation.setRangeAttr(rewriter.getI64IntegerAttr(kReducedRange));
    });
    return success();
  }
};

struct SimReductionPatternInterface : DialectReductionPatternInterface {
  SimReductionPatternInterface(Dialect *dialect)
      : DialectReductionPatternInterface(dialect) {}

  void populateReductionPatterns(RewritePatternSet &patterns) const override {
    patterns.add<ShrinkRange>(patterns.getContext());
  }
  void populateReductionPatternsWithTester(RewritePatternSet &patterns,
                                           Tester &tester) const override {
    patterns.add<RemoveSceneParts>(patterns.getContext(), tester);
  }
};

} // namespace

void mlir::sim::registerSimReductionPatterns(DialectRegistry &registry) {
  registry.addExtension(+[](MLIRContext *, SimDialect *dialect) {
    dialect->addInterfaces<SimReductionPatternInterface>();
  });
}
