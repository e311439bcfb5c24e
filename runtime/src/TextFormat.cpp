//===- TextFormat.cpp - the scene and plan text sections ------------------===//
//
// Parses the two text sections of a bundle (docs/Bundle.md, "Text
// sections") into Scene and Plan, and checks what the executor relies on:
// names resolve, clock slots lie inside the clock, phases nest. Every
// error is a SIM_ERROR_BUNDLE whose message names the section and line.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>

namespace sim::rt {

//===----------------------------------------------------------------------===//
// Names and values
//===----------------------------------------------------------------------===//

const char *strategyName(Strategy strategy) {
  switch (strategy) {
  case Strategy::Simple:
    return "simple";
  case Strategy::Traditional:
    return "traditional";
  case Strategy::Hip:
    return "hip";
  case Strategy::HipCache:
    return "hip-cache";
  }
  return "?";
}

std::optional<Strategy> parseStrategy(std::string_view name) {
  for (int i = 0; i < kNumStrategies; ++i)
    if (name == strategyName(Strategy(i)))
      return Strategy(i);
  return std::nullopt;
}

const char *scalarTypeName(ScalarType type) {
  switch (type) {
  case ScalarType::I32:
    return "i32";
  case ScalarType::I64:
    return "i64";
  case ScalarType::Index:
    return "index";
  case ScalarType::F32:
    return "f32";
  case ScalarType::F64:
    return "f64";
  }
  return "?";
}

std::optional<ScalarType> parseScalarType(std::string_view name) {
  for (ScalarType type : {ScalarType::I32, ScalarType::I64, ScalarType::Index,
                          ScalarType::F32, ScalarType::F64})
    if (name == scalarTypeName(type))
      return type;
  return std::nullopt;
}

const char *phaseName(PhaseKind phase) {
  switch (phase) {
  case PhaseKind::Init:
    return "init";
  case PhaseKind::Step:
    return "step";
  case PhaseKind::Finish:
    return "finish";
  case PhaseKind::Exact:
    return "exact";
  case PhaseKind::Total:
    return "total";
  }
  return "?";
}

uint64_t Value::bits() const {
  switch (type) {
  case ScalarType::I32:
    return uint32_t(int32_t(i));
  case ScalarType::I64:
  case ScalarType::Index:
    return uint64_t(i);
  case ScalarType::F32: {
    float value = float(f);
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
  }
  case ScalarType::F64: {
    uint64_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
  }
  }
  return 0;
}

std::string Value::text() const {
  if (!isFloat())
    return std::to_string(i);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer,
                type == ScalarType::F32 ? "%.9g" : "%.17g", f);
  return buffer;
}

Value parseValue(ScalarType type, std::string_view text,
                 const std::string &what) {
  std::string copy(text);
  auto bad = [&](const char *why) {
    fail(SIM_ERROR_INVALID_ARGUMENT, what + ": '" + copy + "' " + why);
  };
  // strtoll and strtod skip leading blanks and accept an empty string; a
  // value is one token.
  if (copy.empty() || std::isspace((unsigned char)copy.front()))
    bad(("is not a " + std::string(scalarTypeName(type)) + " value").c_str());
  Value value;
  value.type = type;
  char *end = nullptr;
  errno = 0;
  if (value.isFloat()) {
    value.f = type == ScalarType::F32 ? double(std::strtof(copy.c_str(), &end))
                                      : std::strtod(copy.c_str(), &end);
    if (*end)
      bad(("is not a " + std::string(scalarTypeName(type)) + " value").c_str());
    if (errno == ERANGE && std::isinf(value.f))
      bad(("is out of range for " + std::string(scalarTypeName(type))).c_str());
    return value;
  }
  long long parsed = std::strtoll(copy.c_str(), &end, 10);
  if (*end)
    bad(("is not an integer (" + std::string(scalarTypeName(type)) + ")")
            .c_str());
  if (errno == ERANGE || (type == ScalarType::I32 &&
                          (parsed < std::numeric_limits<int32_t>::min() ||
                           parsed > std::numeric_limits<int32_t>::max())))
    bad(("is out of range for " + std::string(scalarTypeName(type))).c_str());
  value.i = parsed;
  return value;
}

std::optional<ElementType> parseElementType(std::string_view text) {
  ElementType type;
  type.text = std::string(text);
  auto scalar = [&](std::string_view name) -> bool {
    if (name == "f32")
      return type.f64 = false, true;
    if (name == "f64")
      return type.f64 = true, true;
    return false;
  };
  if (scalar(text))
    return type;
  // vector<Nxf32> or vector<Nxf64>.
  constexpr std::string_view prefix = "vector<";
  if (text.substr(0, prefix.size()) != prefix || text.back() != '>')
    return std::nullopt;
  std::string_view inner = text.substr(prefix.size());
  inner.remove_suffix(1);
  size_t x = inner.find('x');
  if (x == 0 || x == std::string_view::npos || !scalar(inner.substr(x + 1)))
    return std::nullopt;
  int64_t lanes = 0;
  for (char c : inner.substr(0, x)) {
    if (c < '0' || c > '9' || lanes > 65536)
      return std::nullopt;
    lanes = lanes * 10 + (c - '0');
  }
  if (lanes < 1 || lanes > 65536)
    return std::nullopt;
  type.lanes = int32_t(lanes);
  return type;
}

int Scene::findParam(std::string_view name) const {
  for (size_t i = 0; i < params.size(); ++i)
    if (params[i].name == name)
      return int(i);
  return -1;
}

int Scene::findBuffer(std::string_view name) const {
  for (size_t i = 0; i < buffers.size(); ++i)
    if (buffers[i].name == name)
      return int(i);
  return -1;
}

int Plan::findBuffer(std::string_view name) const {
  for (size_t i = 0; i < buffers.size(); ++i)
    if (buffers[i].name == name)
      return int(i);
  return -1;
}

int Plan::findTotal(std::string_view name) const {
  for (size_t i = 0; i < totals.size(); ++i)
    if (totals[i].name == name)
      return int(i);
  return -1;
}

std::vector<std::string> Plan::kernelNames() const {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const std::vector<Launch> &launches : phases)
    for (const Launch &launch : launches)
      if (seen.insert(launch.kernel).second)
        names.push_back(launch.kernel);
  return names;
}

//===----------------------------------------------------------------------===//
// Lines and fields
//===----------------------------------------------------------------------===//

namespace {

/// The records of a text section: lines split into fields, without blank
/// lines and comments, each remembering its line number for messages.
class Records {
public:
  Records(std::string_view text, std::string section)
      : text(text), section(std::move(section)) {
    // A writer may NUL-terminate text sections like the PTX.
    while (!this->text.empty() && this->text.back() == '\0')
      this->text.remove_suffix(1);
  }

  /// Advances to the next record; false at the end.
  bool next() {
    while (position < text.size() || (position == text.size() && !done)) {
      size_t end = text.find('\n', position);
      if (end == std::string_view::npos) {
        end = text.size();
        done = true;
      }
      std::string_view line = text.substr(position, end - position);
      position = end + 1;
      ++lineNumber;
      if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
      if (line.find('\0') != std::string_view::npos)
        error("contains a NUL character");
      fields.clear();
      size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
          ++i;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
          ++i;
        if (i > start)
          fields.push_back(line.substr(start, i - start));
      }
      if (fields.empty() || fields.front().front() == '#')
        continue;
      return true;
    }
    return false;
  }

  size_t size() const { return fields.size(); }
  std::string_view operator[](size_t i) const { return fields[i]; }
  std::string str(size_t i) const { return std::string(fields[i]); }

  [[noreturn]] void error(const std::string &message) const {
    fail(SIM_ERROR_BUNDLE,
         section + ", line " + std::to_string(lineNumber) + ": " + message);
  }

  /// Requires `fields[i] == keyword`.
  void expect(size_t i, std::string_view keyword) const {
    if (i >= fields.size())
      error("expected '" + std::string(keyword) + "' after '" +
            std::string(fields.back()) + "'");
    if (fields[i] != keyword)
      error("expected '" + std::string(keyword) + "', found '" +
            std::string(fields[i]) + "'");
  }
  void expectCount(size_t count, const char *syntax) const {
    if (fields.size() != count)
      error("expected '" + std::string(syntax) + "'");
  }
  void expectAtLeast(size_t count, const char *syntax) const {
    if (fields.size() < count)
      error("expected '" + std::string(syntax) + "'");
  }

  /// An integer field in [min, max].
  int64_t integer(size_t i, const char *what, int64_t min = 0,
                  int64_t max = std::numeric_limits<int64_t>::max()) const {
    std::string field = str(i);
    char *end = nullptr;
    errno = 0;
    long long value = std::strtoll(field.c_str(), &end, 10);
    if (field.empty() || *end || errno == ERANGE ||
        !(field[0] == '-' || (field[0] >= '0' && field[0] <= '9')))
      error(std::string(what) + " '" + field + "' is not an integer");
    if (value < min || value > max)
      error(std::string(what) + " " + field + " is out of range [" +
            std::to_string(min) + ", " + std::to_string(max) + "]");
    return value;
  }

  std::string_view text;
  std::string section;
  size_t position = 0;
  bool done = false;
  int lineNumber = 0;
  std::vector<std::string_view> fields;
};

/// The name a `kind:<name>` argument or `hermite:<name>` carries.
std::optional<std::string_view> afterPrefix(std::string_view field,
                                            std::string_view prefix) {
  if (field.size() > prefix.size() && field.substr(0, prefix.size()) == prefix)
    return field.substr(prefix.size());
  return std::nullopt;
}

/// The `observed` and `exact` flags of a scene or model `buffer` record,
/// from field `first` on, each at most once.
void parseBufferFlags(Records &records, size_t first, bool &observed,
                      bool &exact) {
  for (size_t i = first; i < records.size(); ++i) {
    bool *flag = records[i] == "observed" ? &observed
                 : records[i] == "exact"  ? &exact
                                          : nullptr;
    if (!flag)
      records.error("unknown buffer flag '" + records.str(i) + "'");
    if (*flag)
      records.error("buffer flag '" + records.str(i) + "' is repeated");
    *flag = true;
  }
}

/// The element type in field `typeField` of a plan or model `buffer` record
/// that names buffer `name`, which must be a buffer of `scene` with the same
/// element type.
ElementType sceneBufferType(Records &records, const Scene &scene,
                            const std::string &name, size_t typeField) {
  int sceneBuffer = scene.findBuffer(name);
  if (sceneBuffer < 0)
    records.error("buffer '" + name + "' is not a buffer of scene '" +
                  scene.name + "'");
  std::optional<ElementType> type = parseElementType(records[typeField]);
  if (!type)
    records.error("element type '" + records.str(typeField) +
                  "' is not f32, f64, vector<Nxf32> or vector<Nxf64>");
  if (!(*type == scene.buffers[sceneBuffer].type))
    records.error("buffer '" + name + "' has element type " +
                  records.str(typeField) + " but the scene says " +
                  scene.buffers[sceneBuffer].type.text);
  return *type;
}

} // namespace

//===----------------------------------------------------------------------===//
// Scene
//===----------------------------------------------------------------------===//

Scene parseScene(std::string_view text) {
  Records records(text, "scene section");
  Scene scene;
  bool header = false, strategies = false;
  while (records.next()) {
    std::string_view record = records[0];
    if (record != "scene" && !header)
      records.error("expected the 'scene' record first, found '" +
                    std::string(record) + "'");
    if (record == "scene") {
      if (header)
        records.error("a second 'scene' record");
      const char *syntax =
          "scene <name> range <n> dt <f32|f64> <value> max_steps <n>";
      records.expectCount(9, syntax);
      records.expect(2, "range");
      records.expect(4, "dt");
      records.expect(7, "max_steps");
      scene.name = records.str(1);
      scene.range = records.integer(3, "range", 1);
      std::optional<ScalarType> dtType = parseScalarType(records[5]);
      if (!dtType || (*dtType != ScalarType::F32 && *dtType != ScalarType::F64))
        records.error("dt type '" + records.str(5) + "' is not f32 or f64");
      try {
        scene.dt = parseValue(*dtType, records[6], "dt");
      } catch (const Error &error) {
        records.error(error.what());
      }
      scene.maxSteps = records.integer(8, "max_steps", 1, 1 << 20);
      header = true;
    } else if (record == "param") {
      records.expectCount(4, "param <name> <i32|i64|index|f32|f64> <default>");
      SceneParam param;
      param.name = records.str(1);
      if (param.name == "range" || param.name == "dt")
        records.error("a parameter named '" + param.name +
                      "' clashes with the scene's " + param.name);
      if (scene.findParam(param.name) >= 0)
        records.error("parameter '" + param.name + "' is declared twice");
      std::optional<ScalarType> type = parseScalarType(records[2]);
      if (!type)
        records.error("parameter type '" + records.str(2) +
                      "' is not one of i32, i64, index, f32, f64");
      param.type = *type;
      param.defaultText = records.str(3);
      try {
        param.defaultValue =
            parseValue(*type, records[3], "parameter '" + param.name + "'");
      } catch (const Error &error) {
        records.error(error.what());
      }
      scene.params.push_back(std::move(param));
    } else if (record == "buffer") {
      const char *syntax = "buffer <name> <element type> interp <interp> "
                           "boundary <boundary> [observed] [exact]";
      records.expectAtLeast(7, syntax);
      records.expect(3, "interp");
      records.expect(5, "boundary");
      SceneBuffer buffer;
      buffer.name = records.str(1);
      if (scene.findBuffer(buffer.name) >= 0)
        records.error("buffer '" + buffer.name + "' is declared twice");
      std::optional<ElementType> type = parseElementType(records[2]);
      if (!type)
        records.error("element type '" + records.str(2) +
                      "' is not f32, f64, vector<Nxf32> or vector<Nxf64>");
      buffer.type = *type;
      buffer.interp = records.str(4);
      std::optional<std::string_view> derivative =
          afterPrefix(records[4], "hermite:");
      if (buffer.interp != "linear" && buffer.interp != "cubic" &&
          buffer.interp != "none" && !derivative)
        records.error("interpolation '" + buffer.interp +
                      "' is not linear, cubic, hermite:<buffer> or none");
      buffer.boundary = records.str(6);
      if (buffer.boundary != "clamp" && buffer.boundary != "wrap" &&
          buffer.boundary != "zero")
        records.error("boundary '" + buffer.boundary +
                      "' is not clamp, wrap or zero");
      parseBufferFlags(records, 7, buffer.observed, buffer.exact);
      scene.buffers.push_back(std::move(buffer));
    } else if (record == "strategies") {
      if (strategies)
        records.error("a second 'strategies' record");
      records.expectAtLeast(2, "strategies <strategy>...");
      for (size_t i = 1; i < records.size(); ++i) {
        std::optional<Strategy> strategy = parseStrategy(records[i]);
        if (!strategy)
          records.error("unknown strategy '" + records.str(i) + "'");
        for (Strategy seen : scene.strategies)
          if (seen == *strategy)
            records.error("strategy '" + records.str(i) + "' is repeated");
        scene.strategies.push_back(*strategy);
      }
      strategies = true;
    } else {
      records.error("unknown record '" + std::string(record) + "'");
    }
  }
  if (!header)
    fail(SIM_ERROR_BUNDLE, "scene section: no 'scene' record");
  if (!strategies)
    fail(SIM_ERROR_BUNDLE, "scene section: no 'strategies' record");
  // Hermite interpolation names a derivative buffer of the scene.
  for (const SceneBuffer &buffer : scene.buffers)
    if (std::optional<std::string_view> derivative =
            afterPrefix(buffer.interp, "hermite:"))
      if (scene.findBuffer(*derivative) < 0)
        fail(SIM_ERROR_BUNDLE, "scene section: buffer '" + buffer.name +
                                   "' interpolates with the derivative '" +
                                   std::string(*derivative) +
                                   "', which is not a buffer");
  return scene;
}

//===----------------------------------------------------------------------===//
// Plan
//===----------------------------------------------------------------------===//

namespace {

/// Unrolled launches per phase are bounded so that a hostile `repeat`
/// cannot exhaust memory.
constexpr size_t kMaxLaunchesPerPhase = 1 << 20;

/// An open `phase` or `repeat` while parsing.
struct Block {
  std::vector<Launch> launches;
  int64_t repeat = 1;
};

} // namespace

Plan parsePlan(std::string_view text, const Scene &scene, Strategy strategy) {
  Records records(text, std::string("plan section of strategy ") +
                            strategyName(strategy));
  Plan plan;
  plan.strategy = strategy;
  bool header = false;
  std::vector<Block> open;
  PhaseKind phase = PhaseKind::Init;

  while (records.next()) {
    std::string_view record = records[0];
    if (!header && record != "plan")
      records.error("expected the 'plan' record first, found '" +
                    std::string(record) + "'");
    bool inPhase = !open.empty();
    if (inPhase && record != "launch" && record != "repeat" && record != "end")
      records.error("'" + std::string(record) + "' inside phase '" +
                    phaseName(phase) + "' (missing 'end'?)");

    if (record == "plan") {
      if (header)
        records.error("a second 'plan' record");
      const char *syntax = "plan <strategy> group_size <n> clock_slots <n> "
                           "histogram <slot>";
      records.expectCount(8, syntax);
      records.expect(2, "group_size");
      records.expect(4, "clock_slots");
      records.expect(6, "histogram");
      std::optional<Strategy> named = parseStrategy(records[1]);
      if (!named)
        records.error("unknown strategy '" + records.str(1) + "'");
      if (*named != strategy)
        records.error("the plan is for strategy '" + records.str(1) +
                      "' but its section is for '" + strategyName(strategy) +
                      "'");
      plan.groupSize = records.integer(3, "group_size", 1, 1 << 20);
      plan.clockSlots =
          records.integer(5, "clock_slots", kFirstFreeSlot, 1 << 20);
      // Slots histogram + m for m in 1..max_steps must lie in the clock.
      plan.histogramSlot =
          records.integer(7, "histogram slot", kFirstFreeSlot,
                          plan.clockSlots - 1 - scene.maxSteps);
      header = true;
    } else if (record == "buffer") {
      const char *syntax = "buffer <name> <element type> stride <bytes> "
                           "[snapshot] [observed] [exact]";
      records.expectAtLeast(5, syntax);
      records.expect(3, "stride");
      PlanBuffer buffer;
      buffer.name = records.str(1);
      if (plan.findBuffer(buffer.name) >= 0)
        records.error("buffer '" + buffer.name + "' is declared twice");
      buffer.type = sceneBufferType(records, scene, buffer.name, 2);
      buffer.stride =
          records.integer(4, "stride", buffer.type.packedBytes(), 1 << 20);
      for (size_t i = 5; i < records.size(); ++i) {
        bool *flag = records[i] == "snapshot"   ? &buffer.snapshot
                     : records[i] == "observed" ? &buffer.observed
                     : records[i] == "exact"    ? &buffer.exact
                                                : nullptr;
        if (!flag)
          records.error("unknown buffer flag '" + records.str(i) + "'");
        if (*flag)
          records.error("buffer flag '" + records.str(i) + "' is repeated");
        *flag = true;
      }
      plan.buffers.push_back(std::move(buffer));
    } else if (record == "component") {
      records.expectAtLeast(
          5, "component <name> evaluations <slot> writes <B>...");
      records.expect(2, "evaluations");
      records.expect(4, "writes");
      PlanComponent component;
      component.name = records.str(1);
      for (const PlanComponent &other : plan.components)
        if (other.name == component.name)
          records.error("component '" + component.name + "' is declared twice");
      component.evaluationSlot = records.integer(
          3, "evaluations slot", kFirstFreeSlot, plan.clockSlots - 1);
      for (size_t i = 5; i < records.size(); ++i) {
        int buffer = plan.findBuffer(records[i]);
        if (buffer < 0)
          records.error("component '" + component.name + "' writes '" +
                        records.str(i) + "', which is not a plan buffer");
        component.writes.push_back(buffer);
      }
      plan.components.push_back(std::move(component));
    } else if (record == "total") {
      records.expectCount(3, "total <name> <f32|f64>");
      PlanTotal total;
      total.name = records.str(1);
      if (plan.findTotal(total.name) >= 0)
        records.error("total '" + total.name + "' is declared twice");
      std::optional<ScalarType> type = parseScalarType(records[2]);
      if (!type || (*type != ScalarType::F32 && *type != ScalarType::F64))
        records.error("total type '" + records.str(2) + "' is not f32 or f64");
      total.type = *type;
      plan.totals.push_back(std::move(total));
    } else if (record == "phase") {
      records.expectCount(2, "phase <init|step|finish|exact|total>");
      std::optional<PhaseKind> kind;
      for (int i = 0; i < kNumPhases; ++i)
        if (records[1] == phaseName(PhaseKind(i)))
          kind = PhaseKind(i);
      if (!kind)
        records.error("unknown phase '" + records.str(1) + "'");
      if (plan.hasPhase[int(*kind)])
        records.error("phase '" + records.str(1) + "' is repeated");
      phase = *kind;
      plan.hasPhase[int(phase)] = true;
      open.emplace_back();
    } else if (record == "repeat") {
      if (!inPhase)
        records.error("'repeat' outside a phase");
      records.expectCount(2, "repeat <count>");
      open.emplace_back();
      open.back().repeat = records.integer(1, "repeat count", 0, 1 << 20);
    } else if (record == "end") {
      if (!inPhase)
        records.error("'end' without an open phase or repeat");
      records.expectCount(1, "end");
      Block block = std::move(open.back());
      open.pop_back();
      std::vector<Launch> &into =
          open.empty() ? plan.phases[int(phase)] : open.back().launches;
      if (block.launches.size() * uint64_t(block.repeat) + into.size() >
          kMaxLaunchesPerPhase)
        records.error("phase '" + std::string(phaseName(phase)) +
                      "' unrolls to more than " +
                      std::to_string(kMaxLaunchesPerPhase) + " launches");
      for (int64_t i = 0; i < block.repeat; ++i)
        into.insert(into.end(), block.launches.begin(), block.launches.end());
    } else if (record == "launch") {
      if (!inPhase)
        records.error("'launch' outside a phase");
      const char *syntax = "launch <kernel> <items|single> for <component|-> "
                           "shared <per_thread> <fixed> args <arg>...";
      records.expectAtLeast(8, syntax);
      records.expect(3, "for");
      records.expect(5, "shared");
      records.expect(8, "args");
      Launch launch;
      launch.kernel = records.str(1);
      if (records[2] != "items" && records[2] != "single")
        records.error("launch shape '" + records.str(2) +
                      "' is not items or single");
      launch.single = records[2] == "single";
      if (records[4] != "-") {
        for (size_t i = 0; i < plan.components.size(); ++i)
          if (plan.components[i].name == records[4])
            launch.component = int32_t(i);
        if (launch.component < 0)
          records.error("launch of '" + launch.kernel + "' is for '" +
                        records.str(4) + "', which is not a plan component");
      }
      launch.sharedPerThread =
          records.integer(6, "shared bytes per thread", 0, 1 << 20);
      launch.sharedFixed = records.integer(7, "fixed shared bytes", 0, 1 << 30);
      for (size_t i = 9; i < records.size(); ++i) {
        std::string_view field = records[i];
        Arg arg;
        auto bufferArg = [&](std::string_view name, ArgKind kind) {
          arg.kind = kind;
          arg.index = plan.findBuffer(name);
          if (arg.index < 0)
            records.error("argument '" + std::string(field) +
                          "' names no plan buffer");
          const PlanBuffer &buffer = plan.buffers[arg.index];
          if (kind == ArgKind::Snapshot && !buffer.snapshot)
            records.error("argument '" + std::string(field) + "': buffer '" +
                          buffer.name + "' has no snapshot");
          if (kind == ArgKind::Exact && !buffer.exact)
            records.error("argument '" + std::string(field) + "': buffer '" +
                          buffer.name + "' has no exact solution");
        };
        if (field == "clock") {
          arg.kind = ArgKind::Clock;
        } else if (field == "range") {
          arg.kind = ArgKind::Range;
        } else if (field == "dt") {
          arg.kind = ArgKind::Dt;
        } else if (field == "time") {
          arg.kind = ArgKind::Time;
        } else if (auto name = afterPrefix(field, "buffer:")) {
          bufferArg(*name, ArgKind::Buffer);
        } else if (auto name = afterPrefix(field, "snapshot:")) {
          bufferArg(*name, ArgKind::Snapshot);
        } else if (auto name = afterPrefix(field, "exact:")) {
          bufferArg(*name, ArgKind::Exact);
        } else if (auto name = afterPrefix(field, "total:")) {
          arg.kind = ArgKind::Total;
          arg.index = plan.findTotal(*name);
          if (arg.index < 0)
            records.error("argument '" + std::string(field) +
                          "' names no plan total");
        } else if (auto name = afterPrefix(field, "param:")) {
          arg.kind = ArgKind::Param;
          arg.index = scene.findParam(*name);
          if (arg.index < 0)
            records.error("argument '" + std::string(field) +
                          "' names no parameter of scene '" + scene.name + "'");
        } else {
          records.error("unknown argument '" + std::string(field) + "'");
        }
        launch.args.push_back(arg);
      }
      open.back().launches.push_back(std::move(launch));
    } else {
      records.error("unknown record '" + std::string(record) + "'");
    }
  }

  std::string section = records.section;
  if (!header)
    fail(SIM_ERROR_BUNDLE, section + ": no 'plan' record");
  if (!open.empty())
    fail(SIM_ERROR_BUNDLE, section + ": phase '" + phaseName(phase) +
                               "' is not closed with 'end'");
  for (PhaseKind required :
       {PhaseKind::Init, PhaseKind::Step, PhaseKind::Finish})
    if (!plan.hasPhase[int(required)])
      fail(SIM_ERROR_BUNDLE,
           section + ": no '" + phaseName(required) + "' phase");
  if (plan.phase(PhaseKind::Step).empty())
    fail(SIM_ERROR_BUNDLE, section + ": the 'step' phase launches nothing");
  return plan;
}

//===----------------------------------------------------------------------===//
// Reference model
//===----------------------------------------------------------------------===//

int ReferenceModel::findBuffer(std::string_view name) const {
  for (size_t i = 0; i < buffers.size(); ++i)
    if (buffers[i].name == name)
      return int(i);
  return -1;
}

int ReferenceModel::findComponent(std::string_view name) const {
  for (size_t i = 0; i < components.size(); ++i)
    if (components[i].name == name)
      return int(i);
  return -1;
}

ReferenceModel parseReferenceModel(std::string_view text, const Scene &scene) {
  Records records(text, "reference model section");
  ReferenceModel model;
  bool header = false, schedule = false;
  // Hermite derivatives may name a buffer declared later: resolved at the
  // end, with the line that named them.
  struct Derivative {
    int32_t buffer;
    std::string name;
    int line;
  };
  std::vector<Derivative> derivatives;
  // Indices are positions: the callbacks and symbol names use them.
  auto index = [&](size_t count, const char *what) {
    int64_t value = records.integer(1, what, 0, 1 << 30);
    if (value != int64_t(count))
      records.error(std::string(what) + " " + records.str(1) +
                    " is out of order (expected " + std::to_string(count) +
                    ": indices count 0, 1, ... in the order of the lines)");
  };
  auto buffer = [&](size_t i, const std::string &what) {
    int found = model.findBuffer(records[i]);
    if (found < 0)
      records.error(what + " '" + records.str(i) +
                    "', which is not a buffer declared before it");
    return int32_t(found);
  };

  while (records.next()) {
    std::string_view record = records[0];
    if (!header && record != "reference")
      records.error("expected the 'reference' record first, found '" +
                    std::string(record) + "'");
    if (schedule)
      records.error("'" + std::string(record) +
                    "' after 'schedule', which comes last");
    if (record == "reference") {
      if (header)
        records.error("a second 'reference' record");
      records.expectCount(2, "reference <scene>");
      model.scene = records.str(1);
      if (model.scene != scene.name)
        records.error("the model is of scene '" + model.scene +
                      "' but the bundle's scene is '" + scene.name + "'");
      header = true;
    } else if (record == "param") {
      records.expectCount(4, "param <index> <name> <i32|i64|index|f32|f64>");
      index(model.params.size(), "param index");
      RefParam param;
      param.name = records.str(2);
      for (const RefParam &other : model.params)
        if (other.name == param.name)
          records.error("parameter '" + param.name + "' is declared twice");
      std::optional<ScalarType> type = parseScalarType(records[3]);
      if (!type)
        records.error("parameter type '" + records.str(3) +
                      "' is not one of i32, i64, index, f32, f64");
      param.type = *type;
      param.sceneParam = scene.findParam(param.name);
      if (param.sceneParam < 0)
        records.error("parameter '" + param.name +
                      "' is not a parameter of scene '" + scene.name + "'");
      if (scene.params[param.sceneParam].type != param.type)
        records.error("parameter '" + param.name + "' has type " +
                      records.str(3) + " but the scene says " +
                      scalarTypeName(scene.params[param.sceneParam].type));
      model.params.push_back(std::move(param));
    } else if (record == "buffer") {
      const char *syntax = "buffer <index> <name> <element type> interp "
                           "<interp> boundary <boundary> [observed] [exact]";
      records.expectAtLeast(8, syntax);
      index(model.buffers.size(), "buffer index");
      records.expect(4, "interp");
      records.expect(6, "boundary");
      RefBuffer buffer;
      buffer.name = records.str(2);
      if (model.findBuffer(buffer.name) >= 0)
        records.error("buffer '" + buffer.name + "' is declared twice");
      buffer.type = sceneBufferType(records, scene, buffer.name, 3);
      std::string_view interp = records[5];
      if (interp == "linear") {
        buffer.interp = Interp::Linear;
      } else if (interp == "cubic") {
        buffer.interp = Interp::Cubic;
      } else if (interp == "none") {
        buffer.interp = Interp::None;
      } else if (auto derivative = afterPrefix(interp, "hermite:")) {
        buffer.interp = Interp::Hermite;
        derivatives.push_back({int32_t(model.buffers.size()),
                               std::string(*derivative), records.lineNumber});
      } else {
        records.error("interpolation '" + records.str(5) +
                      "' is not linear, cubic, hermite:<buffer> or none");
      }
      std::string_view boundary = records[7];
      if (boundary == "clamp")
        buffer.boundary = Boundary::Clamp;
      else if (boundary == "wrap")
        buffer.boundary = Boundary::Wrap;
      else if (boundary == "zero")
        buffer.boundary = Boundary::Zero;
      else
        records.error("boundary '" + records.str(7) +
                      "' is not clamp, wrap or zero");
      parseBufferFlags(records, 8, buffer.observed, buffer.exact);
      model.buffers.push_back(std::move(buffer));
    } else if (record == "component") {
      const char *syntax = "component <index> <name> substep "
                           "<in_kernel|grid_sync> [num_steps] writes <B>... "
                           "reads <B>...";
      records.expectAtLeast(7, syntax);
      index(model.components.size(), "component index");
      records.expect(3, "substep");
      RefComponent component;
      component.name = records.str(2);
      if (model.findComponent(component.name) >= 0)
        records.error("component '" + component.name + "' is declared twice");
      if (records[4] != "in_kernel" && records[4] != "grid_sync")
        records.error("substep '" + records.str(4) +
                      "' is not in_kernel or grid_sync");
      component.gridSync = records[4] == "grid_sync";
      size_t at = 5;
      if (records[at] == "num_steps") {
        component.numSteps = true;
        ++at;
      }
      records.expect(at, "writes");
      size_t reads = at + 1;
      while (reads < records.size() && records[reads] != "reads")
        ++reads;
      if (reads == records.size())
        records.error("expected 'reads' (possibly followed by nothing) after "
                      "the buffers the component writes");
      if (reads == at + 1)
        records.error("component '" + component.name + "' writes no buffer");
      int32_t self = int32_t(model.components.size());
      for (size_t i = at + 1; i < reads; ++i) {
        int32_t written =
            buffer(i, "component '" + component.name + "' writes");
        RefBuffer &target = model.buffers[written];
        if (target.writer >= 0)
          records.error("buffer '" + target.name + "' is written by both '" +
                        model.components[target.writer].name + "' and '" +
                        component.name + "'");
        target.writer = self;
        component.writes.push_back(written);
      }
      for (size_t i = reads + 1; i < records.size(); ++i) {
        int32_t read = buffer(i, "component '" + component.name + "' reads");
        for (int32_t seen : component.reads)
          if (seen == read)
            records.error("component '" + component.name + "' lists '" +
                          records.str(i) + "' twice in 'reads'");
        component.reads.push_back(read);
      }
      model.components.push_back(std::move(component));
    } else if (record == "total") {
      const char *syntax = "total <index> <name> <f32|f64> reads <B>...";
      records.expectAtLeast(5, syntax);
      index(model.totals.size(), "total index");
      records.expect(4, "reads");
      RefTotal total;
      total.name = records.str(2);
      for (const RefTotal &other : model.totals)
        if (other.name == total.name)
          records.error("total '" + total.name + "' is declared twice");
      std::optional<ScalarType> type = parseScalarType(records[3]);
      if (!type || (*type != ScalarType::F32 && *type != ScalarType::F64))
        records.error("total type '" + records.str(3) + "' is not f32 or f64");
      total.type = *type;
      for (size_t i = 5; i < records.size(); ++i)
        total.reads.push_back(buffer(i, "total '" + total.name + "' reads"));
      model.totals.push_back(std::move(total));
    } else if (record == "schedule") {
      records.expectAtLeast(1, "schedule <component>...");
      for (size_t i = 1; i < records.size(); ++i) {
        int found = model.findComponent(records[i]);
        if (found < 0)
          records.error("schedule names '" + records.str(i) +
                        "', which is not a component");
        RefComponent &component = model.components[found];
        if (component.position >= 0)
          records.error("schedule names '" + component.name + "' twice");
        component.position = int32_t(model.schedule.size());
        model.schedule.push_back(found);
      }
      for (const RefComponent &component : model.components)
        if (component.position < 0)
          records.error("component '" + component.name +
                        "' is not in the schedule");
      schedule = true;
    } else {
      records.error("unknown record '" + std::string(record) + "'");
    }
  }

  const std::string section = records.section;
  if (!header)
    fail(SIM_ERROR_BUNDLE, section + ": no 'reference' record");
  if (!schedule)
    fail(SIM_ERROR_BUNDLE, section + ": no 'schedule' record");
  for (const Derivative &derivative : derivatives) {
    std::string where = section + ", line " + std::to_string(derivative.line) +
                        ": buffer '" + model.buffers[derivative.buffer].name +
                        "' interpolates with the derivative '" +
                        derivative.name + "'";
    int found = model.findBuffer(derivative.name);
    if (found < 0)
      fail(SIM_ERROR_BUNDLE, where + ", which is not a buffer of the model");
    if (!(model.buffers[found].type == model.buffers[derivative.buffer].type))
      fail(SIM_ERROR_BUNDLE,
           where + ", whose element type " + model.buffers[found].type.text +
               " differs from " + model.buffers[derivative.buffer].type.text);
    model.buffers[derivative.buffer].derivative = int32_t(found);
  }
  return model;
}

} // namespace sim::rt
