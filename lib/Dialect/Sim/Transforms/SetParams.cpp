//===- SetParams.cpp - override scene parameters --------------------------===//
//
// Scene parameters (the item range, the base time step, the largest big step
// and every sim.param) must be settable without editing the scene file. This
// pass applies `name=value` overrides and rejects names and values it cannot
// apply, so that a typo on the command line never silently runs the default.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/IR/Builders.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/Error.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMSETPARAMS
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Why a value could not be parsed.
enum class ScalarError {
  /// The text is not a number of the expected kind.
  Invalid,
  /// The text is a number, but the type cannot hold it.
  OutOfRange,
};

/// Parses `text` as a constant of `type` (a signless integer, index or float).
/// Integers are written as in MLIR literals: decimal or `0x` hexadecimal,
/// optionally negative. A value that does not fit is an error, never silently
/// truncated: a decimal integer must fit the signed range of the width, as
/// the kernels read it and sim-run --set takes it (4294967295 is no i32),
/// while a hexadecimal one gives the bits and may use the full unsigned range
/// (0xFF is an i8 of -1, as in an MLIR literal), unless `isSigned` is set.
static FailureOr<TypedAttr> parseScalar(Builder &builder, StringRef text,
                                        Type type, ScalarError &error,
                                        bool isSigned = false) {
  error = ScalarError::Invalid;
  text = text.trim();
  if (isa<IntegerType, IndexType>(type)) {
    unsigned width = type.isIndex() ? IndexType::kInternalStorageBitWidth
                                    : cast<IntegerType>(type).getWidth();
    StringRef digits = text;
    bool negative = digits.consume_front("-");
    unsigned radix = 10;
    if (digits.consume_front("0x") || digits.consume_front("0X"))
      radix = 16;
    // StringRef::getAsInteger accepts neither a sign nor an empty string here,
    // and with an explicit radix it does not read a leading 0 as octal.
    APInt magnitude;
    if (digits.empty() || digits.getAsInteger(radix, magnitude))
      return failure();
    // One more bit, so that the magnitude is never read as negative.
    APInt value = magnitude.zext(magnitude.getBitWidth() + 1);
    if (negative)
      value.negate();
    // An i1 holds 0 and 1 (its signed range is -1..0).
    bool bits = radix == 16 || width == 1;
    bool fits = negative || isSigned || !bits
                    ? value.getSignificantBits() <= width
                    : value.getActiveBits() <= width;
    if (!fits) {
      error = ScalarError::OutOfRange;
      return failure();
    }
    return TypedAttr(builder.getIntegerAttr(type, value.sextOrTrunc(width)));
  }
  if (auto floatType = dyn_cast<FloatType>(type)) {
    // Convert in the parameter's own semantics: a finite value that overflows
    // to infinity or a non-zero one that underflows to zero is out of range.
    APFloat value(floatType.getFloatSemantics());
    llvm::Expected<APFloat::opStatus> status =
        value.convertFromString(text, APFloat::rmNearestTiesToEven);
    if (!status) {
      llvm::consumeError(status.takeError());
      return failure();
    }
    if ((*status & APFloat::opOverflow) ||
        ((*status & APFloat::opUnderflow) && value.isZero())) {
      error = ScalarError::OutOfRange;
      return failure();
    }
    return TypedAttr(FloatAttr::get(floatType, value));
  }
  return failure();
}

/// Returns `options` without the whitespace next to `=`, `,`, `{` and `}`.
/// MLIR's pass-option parser ends an option at a space, so that
/// `values=L=64, k=0.5` would otherwise be `values=L=64,` and an unknown
/// option `k`, and `values = L=64` an error with no message.
static std::string closeUpSeparators(StringRef options) {
  auto isSeparator = [](char c) { return StringRef("=,{}").contains(c); };
  options = options.trim();
  std::string result;
  for (size_t i = 0, e = options.size(); i < e;) {
    if (!llvm::isSpace(options[i])) {
      result.push_back(options[i++]);
      continue;
    }
    size_t next = i;
    while (next < e && llvm::isSpace(options[next]))
      ++next;
    // trim() leaves no whitespace at either end, so options[next] exists.
    if (!isSeparator(options[next]) &&
        (result.empty() || !isSeparator(result.back())))
      result.append(options.slice(i, next).str());
    i = next;
  }
  return result;
}

struct SetParamsPass : public sim::impl::SimSetParamsBase<SetParamsPass> {
  using SimSetParamsBase::SimSetParamsBase;

  /// Accepts whitespace around names, `=` and `,` (as sim-translate's
  /// --sim-set-params does) and tells how the option is written when the
  /// string still does not parse (`--sim-set-params="L=64"` is an unknown
  /// option `L`). The error has no location: there is no IR yet.
  LogicalResult initializeOptions(
      StringRef options,
      function_ref<LogicalResult(const Twine &)> errorHandler) override {
    return Pass::initializeOptions(
        closeUpSeparators(options), [&](const Twine &message) {
          std::string text = message.str();
          return errorHandler(StringRef(text).rtrim() +
                              "; --sim-set-params takes its overrides as "
                              "values=name=value,name=value,... (for example "
                              "--sim-set-params=\"values=range=16384,L=64\")");
        });
  }

  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    Builder builder(&getContext());
    // The front end decides from the values (the big step's cap from
    // max_steps, the level blocks from the range): after it, new values
    // would leave a plan made for the old ones.
    if (StrategyAttr strategy = simulation.getStrategyAttr();
        strategy && !values.empty()) {
      simulation.emitError()
          << "has been through the front end already (a memory plan for "
             "strategy '"
          << stringifyStrategy(strategy.getValue())
          << "'), which decided from its values; set them on the scene as "
             "written, before --sim-front-end";
      return signalPassFailure();
    }
    for (const std::string &entry : values) {
      // A comma too many (`L=64,,k=1` or one at an end) leaves an empty
      // entry: named as such, since '' in a message is easy to misread.
      if (StringRef(entry).trim().empty()) {
        simulation.emitError()
            << "expects a parameter override of the form name=value, but got "
               "an empty entry; remove the extra comma";
        return signalPassFailure();
      }
      // Whitespace around the name, `=` and the value is not part of them
      // (sim-translate's comma-separated list keeps the blanks after commas).
      auto [name, text] = StringRef(entry).split('=');
      name = name.trim();
      if (name.empty() || !StringRef(entry).contains('=')) {
        simulation.emitError() << "expects a parameter override of the form "
                                  "name=value, but got '"
                               << StringRef(entry).trim() << "'";
        return signalPassFailure();
      }
      if (failed(apply(simulation, builder, name, text)))
        return signalPassFailure();
    }
  }

  LogicalResult apply(SimulationOp simulation, Builder &builder, StringRef name,
                      StringRef text) {
    ScalarError error;
    auto invalid = [&](Type type) {
      return simulation.emitError()
             << "cannot set parameter '" << name << "': '" << text.trim()
             << (error == ScalarError::OutOfRange ? "' is out of range for "
                                                  : "' is not a valid ")
             << type;
    };
    if (name == "range" || name == "max_steps") {
      // Parsed as i64 whatever the attribute's width, so that a value past
      // the limit is told the limit, not the width.
      int64_t most = name == "range" ? SimulationOp::kMaxRange
                                     : SimulationOp::kMaxMaxSteps;
      FailureOr<TypedAttr> value = parseScalar(
          builder, text, builder.getI64Type(), error, /*isSigned=*/true);
      if (failed(value))
        return simulation.emitError()
               << "cannot set parameter '" << name << "': '" << text.trim()
               << "' is not an integer from 1 to " << most;
      int64_t intValue = cast<IntegerAttr>(*value).getInt();
      if (intValue < 1)
        return simulation.emitError()
               << "cannot set parameter '" << name << "' to " << intValue
               << ": it must be at least 1";
      if (intValue > most)
        return simulation.emitError()
               << "cannot set parameter '" << name << "' to " << intValue
               << ": it must be at most " << most;
      if (name == "range")
        simulation.setRangeAttr(builder.getI64IntegerAttr(intValue));
      else
        simulation.setMaxStepsAttr(builder.getI32IntegerAttr(intValue));
      return success();
    }
    if (name == "dt") {
      Type type = simulation.getTimeStepType();
      FailureOr<TypedAttr> value = parseScalar(builder, text, type, error);
      if (failed(value))
        return invalid(type);
      double dt = cast<FloatAttr>(*value).getValueAsDouble();
      if (!(dt > 0.0) || !std::isfinite(dt))
        return simulation.emitError()
               << "cannot set parameter 'dt' to " << text.trim()
               << ": it must be positive and finite";
      simulation.setDtAttr(*value);
      return success();
    }
    auto param = dyn_cast_or_null<ParamOp>(
        SymbolTable::lookupSymbolIn(simulation, builder.getStringAttr(name)));
    if (!param) {
      InFlightDiagnostic diag = simulation.emitError()
                                << "has no parameter named '" << name
                                << "'; it has range, dt, max_steps";
      for (ParamOp known : simulation.getParams())
        diag << ", " << known.getSymName();
      return diag;
    }
    Type type = cast<TypedAttr>(param.getValue()).getType();
    FailureOr<TypedAttr> value = parseScalar(builder, text, type, error);
    if (failed(value))
      return invalid(type);
    param.setValueAttr(*value);
    return success();
  }
};

} // namespace
