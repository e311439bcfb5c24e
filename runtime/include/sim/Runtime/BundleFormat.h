//===- BundleFormat.h - the header of a .simb file --------------*- C++ -*-===//
//
// A bundle file is this 32-byte header followed by one FlatBuffer of the
// schema runtime/schema/bundle.fbs (docs/Bundle.md):
//
//   offset  size  field
//   0       8     magic "SIMBNDL\0"
//   8       4     u32 format version (kFormatVersion)
//   12      4     u32 CRC-32 (zlib's) of every byte after the header
//   16      8     u64 size of the whole file in bytes
//   24      8     reserved, 0
//
// All integers are little-endian. The compiler (lib/Target/Bundle) writes
// it and the runtime (runtime/src/Bundle.cpp) checks it before it looks at
// anything else; both include this header, so the layout is written once.
// Header-only, C++17, no dependency.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_BUNDLEFORMAT_H
#define SIM_RUNTIME_BUNDLEFORMAT_H

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace sim::bundle {

constexpr char kMagic[8] = {'S', 'I', 'M', 'B', 'N', 'D', 'L', '\0'};
/// Version 1 held text sections; version 2 is the FlatBuffer; version 3
/// gives `levels @C` a seventh section, the blocks' sub-steps (kernels of
/// version 2 decoded them in place and would find too little memory
/// under a version 3 runtime's layout contract, and the reverse); version
/// 4 adds `exchange_local_step` (a version 3 runtime would not send those
/// ghost items at all); version 5 adds `exchange_local_flux` (likewise);
/// version 6 gives `levels @C` an eighth section, the codes kept for a
/// component with `invariant_levels` (a version 5 runtime would allocate
/// too little memory for them); version 7 lets a pair's writer bound the
/// big step by its largest num_steps under lts (`largest_estimate`: a
/// version 6 reference executor would take its smallest and disagree with
/// the kernels).
constexpr uint32_t kFormatVersion = 7;
constexpr size_t kHeaderSize = 32;
/// The largest bundle a runtime reads (a bundle of every strategy of the
/// paper's scenes takes well under 1 MiB).
constexpr uint64_t kMaxBundleBytes = uint64_t(1) << 30;
/// The largest group size a plan may be made for (the compiler refuses a
/// larger --sim-group-size, the runtime a bundle that records one).
constexpr uint32_t kMaxGroupSize = uint32_t(1) << 16;
/// The widest halo of a distributed plan: the ghost items a rank holds on
/// each side of its block. The compiler refuses a scene whose windows reach
/// further, and the runtime a bundle that records more.
constexpr uint32_t kMaxHalo = uint32_t(1) << 20;

struct Header {
  uint32_t version = kFormatVersion;
  uint32_t checksum = 0;
  uint64_t size = 0;
  uint64_t reserved = 0;
};

namespace detail {
inline void putLittle(uint8_t *at, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i)
    at[i] = uint8_t(value >> (8 * i));
}
inline uint64_t getLittle(const uint8_t *at, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i)
    value |= uint64_t(at[i]) << (8 * i);
  return value;
}
} // namespace detail

/// The header's 32 bytes.
inline std::string encodeHeader(const Header &header) {
  uint8_t bytes[kHeaderSize] = {};
  std::memcpy(bytes, kMagic, sizeof kMagic);
  detail::putLittle(bytes + 8, header.version, 4);
  detail::putLittle(bytes + 12, header.checksum, 4);
  detail::putLittle(bytes + 16, header.size, 8);
  detail::putLittle(bytes + 24, header.reserved, 8);
  return std::string(reinterpret_cast<const char *>(bytes), kHeaderSize);
}

/// Whether `data` starts with the magic (at least 8 bytes).
inline bool hasMagic(const uint8_t *data, size_t size) {
  return size >= sizeof kMagic && std::memcmp(data, kMagic, sizeof kMagic) == 0;
}

/// The fields of a header of at least kHeaderSize bytes (the magic is not
/// checked).
inline Header decodeHeader(const uint8_t *data) {
  Header header;
  header.version = uint32_t(detail::getLittle(data + 8, 4));
  header.checksum = uint32_t(detail::getLittle(data + 12, 4));
  header.size = detail::getLittle(data + 16, 8);
  header.reserved = detail::getLittle(data + 24, 8);
  return header;
}

} // namespace sim::bundle

#endif // SIM_RUNTIME_BUNDLEFORMAT_H
