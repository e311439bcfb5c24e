//===- Timeline.cpp - where sim-run's runs stop on their way --------------===//

#include "Timeline.h"

#include "Options.h"
#include "Signals.h"

#include <algorithm>
#include <limits>

namespace simrun {

int64_t Stops::nextOutput(int64_t time) const {
  if (outputEvery <= 0 || time >= end)
    return end;
  // time and outputEvery are at most 10^12: no overflow.
  return std::min(end, (time / outputEvery + 1) * outputEvery);
}

int64_t Stops::nextCheckpoint(int64_t time) const {
  if (checkpointEvery <= 0)
    return std::numeric_limits<int64_t>::max();
  return (time / checkpointEvery + 1) * checkpointEvery;
}

int64_t Stops::outputTimes(int64_t begin) const {
  if (outputEvery <= 0)
    return 0;
  if (begin >= end)
    return 1;
  // The start, the multiples after it and before the end, the end.
  return 2 + (end - 1) / outputEvery - begin / outputEvery;
}

void RunTotals::add(sim_session *session, int64_t maxSteps, bool atOutput) {
  sim_metrics run;
  if (sim_session_metrics(session, &run) != SIM_OK)
    runError(sim_last_error());
  if (!started)
    metrics.begin = run.begin;
  started = true;
  metrics.steps += run.steps;
  metrics.end = run.end;
  metrics.wall_seconds += run.wall_seconds;
  metrics.kernel_seconds += run.kernel_seconds;
  metrics.launches += run.launches;
  metrics.graph_launches += run.graph_launches;
  metrics.host_syncs += run.host_syncs;
  metrics.big_steps += run.big_steps;
  metrics.halo_exchanges += run.halo_exchanges;
  metrics.exchanged_bytes += run.exchanged_bytes;
  metrics.allreduces += run.allreduces;
  counts.bigSteps += run.big_steps;
  int32_t components = sim_session_num_components(session);
  if (counts.evaluations.empty())
    for (int32_t c = 0; c < components; ++c)
      counts.evaluations.emplace_back(sim_session_component(session, c), 0);
  for (int32_t c = 0; c < components; ++c)
    counts.evaluations[size_t(c)].second += sim_session_evaluations(session, c);
  int32_t kernels = sim_session_num_kernels(session);
  for (int32_t k = 0; k < kernels; ++k) {
    sim_kernel_profile profile;
    if (sim_session_kernel_profile(session, k, &profile) != SIM_OK)
      runError(sim_last_error());
    if (size_t(k) == counts.kernels.size())
      counts.kernels.push_back({profile.name, 0, 0});
    RunCounts::Kernel &kernel = counts.kernels[size_t(k)];
    kernel.launches += profile.launches;
    // Untimed in one session run: untimed in all of them.
    kernel.seconds = profile.seconds < 0 || kernel.seconds < 0
                         ? -1
                         : kernel.seconds + profile.seconds;
  }
  counts.histogram.resize(size_t(maxSteps) + 1, 0);
  for (int64_t m = 1; m <= maxSteps; ++m)
    counts.histogram[size_t(m)] += sim_session_histogram(session, m);
  int64_t cut = sim_session_cut_big_steps(session);
  cuts += cut;
  if (atOutput)
    cutsAtOutputs += cut;
}

PartState runThrough(sim_session *session, const Stops &stops, int64_t maxSteps,
                     RunTotals &totals, const TimelineHooks &hooks) {
  int64_t now = sim_session_time(session);
  if (hooks.output && !hooks.output(now))
    return {Stage::Cut, now, stops.end};
  int64_t lastOutput = now;
  int64_t nextOutput = stops.nextOutput(now);
  int64_t nextCheckpoint = stops.nextCheckpoint(now);
  // One session run at least, for a run of 0 base steps too: its metrics.
  bool ran = false;
  while (now < stops.end || !ran) {
    // A signal between two session runs stops the run as one inside would.
    if (interrupted())
      return {Stage::Cut, now, stops.end};
    int64_t to = nextOutput;
    if (hooks.beforeRun)
      hooks.beforeRun(session, now);
    sim_status status =
        nextCheckpoint < to
            ? sim_session_run_pausing(session, to - now, nextCheckpoint - now)
            : sim_session_run(session, to - now);
    if (hooks.afterRun)
      hooks.afterRun();
    ran = true;
    if (status != SIM_OK && status != SIM_ERROR_INTERRUPTED)
      runError(sim_last_error());
    now = sim_session_time(session);
    totals.add(session, maxSteps, now == to && to < stops.end);
    if (status == SIM_ERROR_INTERRUPTED)
      return {Stage::Cut, now, stops.end};
    if (now >= nextCheckpoint) {
      if (hooks.checkpoint)
        hooks.checkpoint(now);
      nextCheckpoint = stops.nextCheckpoint(now);
    }
    if (now == to) {
      if (now != lastOutput && hooks.output && !hooks.output(now))
        return {Stage::Cut, now, stops.end};
      lastOutput = now;
      nextOutput = stops.nextOutput(now);
    }
  }
  if (now != stops.end)
    runError("the run ended at base step " + std::to_string(now) + ", not at " +
             std::to_string(stops.end));
  return {Stage::Done, stops.end, stops.end};
}

void startAt(sim_session *session, const std::string &restart) {
  sim_status status = restart.empty()
                          ? sim_session_init(session)
                          : sim_session_restart(session, restart.c_str());
  if (status != SIM_OK)
    runError(std::string(restart.empty() ? "" : "--restart: ") +
             sim_last_error());
}

} // namespace simrun
