//===- Bundle.cpp - reading a .simb file ----------------------------------===//
//
// The checks before anything of a bundle is used, outermost first: the file
// (a regular file of at most kMaxBundleBytes, read whole), the header
// (BundleFormat.h: magic, version, size, reserved bits), the CRC-32 of the
// rest, the FlatBuffer (FlatBuffers' verifier), and the cross-references
// (verifyBundle). Each gives a message that names what is wrong, so a
// damaged or hostile file never reaches the executor.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "VectorAlignment.h"

#include "sim/Runtime/BundleFormat.h"
#include "sim/Runtime/CpuLevels.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

namespace sim::rt {

//===----------------------------------------------------------------------===//
// Names
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
  case Strategy::Lts:
    return "lts";
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

const char *interpName(Interp interp) {
  switch (interp) {
  case Interp::Linear:
    return "linear";
  case Interp::Cubic:
    return "cubic";
  case Interp::Hermite:
    return "hermite";
  case Interp::None:
    return "none";
  case Interp::Flux:
    return "flux";
  }
  return "?";
}

const char *boundaryName(Boundary boundary) {
  switch (boundary) {
  case Boundary::Clamp:
    return "clamp";
  case Boundary::Wrap:
    return "wrap";
  case Boundary::Zero:
    return "zero";
  }
  return "?";
}

const char *advanceName(Advance advance) {
  switch (advance) {
  case Advance::WholeStep:
    return "whole_step";
  case Advance::GroupSubSteps:
    return "group_substeps";
  case Advance::GridSubSteps:
    return "grid_substeps";
  case Advance::LocalSteps:
    return "local_steps";
  case Advance::LocalFlux:
    return "local_flux";
  }
  return "?";
}

const char *hostIsa() {
#if defined(__x86_64__)
  return "x86-64";
#elif defined(__aarch64__)
  return "aarch64";
#else
  return "unknown";
#endif
}

const std::vector<std::string> &knownIsas() {
#if defined(__x86_64__)
  // The x86-64 microarchitecture levels of the psABI, as the compiler
  // names them (getCPUIsaLevels()), most portable first.
  static const std::vector<std::string> levels = {"x86-64", "x86-64-v2",
                                                  "x86-64-v3", "x86-64-v4"};
#else
  static const std::vector<std::string> levels = {hostIsa()};
#endif
  return levels;
}

namespace {

/// Whether this CPU (and its operating system, which must save the wider
/// registers) runs code of `level`.
bool cpuSupports(const std::string &level) {
#if defined(__x86_64__)
  return bundle::cpuRunsLevel(level);
#else
  return level == hostIsa();
#endif
}

std::string joinNames(const std::vector<std::string> &names) {
  std::string text;
  for (const std::string &name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

/// What a level adds that code of it may use, for messages.
const char *isaFeatures(const std::string &level) {
  if (level == "x86-64-v2")
    return "SSE4.2, POPCNT";
  if (level == "x86-64-v3")
    return "AVX2, FMA, BMI2";
  if (level == "x86-64-v4")
    return "AVX-512 F/BW/CD/DQ/VL";
  return "";
}

} // namespace

std::vector<std::string> hostIsas() {
  const std::vector<std::string> &known = knownIsas();
  size_t cap = known.size();
  if (const char *limit = std::getenv("SIM_CPU_ISA"); limit && *limit) {
    auto found = std::find(known.begin(), known.end(), limit);
    if (found == known.end())
      fail(SIM_ERROR_INVALID_ARGUMENT,
           std::string("SIM_CPU_ISA=") + limit +
               " is not an instruction-set level of this machine (" +
               joinNames(known) + ")");
    cap = size_t(found - known.begin()) + 1;
  }
  std::vector<std::string> levels;
  for (size_t i = cap; i-- > 0;)
    if (cpuSupports(known[i]))
      levels.push_back(known[i]);
  return levels;
}

std::string crcText(uint32_t crc) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", crc);
  return text;
}

std::string missingIsaMessage(const schema::PlanT &plan) {
  std::vector<std::string> present;
  for (const auto &code : plan.cpu)
    present.push_back(code->isa);
  if (present.empty())
    return "it has no CPU kernels";
  const char *limit = std::getenv("SIM_CPU_ISA");
  std::string message = "it has CPU kernels for " + joinNames(present) +
                        " only, and this CPU runs none of them";
  if (limit && *limit)
    message += std::string(" at SIM_CPU_ISA=") + limit + " or below";
  for (const std::string &isa : present)
    if (std::find(knownIsas().begin(), knownIsas().end(), isa) !=
            knownIsas().end() &&
        !cpuSupports(isa) && *isaFeatures(isa))
      message += " (" + isa + " needs " + isaFeatures(isa) + ")";
  return message +
         "; recompile with sim-translate --sim-cpu-isas=" + knownIsas().front();
}

//===----------------------------------------------------------------------===//
// Elements and values
//===----------------------------------------------------------------------===//

std::string elementText(const schema::Element &element) {
  std::string scalar = scalarTypeName(element.scalar());
  if (element.lanes() == 1)
    return scalar;
  return "vector<" + std::to_string(element.lanes()) + "x" + scalar + ">";
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
  std::string typeName = scalarTypeName(type);
  auto bad = [&](const std::string &why) {
    fail(SIM_ERROR_INVALID_ARGUMENT, what + ": '" + copy + "' " + why);
  };
  // strtoll and strtod skip leading blanks and accept an empty string; a
  // value is one token.
  if (copy.empty() || std::isspace((unsigned char)copy.front()))
    bad("is not an " + typeName + " value");
  Value value;
  value.type = type;
  char *end = nullptr;
  errno = 0;
  if (value.isFloat()) {
    value.f = type == ScalarType::F32 ? double(std::strtof(copy.c_str(), &end))
                                      : std::strtod(copy.c_str(), &end);
    if (*end)
      bad("is not an " + typeName + " value");
    if (errno == ERANGE && std::isinf(value.f))
      bad("is out of range for " + typeName);
    // A nonzero value that rounds to 0 (below the smallest subnormal) is
    // refused as the compiler's --sim-set-params refuses it, not run as 0.
    if (errno == ERANGE && value.f == 0)
      bad("underflows to 0 in " + typeName);
    // strtod reads 0x10 as 16, where an MLIR float literal 0x... is the
    // value's bits: neither is taken for the other.
    std::string_view digits = text;
    if (!digits.empty() && (digits.front() == '-' || digits.front() == '+'))
      digits.remove_prefix(1);
    if (digits.size() > 1 && digits[0] == '0' &&
        (digits[1] == 'x' || digits[1] == 'X'))
      bad("is hexadecimal; give an " + typeName + " value in decimal");
    return value;
  }
  long long parsed = std::strtoll(copy.c_str(), &end, 10);
  if (*end)
    bad("is not an integer (" + typeName + ")");
  if (errno == ERANGE || (type == ScalarType::I32 &&
                          (parsed < std::numeric_limits<int32_t>::min() ||
                           parsed > std::numeric_limits<int32_t>::max())))
    bad("is out of range for " + typeName);
  value.i = parsed;
  return value;
}

//===----------------------------------------------------------------------===//
// The bundle
//===----------------------------------------------------------------------===//

const schema::PlanT *Bundle::plan(Strategy strategy) const {
  for (const auto &plan : contents.plans)
    if (plan->strategy == strategy)
      return plan.get();
  return nullptr;
}

std::vector<Strategy> Bundle::strategies() const {
  std::vector<Strategy> list;
  for (const auto &plan : contents.plans)
    list.push_back(plan->strategy);
  return list;
}

const schema::CpuCodeT *Bundle::cpuCode(const schema::PlanT &plan) const {
  // The highest level the CPU runs: every level computes the same bits
  // (docs/Bundle.md), the higher ones faster.
  for (const std::string &isa : hostIsas())
    for (const auto &code : plan.cpu)
      if (code->isa == isa)
        return code.get();
  return nullptr;
}

int Bundle::findParam(std::string_view name) const {
  for (size_t i = 0; i < scene().params.size(); ++i)
    if (scene().params[i]->name == name)
      return int(i);
  return -1;
}

const schema::PhaseT *findPhase(const schema::PlanT &plan, PhaseKind kind) {
  for (const auto &phase : plan.phases)
    if (phase->kind == kind)
      return phase.get();
  return nullptr;
}

namespace {

void unrollSteps(const std::vector<std::unique_ptr<schema::StepT>> &steps,
                 std::vector<const schema::LaunchT *> &into) {
  for (const auto &step : steps) {
    if (step->launch) {
      into.push_back(step->launch.get());
      continue;
    }
    for (uint32_t i = 0; i < step->repeat->count; ++i)
      unrollSteps(step->repeat->body, into);
  }
}

} // namespace

std::vector<const schema::LaunchT *> unrollPhase(const schema::PhaseT &phase) {
  std::vector<const schema::LaunchT *> launches;
  unrollSteps(phase.body, launches);
  return launches;
}

std::shared_ptr<const Bundle> Bundle::read(const std::string &path) {
  // Without blocking: opening a FIFO for reading would wait for a writer
  // before the check below can refuse it.
  int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0)
    fail(SIM_ERROR_IO,
         "cannot open bundle '" + path + "': " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { close(fd); }
  } closer{fd};
  struct stat info;
  if (fstat(fd, &info) != 0)
    fail(SIM_ERROR_IO,
         "cannot read bundle '" + path + "': " + std::strerror(errno));
  // A device, FIFO or directory has no size to trust (/dev/zero never
  // ends).
  if (!S_ISREG(info.st_mode))
    fail(SIM_ERROR_IO,
         "cannot read bundle '" + path + "': it is not a regular file");
  if (uint64_t(info.st_size) > schema::kMaxBundleBytes)
    fail(SIM_ERROR_BUNDLE, "bundle '" + path + "': the file has " +
                               std::to_string(info.st_size) +
                               " bytes, more than a bundle may have (" +
                               std::to_string(schema::kMaxBundleBytes) + ")");
  std::vector<uint8_t> bytes(size_t(info.st_size));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      fail(SIM_ERROR_IO,
           "cannot read bundle '" + path + "': " + std::strerror(errno));
    if (n == 0)
      break; // Shrunk while reading: the header check reports it.
    done += size_t(n);
  }
  bytes.resize(done);
  return parse(bytes.data(), bytes.size(), path);
}

std::shared_ptr<const Bundle> Bundle::parse(const uint8_t *data, size_t size,
                                            const std::string &name) {
  auto result = std::make_shared<Bundle>();
  result->name = name;
  const std::string where = "bundle '" + name + "': ";
  auto error = [&](const std::string &message) {
    fail(SIM_ERROR_BUNDLE, where + message);
  };

  if (!schema::hasMagic(data, size))
    error(size < sizeof schema::kMagic
              ? "the file has " + std::to_string(size) +
                    " bytes, too few for a bundle (truncated?)"
              : "not a sim bundle (wrong magic; expected \"SIMBNDL\\0\")");
  if (size < schema::kHeaderSize)
    error("the file has " + std::to_string(size) + " bytes, fewer than the " +
          std::to_string(schema::kHeaderSize) + "-byte header (truncated?)");
  schema::Header header = schema::decodeHeader(data);
  if (header.version != schema::kFormatVersion)
    error("format version " + std::to_string(header.version) +
          (header.version < schema::kFormatVersion
               ? " is no longer supported: this runtime reads version " +
                     std::to_string(schema::kFormatVersion) +
                     "; recompile the scene with sim-translate --sim-to-bundle"
               : " is not supported (this runtime reads version " +
                     std::to_string(schema::kFormatVersion) + ")"));
  if (header.size != size)
    error("the header gives a file size of " + std::to_string(header.size) +
          " bytes but the file has " + std::to_string(size) +
          (header.size > size ? " (truncated?)" : ""));
  if (header.reserved != 0)
    error("the reserved header field is not zero (damaged?)");
  const uint8_t *payload = data + schema::kHeaderSize;
  size_t payloadSize = size - schema::kHeaderSize;
  // zlib's crc32 takes sizes as uInt: a bundle is at most 1 GiB.
  if (payloadSize > schema::kMaxBundleBytes)
    error("the file is larger than a bundle may be");
  uint32_t crc = uint32_t(crc32(0L, Z_NULL, 0));
  crc = uint32_t(crc32(crc, payload, uInt(payloadSize)));
  if (crc != header.checksum)
    error("the checksum does not match its contents (CRC-32 " + crcText(crc) +
          ", the header says " + crcText(header.checksum) +
          "): the file is damaged");

  result->checksum = crc;

  // A root offset and the file identifier, at least, before the identifier
  // is looked at.
  if (payloadSize <
      sizeof(flatbuffers::uoffset_t) + flatbuffers::kFileIdentifierLength)
    error("the contents have " + std::to_string(payloadSize) +
          " bytes, too few for a bundle FlatBuffer");
  // FlatBuffers reads scalars in place: the buffer must be aligned as the
  // writer aligned it (8), which `data` need not be.
  std::vector<uint8_t> aligned(payload, payload + payloadSize);
  flatbuffers::Verifier::Options options;
  options.max_depth = 64;
  options.max_tables = 1000000;
  flatbuffers::Verifier verifier(aligned.data(), aligned.size(), options);
  if (!schema::BundleBufferHasIdentifier(aligned.data()))
    error("the contents are not a bundle FlatBuffer (wrong identifier)");
  if (!schema::VerifyBundleBuffer(verifier))
    error("the contents do not verify as a bundle FlatBuffer (an offset, "
          "length or nesting outside the buffer)");
  const schema::Bundle *root = schema::GetBundle(aligned.data());
  if (const schema::Reference *reference = root->reference();
      reference && reference->components()) {
    auto components = reference->components();
    for (flatbuffers::uoffset_t c = 0; c < components->size(); ++c) {
      const schema::RefComponent *component = components->Get(c);
      for (auto [field, vector] :
           {std::pair{"local_window", component->local_window()},
            std::pair{"flux_window", component->flux_window()}})
        if (!elementsAligned(vector))
          error("the contents do not verify as a bundle FlatBuffer: the "
                "int64 vector " +
                std::string(field) + " of reference component " +
                std::to_string(c) +
                " is not aligned to 8 bytes (damaged? FlatBuffers aligns "
                "what it writes)");
    }
  }
  root->UnPackTo(&result->contents);
  try {
    verifyBundle(result->contents);
  } catch (const Error &e) {
    error(e.what());
  }

  for (const auto &buffer : result->scene().buffers) {
    result->elementTexts.push_back(elementText(*buffer->element));
    std::string interp = interpName(buffer->interp);
    if (buffer->interp == Interp::Hermite)
      interp += ":" + result->scene().buffers[size_t(buffer->derivative)]->name;
    result->interpTexts.push_back(interp);
  }
  for (const auto &param : result->scene().params)
    result->defaultTexts.push_back(Value::of(*param->value).text());
  return result;
}

} // namespace sim::rt
