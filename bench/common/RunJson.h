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
#include <utility>
#include <vector>

namespace sim::bench {

/// What every baseline reports of a run, under sim-run's keys.
struct RunRecord {
  std::string scene, strategy, backend, device, interp;
  bool mOnHost = false;
  long long range = 0, steps = 0;
  double dt = 0;
  int rounds = 0, dist = 0, groupSize = 0, repeat = 0;
  /// Every measured run's wall and kernel time, and their medians.
  std::vector<double> walls, kernels;
  double wall = 0, kernel = 0;
  unsigned long long launches = 0, hostSyncs = 0, bigSteps = 0;
};

/// A run's record with the settings of a baseline's options `o` (their
/// fields have the same names in every baseline).
template <typename Options>
RunRecord recordOf(const Options &o, std::string scene, std::string strategy) {
  RunRecord run;
  run.scene = std::move(scene);
  run.strategy = std::move(strategy);
  run.interp = o.interp;
  run.range = o.params.range;
  run.steps = o.steps;
  run.dt = o.params.dt;
  run.rounds = o.params.rounds;
  run.dist = o.params.dist;
  run.groupSize = o.groupSize;
  run.repeat = o.repeat;
  return run;
}

/// `run` as JSON (implementation "hand-written").
inline nlohmann::ordered_json runJson(const RunRecord &run) {
  return {{"scene", run.scene},
          {"strategy", run.strategy},
          {"implementation", "hand-written"},
          {"backend", run.backend},
          {"device", run.device},
          {"m_on_host", run.mOnHost},
          {"interp", run.interp},
          {"range", run.range},
          {"dt", run.dt},
          {"L", run.rounds},
          {"dist", run.dist},
          {"group_size", run.groupSize},
          {"steps", run.steps},
          {"repeat", run.repeat},
          {"wall_seconds", run.wall},
          {"kernel_seconds", run.kernel},
          {"wall_seconds_runs", run.walls},
          {"kernel_seconds_runs", run.kernels},
          {"launches", run.launches},
          {"host_syncs", run.hostSyncs},
          {"big_steps", run.bigSteps}};
}

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
