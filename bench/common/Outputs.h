//===- Outputs.h - What the hand-written baselines write --------*- C++ -*-===//
//
// The observed buffer as a .npy file (--dump; numpy.load reads it, as it
// reads sim-run's) and the median of the measured runs, shared by
// sim-baseline-cpu, sim-baseline-host and sim-baseline-cuda. Header-only.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_COMMON_OUTPUTS_H
#define SIM_BENCH_COMMON_OUTPUTS_H

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace sim::bench {

/// `values` (range items of 4 floats) as a little-endian f32 .npy of shape
/// (range, 4), written to a temporary file and renamed into place; exits 1
/// when it cannot be written.
inline void writeNpy(const std::string &path, const std::vector<float> &values,
                     long long range) {
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" +
                       std::to_string(range) + ", 4), }";
  size_t total = 10 + header.size() + 1;
  header += std::string((64 - total % 64) % 64, ' ') + "\n";
  std::string temporary = path + ".tmp";
  std::ofstream out(temporary, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  unsigned short length = (unsigned short)header.size();
  out.put((char)(length & 0xff)).put((char)(length >> 8));
  out << header;
  out.write(reinterpret_cast<const char *>(values.data()),
            values.size() * sizeof(float));
  out.close();
  if (!out || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
    std::exit(1);
  }
}

/// The median of `values` (the mean of the middle two for an even count).
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace sim::bench

#endif // SIM_BENCH_COMMON_OUTPUTS_H
