//===- Npz.h - .npy arrays and .npz archives of them ------------*- C++ -*-===//
//
// sim-run's array files: a .npy file (NumPy's format 1.0: magic, a header
// dictionary padded to 64 bytes, the little-endian data) for --dump, and
// an .npz archive of several (what numpy.savez writes: a zip file of
// `<key>.npy` entries, stored uncompressed) for --output. The zip container
// is written by zlib's minizip through a descriptor, so the archive goes
// straight into the temporary file of Output.cpp's atomic write.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_NPZ_H
#define SIM_RUN_NPZ_H

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace simrun {

/// The header of a .npy file (format 1.0) of `descr` ("<f4", "<f8", "<i8",
/// "<U12") and `shape` ({} for a 0-d array), padded so that the data start
/// on a multiple of 64 bytes.
std::string npyHeader(const std::string &descr,
                      const std::vector<int64_t> &shape);

/// The descr of a float of `scalarBytes` (4 or 8).
std::string floatDescr(int32_t scalarBytes);

/// A whole .npy file of little-endian data.
std::string npyFile(const std::string &descr, const std::vector<int64_t> &shape,
                    std::string_view data);

/// A 0-d unicode array (numpy.array("text")): the text as UTF-32LE code
/// points, bytes that are not valid UTF-8 as U+FFFD.
std::string npyString(std::string_view text);

/// One array of an .npz archive: its key (the entry is `<key>.npy`), its
/// .npy header, and its data in pieces (the rows of a time series), written
/// one after the other.
struct NpzArray {
  std::string key;
  std::string header;
  std::vector<std::string_view> pieces;
};

/// Writes an .npz archive of `arrays`, in order, to `fd` (at its offset 0,
/// seekable: the zip container updates each entry's header after its
/// data). Entries are stored, not compressed, as numpy.savez stores them,
/// with a fixed date so that the same arrays make the same file; Zip64
/// where an entry or the archive needs it. `name` names the file in
/// messages. A failure is Exit{1}.
void writeNpz(int fd, const std::vector<NpzArray> &arrays,
              const std::string &name);

} // namespace simrun

#endif // SIM_RUN_NPZ_H
