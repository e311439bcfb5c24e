//===- SimToReference.cpp - bodies as per-item functions for the oracle ---===//
//
// The reference executor (docs/Reference.md) checks every backend, so it
// shares as little as possible with them: it starts from the scheduled IR,
// before the memory plan and interpolation insertion, and this lowering only
// turns each body into a plain per-item function. A view read becomes a call
// back into the executor, which alone decides which value the read sees (its
// local time, interpolation, boundary rule). Nothing of the kernel emission
// (lib/Conversion/SimCommon) is used here.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/Scheduling.h"
#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/IR/Builders.h"
#include "mlir/IR/IRMapping.h"

#include "llvm/ADT/SetVector.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERTOREFERENCE
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Fields of `sim_ref_context` (docs/Reference.md), as pointer slots.
enum ContextField { kExecutor = 0, kReadCallback = 1, kParamCallback = 2 };
/// Parameter indices of the builtin parameters in the `param` callback.
enum BuiltinParam { kRangeParam = -1, kDtParam = -2, kMaxStepsParam = -3 };
/// Bytes of the scratch slot a callback writes into: the largest element
/// (16 lanes of f64).
constexpr int64_t kScratchBytes = 16 * 8;

/// Lowers one scheduled simulation.
class ReferenceLowering {
public:
  explicit ReferenceLowering(SimulationOp simulation)
      : simulation(simulation), context(simulation.getContext()),
        ptrType(LLVM::LLVMPointerType::get(context)) {}

  /// Checks that the simulation is scheduled and not past the front end's
  /// planning, then replaces it with the reference module.
  LogicalResult run();

private:
  LogicalResult check();
  FailureOr<DictionaryAttr> model();
  LogicalResult lowerBody(
      Region &body, StringRef name, ArrayRef<Type> argumentTypes,
      TypeRange results,
      function_ref<void(OpBuilder &, ValueRange, IRMapping &)> mapArguments,
      function_ref<void(OpBuilder &, ValueRange, ValueRange)> finish);
  Value loadField(OpBuilder &b, Location loc, Value ctx, ContextField field);
  Value callForValue(OpBuilder &b, Location loc, Value ctx, Value scratch,
                     ContextField callback, ValueRange indices, Type type);

  SimulationOp simulation;
  MLIRContext *context;
  Type ptrType;
  ModuleOp module;
  llvm::SmallVector<ComponentOp> order;
  llvm::StringMap<int32_t> bufferIndex, paramIndex;
};

LogicalResult ReferenceLowering::check() {
  if (simulation.getStrategyAttr() || simulation.findExplicitAccess())
    return simulation.emitOpError()
           << "is past --sim-plan-memory; the reference lowering starts from "
              "the scheduled IR (run --sim-prune, --sim-schedule and "
              "--sim-substep-legality, or --sim-reference-pipeline)";
  if (failed(simulation.checkConstantsInlined("sim-lower-to-reference")))
    return failure();
  std::optional<SmallVector<ComponentOp>> scheduled =
      simulation.getScheduledOrder();
  if (!scheduled)
    return simulation.emitOpError()
           << "has no complete schedule; run --sim-schedule before "
              "--sim-lower-to-reference";
  order = std::move(*scheduled);
  for (ComponentOp component : order)
    if (!component.getSubSteppingAttr())
      return component.emitOpError()
             << "has no sub-stepping verdict; run --sim-substep-legality "
                "before --sim-lower-to-reference";
  for (ParamOp param : simulation.getParams()) {
    Type type = cast<TypedAttr>(param.getValue()).getType();
    if (!type.isInteger(32) && !type.isInteger(64) && !type.isIndex() &&
        !type.isF32() && !type.isF64())
      return param.emitOpError()
             << "has type " << type
             << ", which the reference executor cannot hold; use i32, i64, "
                "index, f32 or f64";
  }
  return success();
}

/// The model indices of the buffers `op`'s bodies read, each once, in the
/// order of their first read.
DenseI64ArrayAttr getReads(Operation *op,
                           const llvm::StringMap<int32_t> &index) {
  llvm::SetVector<int64_t> reads;
  op->walk([&](ReadOp read) { reads.insert(index.lookup(read.getBuffer())); });
  return DenseI64ArrayAttr::get(op->getContext(), reads.getArrayRef());
}

/// The reference model (docs/Reference.md, "The reference model"): what the
/// executor needs beyond the scene, which the bundle writer turns into the
/// bundle's `Reference` table. Names are the scene's; model buffers and
/// parameters are numbered in the order of `buffers` and `params`.
FailureOr<DictionaryAttr> ReferenceLowering::model() {
  Builder b(context);
  auto named = [&](StringRef name, Attribute value) {
    return b.getNamedAttr(name, value);
  };
  SmallVector<Attribute> params, buffers, components, totals;
  for (ParamOp param : simulation.getParams())
    params.push_back(param.getSymNameAttr());
  for (BufferOp buffer : simulation.getBuffers())
    buffers.push_back(buffer.getSymNameAttr());

  for (ComponentOp component : order) {
    SmallVector<int64_t> writes;
    for (FlatSymbolRefAttr name :
         component.getWrites().getAsRange<FlatSymbolRefAttr>())
      writes.push_back(bufferIndex.lookup(name.getValue()));
    // How the component takes a big step under every strategy, so that the
    // executor runs any of them from one model.
    SmallVector<NamedAttribute> stepping;
    for (uint32_t value = 0; value <= getMaxEnumValForStrategy(); ++value) {
      Strategy strategy = *symbolizeStrategy(value);
      FailureOr<Stepping> decided = decideStepping(component, strategy);
      if (failed(decided))
        return failure();
      stepping.push_back(named(
          stringifyStrategy(strategy),
          b.getDictionaryAttr(
              {named("advance", AdvanceAttr::get(context, decided->advance)),
               named("estimates", b.getBoolAttr(decided->estimates))})));
    }
    SmallVector<NamedAttribute> fields = {
        named("name", component.getSymNameAttr()),
        named("sub_stepping", component.getSubSteppingAttr()),
        named("num_steps", b.getBoolAttr(component.hasNumSteps())),
        named("writes", b.getDenseI64ArrayAttr(writes)),
        named("reads", getReads(component, bufferIndex)),
        named("stepping", b.getDictionaryAttr(stepping))};
    // The window its local time steps read (the neighbours of a group).
    if (DenseI64ArrayAttr window = component.getLocalWindowAttr())
      fields.push_back(named("local_window", window));
    // The offsets its reader reads its fluxes at (a flux pair's writer).
    if (DenseI64ArrayAttr window = component.getFluxWindowAttr())
      fields.push_back(named("flux_window", window));
    components.push_back(b.getDictionaryAttr(fields));
  }
  for (TotalOp total : simulation.getTotals())
    totals.push_back(
        b.getDictionaryAttr({named("name", total.getSymNameAttr()),
                             named("reads", getReads(total, bufferIndex))}));
  // The largest big step of every strategy.
  SmallVector<NamedAttribute> stepCaps;
  for (uint32_t value = 0; value <= getMaxEnumValForStrategy(); ++value) {
    Strategy strategy = *symbolizeStrategy(value);
    stepCaps.push_back(
        named(stringifyStrategy(strategy),
              b.getI64IntegerAttr(getStepCap(simulation, strategy))));
  }
  return b.getDictionaryAttr(
      {named("params", b.getArrayAttr(params)),
       named("buffers", b.getArrayAttr(buffers)),
       named("components", b.getArrayAttr(components)),
       named("totals", b.getArrayAttr(totals)),
       named("step_caps", b.getDictionaryAttr(stepCaps))});
}

Value ReferenceLowering::loadField(OpBuilder &b, Location loc, Value ctx,
                                   ContextField field) {
  Value slot = LLVM::GEPOp::create(b, loc, ptrType, ptrType, ctx,
                                   ArrayRef<LLVM::GEPArg>{field});
  return LLVM::LoadOp::create(b, loc, ptrType, slot);
}

/// Calls `callback(executor, indices..., scratch)` and loads the value of
/// `type` it wrote (an index as i64).
Value ReferenceLowering::callForValue(OpBuilder &b, Location loc, Value ctx,
                                      Value scratch, ContextField callback,
                                      ValueRange indices, Type type) {
  Value function = loadField(b, loc, ctx, callback);
  SmallVector<Value> operands = {function, loadField(b, loc, ctx, kExecutor)};
  SmallVector<Type> parameterTypes = {ptrType};
  for (Value index : indices) {
    operands.push_back(index);
    parameterTypes.push_back(index.getType());
  }
  operands.push_back(scratch);
  parameterTypes.push_back(ptrType);
  auto functionType = LLVM::LLVMFunctionType::get(
      LLVM::LLVMVoidType::get(context), parameterTypes);
  LLVM::CallOp::create(b, loc, functionType, operands);
  Type loadType = type.isIndex() ? b.getI64Type() : type;
  unsigned alignment =
      getElementTypeOrSelf(loadType).getIntOrFloatBitWidth() / 8;
  Value value = LLVM::LoadOp::create(b, loc, loadType, scratch, alignment);
  if (type.isIndex())
    value = arith::IndexCastOp::create(b, loc, type, value);
  return value;
}

/// Makes `func.func @name(ctx, argumentTypes...) -> results` from a body:
/// `mapArguments` maps the body's block arguments to values made from the
/// function's arguments, view reads and parameter reads become callbacks,
/// and `finish` turns the yielded values into the function's result.
LogicalResult ReferenceLowering::lowerBody(
    Region &body, StringRef name, ArrayRef<Type> argumentTypes,
    TypeRange results,
    function_ref<void(OpBuilder &, ValueRange, IRMapping &)> mapArguments,
    function_ref<void(OpBuilder &, ValueRange, ValueRange)> finish) {
  OpBuilder b = OpBuilder::atBlockEnd(module.getBody());
  Location loc = body.getLoc();
  SmallVector<Type> inputs = {ptrType};
  inputs.append(argumentTypes.begin(), argumentTypes.end());
  auto func =
      func::FuncOp::create(b, loc, name, b.getFunctionType(inputs, results));
  Block *entry = func.addEntryBlock();
  b.setInsertionPointToStart(entry);
  Value ctx = entry->getArgument(0);
  ValueRange arguments = entry->getArguments().drop_front();

  // One scratch slot for every callback: each read's value is loaded right
  // after its call, so the slot is free again.
  Value one =
      LLVM::ConstantOp::create(b, loc, b.getI64Type(), b.getI64IntegerAttr(1));
  Value scratch = LLVM::AllocaOp::create(
      b, loc, ptrType, LLVM::LLVMArrayType::get(b.getI8Type(), kScratchBytes),
      one, /*alignment=*/16);

  IRMapping mapping;
  mapArguments(b, arguments, mapping);
  // The terminator is cloned too, so that it sees the replacements below;
  // `finish` takes its operands and it goes.
  for (Operation &op : body.front())
    b.clone(op, mapping);
  Operation *yield = entry->getTerminator();

  // Reads and parameters call back into the executor.
  SmallVector<Operation *> accesses;
  func.walk([&](Operation *op) {
    if (isa<ReadOp, GetParamOp>(op))
      accesses.push_back(op);
  });
  for (Operation *op : accesses) {
    OpBuilder at(op);
    Location opLoc = op->getLoc();
    Value value;
    if (auto read = dyn_cast<ReadOp>(op)) {
      Value buffer = arith::ConstantOp::create(
          at, opLoc,
          at.getI32IntegerAttr(bufferIndex.lookup(read.getBuffer())));
      Value item = arith::IndexCastOp::create(at, opLoc, at.getI64Type(),
                                              read.getIndex());
      value = callForValue(at, opLoc, ctx, scratch, kReadCallback,
                           {buffer, item}, read.getType());
    } else {
      auto getParam = cast<GetParamOp>(op);
      StringRef param = getParam.getParam();
      int32_t index = param == "range"       ? kRangeParam
                      : param == "dt"        ? kDtParam
                      : param == "max_steps" ? kMaxStepsParam
                                             : paramIndex.lookup(param);
      Value indexValue =
          arith::ConstantOp::create(at, opLoc, at.getI32IntegerAttr(index));
      value = callForValue(at, opLoc, ctx, scratch, kParamCallback,
                           {indexValue}, getParam.getType());
    }
    op->getResult(0).replaceAllUsesWith(value);
    op->erase();
  }
  SmallVector<Value> yielded(yield->getOperands());
  b.setInsertionPoint(yield);
  finish(b, arguments, yielded);
  yield->erase();
  return success();
}

LogicalResult ReferenceLowering::run() {
  if (failed(check()))
    return failure();
  for (auto [index, buffer] : llvm::enumerate(simulation.getBuffers()))
    bufferIndex[buffer.getSymName()] = index;
  for (auto [index, param] : llvm::enumerate(simulation.getParams()))
    paramIndex[param.getSymName()] = index;

  OpBuilder top(simulation);
  FailureOr<DictionaryAttr> referenceModel = model();
  if (failed(referenceModel))
    return failure();
  module = ModuleOp::create(top, simulation.getLoc(),
                            (simulation.getSymName() + "_reference").str());
  module->setAttr(kReferenceModelAttrName, *referenceModel);

  Type i64 = top.getI64Type(), i32 = top.getI32Type(), f64 = top.getF64Type();
  Type index = top.getIndexType();
  FloatType dtType = simulation.getTimeStepType();

  auto itemArgument = [&](OpBuilder &b, Value item) -> Value {
    return arith::IndexCastOp::create(b, item.getLoc(), index, item);
  };
  // Stores the k-th yielded value at `pointers[k]` (lanes packed).
  auto storeAll = [&](OpBuilder &b, ValueRange values,
                      function_ref<Value(unsigned)> pointer) {
    for (auto [k, value] : llvm::enumerate(values)) {
      unsigned alignment =
          getElementTypeOrSelf(value.getType()).getIntOrFloatBitWidth() / 8;
      LLVM::StoreOp::create(b, value.getLoc(), value, pointer(k), alignment);
    }
    func::ReturnOp::create(b, simulation.getLoc());
  };

  int64_t bufferNumber = 0;
  for (BufferOp buffer : simulation.getBuffers()) {
    std::string suffix = std::to_string(bufferNumber++);
    auto storeOut = [&](OpBuilder &builder, ValueRange args,
                        ValueRange values) {
      storeAll(builder, values, [&](unsigned) { return args.back(); });
    };
    if (failed(lowerBody(
            buffer.getInit(), "sim_ref_init_" + suffix, {i64, ptrType}, {},
            [&](OpBuilder &builder, ValueRange args, IRMapping &mapping) {
              mapping.map(buffer.getInitItem(), itemArgument(builder, args[0]));
            },
            storeOut)))
      return failure();
    if (buffer.getExact().empty())
      continue;
    if (failed(lowerBody(
            buffer.getExact(), "sim_ref_exact_" + suffix, {i64, f64, ptrType},
            {},
            [&](OpBuilder &builder, ValueRange args, IRMapping &mapping) {
              mapping.map(buffer.getExactItem(),
                          itemArgument(builder, args[0]));
              mapping.map(buffer.getExactTime(), args[1]);
            },
            storeOut)))
      return failure();
  }

  int64_t componentNumber = 0;
  for (ComponentOp component : order) {
    std::string suffix = std::to_string(componentNumber++);
    if (component.hasNumSteps() &&
        failed(lowerBody(
            component.getNumSteps(), "sim_ref_num_steps_" + suffix, {i64, i64},
            {i32},
            [&](OpBuilder &builder, ValueRange args, IRMapping &mapping) {
              mapping.map(component.getNumStepsItem(),
                          itemArgument(builder, args[0]));
              mapping.map(component.getNumStepsTime(), args[1]);
            },
            [&](OpBuilder &builder, ValueRange, ValueRange values) {
              func::ReturnOp::create(builder, component.getLoc(), values);
            })))
      return failure();
    if (failed(lowerBody(
            component.getEvaluate(), "sim_ref_evaluate_" + suffix,
            {i64, i64, i32, f64, ptrType}, {},
            [&](OpBuilder &builder, ValueRange args, IRMapping &mapping) {
              mapping.map(component.getEvaluateItem(),
                          itemArgument(builder, args[0]));
              mapping.map(component.getEvaluateTime(), args[1]);
              mapping.map(component.getEvaluateSteps(), args[2]);
              // An f32 dt converts to double and back exactly.
              Value dt = args[3];
              if (dtType != dt.getType())
                dt = arith::TruncFOp::create(builder, dt.getLoc(), dtType, dt);
              mapping.map(component.getEvaluateTimeStep(), dt);
            },
            [&](OpBuilder &builder, ValueRange args, ValueRange values) {
              Value outs = args.back();
              storeAll(builder, values, [&](unsigned k) -> Value {
                Value slot = LLVM::GEPOp::create(
                    builder, component.getLoc(), ptrType, ptrType, outs,
                    ArrayRef<LLVM::GEPArg>{static_cast<int32_t>(k)});
                return LLVM::LoadOp::create(builder, component.getLoc(),
                                            ptrType, slot);
              });
            })))
      return failure();
  }
  int64_t totalNumber = 0;
  for (TotalOp total : simulation.getTotals()) {
    if (failed(lowerBody(
            total.getBody(), "sim_ref_total_" + std::to_string(totalNumber++),
            {i64, ptrType}, {},
            [&](OpBuilder &builder, ValueRange args, IRMapping &mapping) {
              mapping.map(total.getItem(), itemArgument(builder, args[0]));
            },
            [&](OpBuilder &builder, ValueRange args, ValueRange values) {
              storeAll(builder, values, [&](unsigned) { return args.back(); });
            })))
      return failure();
  }
  simulation.erase();
  return success();
}

struct SimLowerToReferencePass
    : public sim::impl::SimLowerToReferenceBase<SimLowerToReferencePass> {
  void runOnOperation() override {
    SmallVector<SimulationOp> simulations(
        getOperation().getOps<SimulationOp>());
    if (failed(SimulationOp::checkLoweredNamesAreFree(
            simulations, "_reference", "reference functions", getArgument())))
      return signalPassFailure();
    for (SimulationOp simulation : simulations)
      if (failed(ReferenceLowering(simulation).run()))
        return signalPassFailure();
  }
};

} // namespace
