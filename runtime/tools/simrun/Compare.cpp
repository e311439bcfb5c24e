//===- Compare.cpp - sim-run's error norms and --check --------------------===//

#include "Compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace simrun {

double Buffer::at(size_t i) const {
  if (scalarBytes == 8) {
    double value;
    std::memcpy(&value, bytes.data() + i * 8, 8);
    return value;
  }
  float value;
  std::memcpy(&value, bytes.data() + i * 4, 4);
  return value;
}

size_t Buffer::nonFinite() const {
  size_t count = 0;
  for (size_t i = 0; i < values(); ++i)
    count += !std::isfinite(at(i));
  return count;
}

ErrorNorms compare(const Buffer &value, const Buffer &reference) {
  ErrorNorms norms;
  double diff2 = 0, ref2 = 0;
  size_t count = std::min(value.values(), reference.values());
  for (size_t i = 0; i < count; ++i) {
    double a = value.at(i), b = reference.at(i);
    double d = a - b;
    if (std::isnan(d))
      norms.maxAbs = d;
    else if (!std::isnan(norms.maxAbs))
      norms.maxAbs = std::max(norms.maxAbs, std::fabs(d));
    diff2 += d * d;
    ref2 += b * b;
  }
  norms.rmsRel = ref2 > 0    ? std::sqrt(diff2 / ref2)
                 : diff2 > 0 ? INFINITY
                 : std::isnan(diff2) || std::isnan(ref2) ? NAN
                                                         : 0;
  return norms;
}

bool Check::evaluationsEqual() const {
  return std::all_of(
      evaluations.begin(), evaluations.end(),
      [](const CountRow &row) { return row.backend == row.reference; });
}

double defaultTolerance(int32_t precisionBytes) {
  return precisionBytes == 8 ? 1e-10 : 1e-4;
}

double defaultTotalTolerance(int32_t precisionBytes) {
  return precisionBytes == 8 ? 1e-8 : 1e-4;
}

std::string displayName(const std::string &name) {
  std::string shown;
  for (char c : name) {
    unsigned char byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      shown += escaped;
    } else {
      shown += c;
    }
  }
  return shown;
}

std::string scientific(double value, int digits) {
  // A NaN's sign bit depends on the operations that made it (an fma or a
  // multiply and an add, x86 or PTX): "nan" whatever it is.
  if (std::isnan(value))
    return "nan";
  char text[48];
  std::snprintf(text, sizeof text, "%.*e", digits, value);
  return text;
}

namespace {

/// "12 non-finite values on the backend and 3 on the reference executor".
std::string nonFiniteText(size_t backend, size_t reference) {
  auto values = [](size_t count) {
    return std::to_string(count) +
           (count == 1 ? " non-finite value" : " non-finite values");
  };
  if (reference == 0)
    return values(backend) + " on the backend";
  if (backend == 0)
    return values(reference) + " on the reference executor";
  return values(backend) + " on the backend and " + std::to_string(reference) +
         " on the reference executor";
}

Check::BufferRow checkBuffer(const Buffer &backend, const Buffer &reference,
                             double tolerance) {
  Check::BufferRow row;
  row.buffer = backend.name;
  row.norms = compare(backend, reference);
  bool anyFinite = false;
  for (size_t v = 0; v < reference.values(); ++v)
    if (std::isfinite(reference.at(v))) {
      row.maxReference = std::max(row.maxReference, std::fabs(reference.at(v)));
      anyFinite = true;
    }
  // No finite reference value has a largest magnitude (not 0: printed as
  // nan, null in JSON).
  if (!anyFinite && reference.values() > 0)
    row.maxReference = std::numeric_limits<double>::quiet_NaN();
  row.tolerance = tolerance >= 0 ? tolerance
                                 : defaultTolerance(backend.precisionBytes
                                                        ? backend.precisionBytes
                                                        : backend.scalarBytes);
  row.limit =
      row.tolerance * (anyFinite ? std::max(1.0, row.maxReference) : 1.0);
  row.nonFiniteBackend = backend.nonFinite();
  row.nonFiniteReference = reference.nonFinite();
  // A NaN max-abs compares false: it fails too.
  row.pass = row.nonFiniteBackend == 0 && row.nonFiniteReference == 0 &&
             row.norms.maxAbs <= row.limit;
  return row;
}

} // namespace

Check compareWithReference(const std::vector<Buffer> &backend,
                           const std::vector<Buffer> &reference,
                           const RunCounts &backendCounts,
                           const RunCounts &referenceCounts, double tolerance) {
  Check check;
  check.backend = backendCounts;
  check.reference = referenceCounts;
  for (size_t i = 0; i < backend.size() && i < reference.size(); ++i) {
    Check::BufferRow row = checkBuffer(backend[i], reference[i], tolerance);
    std::string name = displayName(row.buffer);
    if (row.nonFiniteBackend || row.nonFiniteReference)
      check.failures.push_back(
          "buffer " + name + " has " +
          nonFiniteText(row.nonFiniteBackend, row.nonFiniteReference));
    else if (!row.pass)
      check.failures.push_back(
          "buffer " + name + " exceeds the tolerance (max-abs " +
          scientific(row.norms.maxAbs) + " > " + scientific(row.limit) + ")");
    check.buffers.push_back(row);
  }

  for (const auto &[name, count] : backendCounts.evaluations)
    check.evaluations.push_back({name, count, -1});
  for (const auto &entry : referenceCounts.evaluations) {
    auto row = std::find_if(check.evaluations.begin(), check.evaluations.end(),
                            [&](const Check::CountRow &row) {
                              return row.component == entry.first;
                            });
    if (row == check.evaluations.end())
      check.evaluations.push_back({entry.first, -1, entry.second});
    else
      row->reference = entry.second;
  }
  auto count = [](int64_t value) {
    return value < 0 ? std::string("-") : std::to_string(value);
  };
  for (const Check::CountRow &row : check.evaluations)
    if (row.backend != row.reference)
      check.failures.push_back("evaluations of " + displayName(row.component) +
                               " differ (" + count(row.backend) + " vs " +
                               count(row.reference) + ")");
  if (backendCounts.bigSteps != referenceCounts.bigSteps)
    check.failures.push_back("big steps differ (" +
                             std::to_string(backendCounts.bigSteps) + " vs " +
                             std::to_string(referenceCounts.bigSteps) + ")");
  size_t sizes = std::max(backendCounts.histogram.size(),
                          referenceCounts.histogram.size());
  auto at = [](const std::vector<int64_t> &histogram, size_t m) {
    return m < histogram.size() ? histogram[m] : 0;
  };
  for (size_t m = 1; m < sizes; ++m)
    if (at(backendCounts.histogram, m) != at(referenceCounts.histogram, m))
      check.failures.push_back(
          "big steps of size " + std::to_string(m) + " differ (" +
          std::to_string(at(backendCounts.histogram, m)) + " vs " +
          std::to_string(at(referenceCounts.histogram, m)) + ")");
  return check;
}

void compareTotals(const std::vector<std::string> &names, int64_t time,
                   const std::vector<double> &backend,
                   const std::vector<double> &reference,
                   const std::vector<double> &tolerances,
                   std::vector<Check::TotalRow> &rows,
                   std::vector<std::string> &failures) {
  for (size_t t = 0; t < names.size() && t < backend.size() &&
                     t < reference.size() && t < tolerances.size();
       ++t) {
    Check::TotalRow row{names[t], time, backend[t], reference[t], 0, false};
    row.limit = tolerances[t] * std::max(1.0, std::fabs(row.reference));
    bool finite = std::isfinite(row.backend) && std::isfinite(row.reference);
    row.pass = finite && std::fabs(row.backend - row.reference) <= row.limit;
    if (!finite)
      failures.push_back("total " + displayName(row.total) + " at base step " +
                         std::to_string(time) + " is not finite (" +
                         scientific(row.backend, 9) + " vs " +
                         scientific(row.reference, 9) + ")");
    else if (!row.pass)
      failures.push_back("total " + displayName(row.total) + " at base step " +
                         std::to_string(time) + " differs (" +
                         scientific(row.backend, 9) + " vs " +
                         scientific(row.reference, 9) + ")");
    rows.push_back(row);
  }
}

} // namespace simrun
