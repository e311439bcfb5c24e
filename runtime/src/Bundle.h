//===- Bundle.h - a verified scene bundle in memory -------------*- C++ -*-===//
//
// A `.simb` file (docs/Bundle.md) is the header of BundleFormat.h and one
// FlatBuffer of runtime/schema/bundle.fbs. Reading one checks, in order, the
// header (magic, format version, size, CRC-32 of the rest), the FlatBuffer
// (FlatBuffers' verifier: every offset and length inside the buffer), and
// the cross-references no schema expresses (BundleVerifier.cpp: indices,
// enum values, names, every launch against its kernel's signature, clock
// slots, the ELF headers of the shared objects). Only then is it unpacked
// into the generated object API (`schema::BundleT`), which the executors
// read without checking again.
//
// The rest of this header names the schema's values for people (strategy,
// type and element names) and holds the scalar values of parameters and dt.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_BUNDLE_H
#define SIM_RUNTIME_BUNDLE_H

#include "sim/Runtime/bundle_generated.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sim::rt {

/// The generated schema (runtime/schema/bundle.fbs) and the file header
/// (BundleFormat.h): a namespace alias, since `bundle` names variables.
namespace schema = ::sim::bundle;

using schema::Advance;
using schema::ArgKind;
using schema::Boundary;
using schema::Interp;
using schema::LaunchShape;
using schema::ParamType;
using schema::PhaseKind;
using schema::ScalarType;
using schema::Strategy;

constexpr int kNumStrategies = int(Strategy::MAX) + 1;
constexpr int kNumPhases = int(PhaseKind::MAX) + 1;

/// The fixed clock slots (the schema's ClockSlot).
constexpr int64_t kSlotBegin = int64_t(schema::ClockSlot::Begin);
constexpr int64_t kSlotSize = int64_t(schema::ClockSlot::Size);
constexpr int64_t kSlotParity = int64_t(schema::ClockSlot::Parity);
constexpr int64_t kSlotEnd = int64_t(schema::ClockSlot::End);
constexpr int64_t kSlotEstimate = int64_t(schema::ClockSlot::Estimate);
constexpr int64_t kSlotEstimateHint = int64_t(schema::ClockSlot::EstimateHint);
constexpr int64_t kSlotBigSteps = int64_t(schema::ClockSlot::BigSteps);
constexpr int64_t kSlotCuts = int64_t(schema::ClockSlot::Cuts);
constexpr int64_t kFirstFreeSlot = int64_t(schema::ClockSlot::FirstFree);

/// The most launches one phase may unroll to (repeats multiplied out).
constexpr int64_t kMaxPhaseLaunches = int64_t(1) << 22;

//===----------------------------------------------------------------------===//
// Names
//===----------------------------------------------------------------------===//

/// "simple", "traditional", "hip", "hip-cache", "lts".
const char *strategyName(Strategy strategy);
std::optional<Strategy> parseStrategy(std::string_view name);
/// "i32", "i64", "index", "f32", "f64".
const char *scalarTypeName(ScalarType type);
const char *phaseName(PhaseKind phase);
/// "linear", "cubic", "hermite", "none"; "clamp", "wrap", "zero".
const char *interpName(Interp interp);
const char *boundaryName(Boundary boundary);
/// "whole_step", "group_substeps", "grid_substeps".
const char *advanceName(Advance advance);

//===----------------------------------------------------------------------===//
// Elements and values
//===----------------------------------------------------------------------===//

/// "f32", "f64", "vector<3xf32>".
std::string elementText(const schema::Element &element);
inline bool isF64(const schema::Element &element) {
  return element.scalar() == ScalarType::F64;
}
inline int64_t scalarBytes(const schema::Element &element) {
  return isF64(element) ? 8 : 4;
}
/// Bytes of the narrowest float a buffer's or total's values derive from
/// (the compiler's precision_bytes; a bundle without it: its own type's).
inline int32_t precisionBytes(const schema::BufferT &buffer) {
  return buffer.precision_bytes ? buffer.precision_bytes
                                : int32_t(scalarBytes(*buffer.element));
}
inline int32_t precisionBytes(const schema::TotalT &total) {
  return total.precision_bytes                   ? total.precision_bytes
         : total.type == schema::ScalarType::F64 ? 8
                                                 : 4;
}
/// Bytes of one item in a host array (lanes packed, no padding).
inline int64_t packedBytes(const schema::Element &element) {
  return int64_t(element.lanes()) * scalarBytes(element);
}
inline bool operator==(const schema::Element &a, const schema::Element &b) {
  return a.scalar() == b.scalar() && a.lanes() == b.lanes();
}
inline bool operator!=(const schema::Element &a, const schema::Element &b) {
  return !(a == b);
}

/// A parameter, dt or range value of a known type.
struct Value {
  ScalarType type = ScalarType::I64;
  int64_t i = 0;
  double f = 0;

  static Value of(const schema::Value &value) {
    return {value.type(), value.int_value(), value.float_value()};
  }
  bool isFloat() const {
    return type == ScalarType::F32 || type == ScalarType::F64;
  }
  /// The value as a kernel receives it: 4 bytes for i32 and f32, else 8
  /// (index parameters travel as i64), in the low bytes of the result.
  uint64_t bits() const;
  /// Enough digits to read back exactly.
  std::string text() const;
};

/// Parses `text` as a value of `type`; throws SIM_ERROR_INVALID_ARGUMENT
/// naming `what` when it does not parse or does not fit.
Value parseValue(ScalarType type, std::string_view text,
                 const std::string &what);

//===----------------------------------------------------------------------===//
// The bundle
//===----------------------------------------------------------------------===//

struct Bundle {
  /// The file, for messages ("bundle 'x.simb': ...").
  std::string name;
  /// The CRC-32 of its header (which identifies it in checkpoints).
  uint32_t checksum = 0;
  schema::BundleT contents;

  const schema::SceneT &scene() const { return *contents.scene; }
  /// Whether the bundle's code runs with subnormals flushed to zero
  /// (sim-translate --sim-ftz).
  bool flushesSubnormals() const {
    return contents.subnormals == schema::Subnormals::FlushToZero;
  }
  /// The plan of `strategy`, or null when the bundle has none.
  const schema::PlanT *plan(Strategy strategy) const;
  /// The strategies the bundle has plans for, in its order.
  std::vector<Strategy> strategies() const;
  /// The reference model and functions, or null.
  const schema::ReferenceT *reference() const {
    return contents.reference.get();
  }
  /// The CPU code of `plan` for the highest instruction-set level this
  /// machine runs (hostIsas()), or null.
  const schema::CpuCodeT *cpuCode(const schema::PlanT &plan) const;

  /// What the C API hands out as strings: per scene buffer its element and
  /// interpolation ("hermite:<derivative>"), per parameter its default.
  std::vector<std::string> elementTexts, interpTexts, defaultTexts;

  int findParam(std::string_view name) const;

  /// Reads and verifies a file; throws SIM_ERROR_IO or SIM_ERROR_BUNDLE.
  static std::shared_ptr<const Bundle> read(const std::string &path);
  /// Verifies bytes in memory; `name` is used in messages.
  static std::shared_ptr<const Bundle> parse(const uint8_t *data, size_t size,
                                             const std::string &name);
};

/// A CRC-32 as every message writes it, "0x" and eight hex digits: the
/// bundle's and the checkpoint's alike, so that one can be compared with
/// the other.
std::string crcText(uint32_t crc);

/// The launches of `phase` in order, repeats unrolled (the verifier checked
/// that they stay below kMaxPhaseLaunches).
std::vector<const schema::LaunchT *> unrollPhase(const schema::PhaseT &phase);

/// The phase of `kind` of `plan`, or null.
const schema::PhaseT *findPhase(const schema::PlanT &plan, PhaseKind kind);

/// Checks everything about a bundle that its FlatBuffer cannot say (see
/// BundleVerifier.cpp); throws SIM_ERROR_BUNDLE with a message that names
/// the offending table.
void verifyBundle(const schema::BundleT &bundle);

/// The portable instruction-set level of this machine's architecture
/// ("x86-64", "aarch64"): what the reference functions are compiled for.
const char *hostIsa();
/// Every instruction-set level of this architecture the compiler knows
/// (sim-translate --sim-cpu-isas), most portable first.
const std::vector<std::string> &knownIsas();
/// The levels this CPU runs, best first, capped by $SIM_CPU_ISA when it is
/// set (throws SIM_ERROR_INVALID_ARGUMENT for a level it does not know).
std::vector<std::string> hostIsas();
/// Why no CPU code of `plan` runs here, and what to do, for messages.
std::string missingIsaMessage(const schema::PlanT &plan);

} // namespace sim::rt

#endif // SIM_RUNTIME_BUNDLE_H
