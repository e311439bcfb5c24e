//===- RunJson.h - the JSON report of the hand-written baselines -*- C++
//-*-===//
//
// sim-baseline-cpu, sim-baseline-host and sim-baseline-cuda write their
// metrics with sim-run's keys (bench/run reads both), with nlohmann-json as
// sim-run does. Header-only; the counters come from each baseline's clock.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_COMMON_RUNJSON_H
#define SIM_BENCH_COMMON_RUNJSON_H

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>

namespace sim::bench {

/// Adds the big-step histogram (sizes 1 to `maxSteps`), the evaluations of
/// `components` components and their total from `clock` to `json`.
template <typename Clock>
void addCounts(nlohmann::ordered_json &json, const Clock &clock, int maxSteps,
               int components) {
  nlohmann::ordered_json histogram = nlohmann::ordered_json::object(),
                         counts = nlohmann::ordered_json::object();
  unsigned long long total = 0;
  for (int m = 1; m <= maxSteps; ++m)
    histogram[std::to_string(m)] = clock.histogram[m];
  for (int c = 0; c < components; ++c) {
    counts["C" + std::to_string(c)] = clock.evaluations[c];
    total += clock.evaluations[c];
  }
  json["big_step_histogram"] = histogram;
  json["evaluations"] = counts;
  json["total_evaluations"] = total;
}

/// Writes `json` to `path`, indented; false (and a message) when it cannot.
inline bool writeJson(const std::string &path,
                      const nlohmann::ordered_json &json) {
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) {
    std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
    return false;
  }
  return true;
}

} // namespace sim::bench

#endif // SIM_BENCH_COMMON_RUNJSON_H
