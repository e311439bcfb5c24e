//===- Bundle.h - a scene bundle in memory ------------------------*- C++
//-*-===//
//
// The contents of a `.simb` file (docs/Bundle.md) as C++ structures: the
// scene's metadata, and per strategy the host plan (docs/Plan.md), the PTX
// text and the CPU shared object. Reading validates everything the format
// specifies, so the executor can trust indices and slots without checking
// them again.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_BUNDLE_H
#define SIM_RUNTIME_BUNDLE_H

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sim::rt {

//===----------------------------------------------------------------------===//
// Scalars and values
//===----------------------------------------------------------------------===//

/// The strategies, numbered as in the section table.
enum class Strategy : uint32_t {
  Simple = 0,
  Traditional = 1,
  Hip = 2,
  HipCache = 3
};
constexpr int kNumStrategies = 4;
const char *strategyName(Strategy strategy);
std::optional<Strategy> parseStrategy(std::string_view name);

/// Types of parameters and of dt.
enum class ScalarType { I32, I64, Index, F32, F64 };
const char *scalarTypeName(ScalarType type);
std::optional<ScalarType> parseScalarType(std::string_view name);

/// A parameter, dt or range value of a known type.
struct Value {
  ScalarType type = ScalarType::I64;
  int64_t i = 0;
  double f = 0;

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

/// A buffer element: a float scalar or a vector of them.
struct ElementType {
  std::string text;
  bool f64 = false;
  int32_t lanes = 1;

  int32_t scalarBytes() const { return f64 ? 8 : 4; }
  /// Bytes of one item in a host array (lanes packed, no padding).
  int64_t packedBytes() const { return int64_t(lanes) * scalarBytes(); }
  bool operator==(const ElementType &other) const {
    return f64 == other.f64 && lanes == other.lanes;
  }
};
std::optional<ElementType> parseElementType(std::string_view text);

//===----------------------------------------------------------------------===//
// Scene
//===----------------------------------------------------------------------===//

struct SceneParam {
  std::string name;
  ScalarType type;
  Value defaultValue;
  std::string defaultText;
};

struct SceneBuffer {
  std::string name;
  ElementType type;
  std::string interp;
  std::string boundary;
  bool observed = false;
  bool exact = false;
};

struct Scene {
  std::string name;
  int64_t range = 0;
  Value dt;
  int64_t maxSteps = 0;
  std::vector<SceneParam> params;
  std::vector<SceneBuffer> buffers;
  std::vector<Strategy> strategies;

  int findParam(std::string_view name) const;
  int findBuffer(std::string_view name) const;
};

/// Parses the text of a scene section; errors name the line.
Scene parseScene(std::string_view text);

//===----------------------------------------------------------------------===//
// Plan
//===----------------------------------------------------------------------===//

enum class ArgKind {
  Clock,
  Buffer,
  Snapshot,
  Exact,
  Param,
  Range,
  Dt,
  Time,
  Total
};

struct Arg {
  ArgKind kind;
  /// The plan buffer (Buffer, Snapshot, Exact), scene parameter (Param) or
  /// plan total (Total).
  int32_t index = -1;
};

struct Launch {
  std::string kernel;
  bool single = false;
  /// The plan component whose buffers the launch writes, or -1.
  int32_t component = -1;
  int64_t sharedPerThread = 0;
  int64_t sharedFixed = 0;
  std::vector<Arg> args;
};

struct PlanBuffer {
  std::string name;
  ElementType type;
  int64_t stride = 0;
  bool snapshot = false;
  bool observed = false;
  bool exact = false;
};

struct PlanComponent {
  std::string name;
  int64_t evaluationSlot = 0;
  std::vector<int32_t> writes;
};

/// A `total` record: a sum over items the scene observes. The `total` phase
/// writes its per-item values as doubles; the runtime sums them.
struct PlanTotal {
  std::string name;
  /// The type the scene declared (f32 or f64).
  ScalarType type = ScalarType::F64;
};

enum class PhaseKind { Init = 0, Step = 1, Finish = 2, Exact = 3, Total = 4 };
constexpr int kNumPhases = 5;
const char *phaseName(PhaseKind phase);

struct Plan {
  Strategy strategy = Strategy::Simple;
  int64_t groupSize = 0;
  int64_t clockSlots = 0;
  int64_t histogramSlot = 0;
  std::vector<PlanBuffer> buffers;
  std::vector<PlanComponent> components;
  std::vector<PlanTotal> totals;
  /// The launches of each phase in order, `repeat` blocks unrolled.
  std::array<std::vector<Launch>, kNumPhases> phases;
  std::array<bool, kNumPhases> hasPhase = {};

  const std::vector<Launch> &phase(PhaseKind kind) const {
    return phases[int(kind)];
  }
  int findBuffer(std::string_view name) const;
  int findTotal(std::string_view name) const;
  /// Every kernel some phase launches, each once.
  std::vector<std::string> kernelNames() const;
};

/// The fixed clock slots (docs/Plan.md).
enum ClockSlot : int64_t {
  kSlotBegin = 0,
  kSlotSize = 1,
  kSlotParity = 2,
  kSlotEnd = 3,
  kSlotEstimate = 4,
  kSlotBigSteps = 5,
  kFirstFreeSlot = 8,
};

/// Parses the text of the plan section of `strategy`, resolving names
/// against the scene; errors name the line.
Plan parsePlan(std::string_view text, const Scene &scene, Strategy strategy);

//===----------------------------------------------------------------------===//
// Reference model
//===----------------------------------------------------------------------===//

enum class Interp { Linear, Cubic, Hermite, None };
enum class Boundary { Clamp, Wrap, Zero };

/// A `param` line: what index `i` of the `param` callback means.
struct RefParam {
  std::string name;
  ScalarType type;
  /// The scene parameter of that name (same type).
  int32_t sceneParam = -1;
};

struct RefBuffer {
  std::string name;
  ElementType type;
  Interp interp = Interp::Linear;
  /// The buffer `hermite:<derivative>` names, or -1.
  int32_t derivative = -1;
  Boundary boundary = Boundary::Clamp;
  bool observed = false;
  bool exact = false;
  /// The component that writes the buffer, or -1 (it keeps its initial
  /// state).
  int32_t writer = -1;
};

/// A `total` line: what `sim_ref_total_<index>` computes.
struct RefTotal {
  std::string name;
  ScalarType type = ScalarType::F64;
  std::vector<int32_t> reads;
};

struct RefComponent {
  std::string name;
  /// `substep grid_sync`: sub-steps over the whole range at once.
  bool gridSync = false;
  bool numSteps = false;
  std::vector<int32_t> writes, reads;
  /// The component's place in `schedule`.
  int32_t position = -1;
};

/// The text of the reference model section (docs/Reference.md).
struct ReferenceModel {
  std::string scene;
  std::vector<RefParam> params;
  std::vector<RefBuffer> buffers;
  std::vector<RefComponent> components;
  std::vector<RefTotal> totals;
  /// Components in the order they run.
  std::vector<int32_t> schedule;

  int findBuffer(std::string_view name) const;
  int findComponent(std::string_view name) const;
};

/// Parses the text of the reference model section, resolving names against
/// the scene; errors name the line.
ReferenceModel parseReferenceModel(std::string_view text, const Scene &scene);

//===----------------------------------------------------------------------===//
// Bundle
//===----------------------------------------------------------------------===//

/// The section kinds of the table.
enum class SectionKind : uint32_t {
  Scene = 1,
  Plan = 2,
  Ptx = 3,
  Cpu = 4,
  ReferenceModel = 5,
  ReferenceObject = 6
};

struct Bundle {
  /// The file, for messages ("bundle 'x.simb': ...").
  std::string name;
  Scene scene;
  struct StrategyCode {
    bool present = false;
    Plan plan;
    std::optional<std::string> ptx;
    std::optional<std::vector<uint8_t>> cpu;
  };
  std::array<StrategyCode, kNumStrategies> strategies;
  /// The reference sections (kinds 5 and 6): both or neither.
  std::optional<ReferenceModel> reference;
  std::optional<std::vector<uint8_t>> referenceObject;

  const StrategyCode &code(Strategy strategy) const {
    return strategies[uint32_t(strategy)];
  }

  /// Reads and validates a file; throws SIM_ERROR_IO or SIM_ERROR_BUNDLE.
  static std::shared_ptr<const Bundle> read(const std::string &path);
  /// Validates bytes in memory; `name` is used in messages.
  static std::shared_ptr<const Bundle> parse(const uint8_t *data, size_t size,
                                             const std::string &name);
};

} // namespace sim::rt

#endif // SIM_RUNTIME_BUNDLE_H
