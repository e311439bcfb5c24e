//===- Bundle.cpp - reading and validating a .simb file -------------------===//
//
// The binary container of docs/Bundle.md: header, section table, sections.
// Every field is checked before it is used (offsets and sizes with overflow
// in mind), so a truncated or hostile file gives a message that names the
// problem rather than a crash.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace sim::rt {

namespace {

constexpr uint8_t kMagic[8] = {'S', 'I', 'M', 'B', 'N', 'D', 'L', 0};
constexpr uint32_t kVersion = 1;
constexpr size_t kHeaderSize = 24;
constexpr size_t kEntrySize = 32;
constexpr uint32_t kNoStrategy = 0xffffffffu;

uint32_t readU32(const uint8_t *p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 |
         uint32_t(p[3]) << 24;
}

uint64_t readU64(const uint8_t *p) {
  return uint64_t(readU32(p)) | uint64_t(readU32(p + 4)) << 32;
}

const char *kindName(uint32_t kind) {
  switch (SectionKind(kind)) {
  case SectionKind::Scene:
    return "scene";
  case SectionKind::Plan:
    return "plan";
  case SectionKind::Ptx:
    return "PTX";
  case SectionKind::Cpu:
    return "CPU";
  case SectionKind::ReferenceModel:
    return "reference model";
  case SectionKind::ReferenceObject:
    return "reference object";
  }
  return "?";
}

/// Scene and reference sections belong to no strategy.
bool hasStrategy(uint32_t kind) {
  return SectionKind(kind) == SectionKind::Plan ||
         SectionKind(kind) == SectionKind::Ptx ||
         SectionKind(kind) == SectionKind::Cpu;
}

bool isElf(const uint8_t *data, uint64_t size) {
  static constexpr uint8_t elf[4] = {0x7f, 'E', 'L', 'F'};
  return size >= 64 && std::memcmp(data, elf, 4) == 0;
}

} // namespace

std::shared_ptr<const Bundle> Bundle::read(const std::string &path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    fail(SIM_ERROR_IO,
         "cannot open bundle '" + path + "': " + std::strerror(errno));
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                             std::istreambuf_iterator<char>());
  if (file.bad())
    fail(SIM_ERROR_IO, "cannot read bundle '" + path + "'");
  return parse(bytes.data(), bytes.size(), path);
}

std::shared_ptr<const Bundle> Bundle::parse(const uint8_t *data, size_t size,
                                            const std::string &name) {
  auto bundle = std::make_shared<Bundle>();
  bundle->name = name;
  const std::string where = "bundle '" + name + "': ";
  auto error = [&](const std::string &message) {
    fail(SIM_ERROR_BUNDLE, where + message);
  };

  if (size < kHeaderSize)
    error("the file has " + std::to_string(size) +
          " bytes, fewer than the 24-byte header (truncated?)");
  if (std::memcmp(data, kMagic, sizeof kMagic) != 0)
    error("not a sim bundle (wrong magic; expected \"SIMBNDL\\0\")");
  uint32_t version = readU32(data + 8);
  if (version != kVersion)
    error("format version " + std::to_string(version) +
          " is not supported (this runtime reads version 1)");
  uint32_t count = readU32(data + 12);
  uint64_t declared = readU64(data + 16);
  if (declared != size)
    error("the header gives a file size of " + std::to_string(declared) +
          " bytes but the file has " + std::to_string(size) +
          (declared > size ? " (truncated?)" : ""));
  // count < 2^32, so the table size cannot overflow 64 bits.
  uint64_t tableEnd = kHeaderSize + uint64_t(count) * kEntrySize;
  if (tableEnd > size)
    error("the section table of " + std::to_string(count) +
          " entries reaches past the end of the file");

  struct Section {
    uint32_t kind, strategy;
    const uint8_t *data;
    uint64_t size;
  };
  std::vector<Section> sections;
  const Section *scene = nullptr;
  const Section *referenceModel = nullptr, *referenceObject = nullptr;
  std::array<std::array<const Section *, 5>, kNumStrategies> byKind = {};
  sections.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint8_t *entry = data + kHeaderSize + size_t(i) * kEntrySize;
    uint32_t kind = readU32(entry);
    uint32_t strategy = readU32(entry + 4);
    uint64_t offset = readU64(entry + 8);
    uint64_t length = readU64(entry + 16);
    std::string what = "section " + std::to_string(i);
    if (kind < 1 || kind > 6)
      error(what + " has unknown kind " + std::to_string(kind));
    what += " (" + std::string(kindName(kind)) + ")";
    if (!hasStrategy(kind)) {
      if (strategy != kNoStrategy)
        error(what + " has strategy " + std::to_string(strategy) + " but a " +
              kindName(kind) + " section has none (0xffffffff)");
    } else if (strategy >= kNumStrategies) {
      error(what + " has unknown strategy " + std::to_string(strategy));
    }
    if (offset > size || length > size - offset)
      error(what + " at offset " + std::to_string(offset) + " with " +
            std::to_string(length) +
            " bytes reaches past the end of the file (" + std::to_string(size) +
            " bytes)");
    if (offset < tableEnd && length > 0)
      error(what + " at offset " + std::to_string(offset) +
            " overlaps the header or the section table (which ends at " +
            std::to_string(tableEnd) + ")");
    if (offset % 8 != 0)
      error(what + " starts at offset " + std::to_string(offset) +
            ", which is not a multiple of 8");
    sections.push_back({kind, strategy, data + offset, length});
  }
  for (const Section &section : sections) {
    const Section *&slot =
        SectionKind(section.kind) == SectionKind::Scene ? scene
        : SectionKind(section.kind) == SectionKind::ReferenceModel
            ? referenceModel
        : SectionKind(section.kind) == SectionKind::ReferenceObject
            ? referenceObject
            : byKind[section.strategy][section.kind];
    if (slot) {
      std::string what = kindName(section.kind) + std::string(" section");
      if (hasStrategy(section.kind))
        what += std::string(" of strategy ") +
                strategyName(Strategy(section.strategy));
      error("repeated " + what);
    }
    slot = &section;
  }

  if (!scene)
    error("no scene section");
  auto text = [](const Section *section) {
    return std::string_view(reinterpret_cast<const char *>(section->data),
                            section->size);
  };
  try {
    bundle->scene = parseScene(text(scene));
  } catch (const Error &e) {
    error(e.what());
  }
  const Scene &sceneInfo = bundle->scene;

  for (int s = 0; s < kNumStrategies; ++s) {
    Strategy strategy = Strategy(s);
    std::string name = strategyName(strategy);
    const auto &kinds = byKind[s];
    bool listed = false;
    for (Strategy other : sceneInfo.strategies)
      listed |= other == strategy;
    const Section *planSection = kinds[uint32_t(SectionKind::Plan)];
    if (!planSection) {
      if (listed)
        error("the scene lists strategy '" + name +
              "' but there is no plan section for it");
      for (SectionKind kind : {SectionKind::Ptx, SectionKind::Cpu})
        if (kinds[uint32_t(kind)])
          error(std::string(kindName(uint32_t(kind))) +
                " section of strategy '" + name +
                "' without a plan section for it");
      continue;
    }
    if (!listed)
      error("plan section of strategy '" + name +
            "', which the scene's 'strategies' record does not list");
    Bundle::StrategyCode &code = bundle->strategies[s];
    code.present = true;
    try {
      code.plan = parsePlan(text(planSection), sceneInfo, strategy);
    } catch (const Error &e) {
      error(e.what());
    }
    if (const Section *ptx = kinds[uint32_t(SectionKind::Ptx)]) {
      // The format NUL-terminates the PTX; the string adds its own NUL
      // for the driver either way.
      std::string_view body = text(ptx);
      size_t nul = body.find('\0');
      if (nul != std::string_view::npos)
        body = body.substr(0, nul);
      if (body.empty())
        error("PTX section of strategy '" + name + "' is empty");
      code.ptx = std::string(body);
    }
    if (const Section *cpu = kinds[uint32_t(SectionKind::Cpu)]) {
      if (!isElf(cpu->data, cpu->size))
        error("CPU section of strategy '" + name +
              "' is not an ELF shared object");
      code.cpu = std::vector<uint8_t>(cpu->data, cpu->data + cpu->size);
    }
  }

  // The model says what to call and the object is what it calls: one is
  // useless without the other.
  if (bool(referenceModel) != bool(referenceObject))
    error(std::string("a reference ") +
          (referenceModel
               ? "model section without a reference object section"
               : "object section without a reference model section") +
          " (docs/Reference.md: both or neither)");
  if (referenceModel) {
    try {
      bundle->reference = parseReferenceModel(text(referenceModel), sceneInfo);
    } catch (const Error &e) {
      error(e.what());
    }
    if (!isElf(referenceObject->data, referenceObject->size))
      error("reference object section is not an ELF shared object");
    bundle->referenceObject = std::vector<uint8_t>(
        referenceObject->data, referenceObject->data + referenceObject->size);
  }
  return bundle;
}

} // namespace sim::rt
