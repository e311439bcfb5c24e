//===- Report.cpp - sim-run's table and JSON ------------------------------===//

#include "Report.h"

#include "Signals.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace simrun {

using Json = nlohmann::ordered_json;

bool Results::interrupted() const {
  for (const PartState *part : {&main.state, &reference, &checkState})
    if (part->stage == Stage::Cut || part->stage == Stage::Skipped)
      return true;
  return false;
}

TotalError compareTotal(const std::string &name, double value,
                        double reference) {
  TotalError error;
  error.total = name;
  error.available = true;
  error.value = value;
  error.reference = reference;
  error.absolute = std::fabs(value - reference);
  error.relative = reference != 0       ? error.absolute / std::fabs(reference)
                   : error.absolute > 0 ? INFINITY
                   : std::isnan(error.absolute) ? NAN
                                                : 0;
  return error;
}

std::string formatTime(double seconds) {
  char text[32];
  if (seconds < 1e-6)
    std::snprintf(text, sizeof text, "%.0f ns", seconds * 1e9);
  else if (seconds < 1e-3)
    std::snprintf(text, sizeof text, "%.1f us", seconds * 1e6);
  else if (seconds < 1)
    std::snprintf(text, sizeof text, "%.3f ms", seconds * 1e3);
  else
    std::snprintf(text, sizeof text, "%.3f s", seconds);
  return text;
}

std::string formatBytes(int64_t bytes) {
  if (bytes < 1024)
    return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  const char *units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes);
  int unit = -1;
  while (value >= 1024 && unit < 5) {
    value /= 1024;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.2f %s", value, units[unit]);
  return text;
}

double median(std::vector<double> values) {
  if (values.empty())
    return 0;
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

//===----------------------------------------------------------------------===//
// The table
//===----------------------------------------------------------------------===//

namespace {

void row(const std::string &name, const std::string &value) {
  std::printf("  %-16s %s\n", name.c_str(), value.c_str());
}

std::string cutText(const PartState &state) {
  return "interrupted at base step " + std::to_string(state.reached) + " of " +
         std::to_string(state.of);
}

/// "; not compared" and the like for a part that a signal cut or skipped.
std::string notDone(const PartState &state, const char *what) {
  if (state.stage == Stage::Cut)
    return cutText(state) + "; " + what;
  return std::string("not run (interrupted)");
}

} // namespace

std::vector<std::pair<std::string, int64_t>>
extraEvaluations(const MainRun &main) {
  std::vector<std::pair<std::string, int64_t>> extra;
  for (const auto &[component, count] : main.counts.evaluations)
    extra.emplace_back(component, main.cutsAtOutputs * main.range);
  return extra;
}

namespace {

void printHeader(const MainRun &main) {
  std::printf("scene %s, strategy %s, backend %s: %s\n",
              displayName(main.scene).c_str(), main.strategy.c_str(),
              main.backend.c_str(), main.device.c_str());
  if (main.showNote && !main.backendNote.empty())
    std::printf("  (not CUDA: %s)\n", main.backendNote.c_str());
  std::printf(
      "range %lld, dt %s, group size %lld, %lld base step%s, %s",
      (long long)main.range, main.dtText.c_str(), (long long)main.groupSize,
      (long long)main.steps, main.steps == 1 ? "" : "s",
      main.flushSubnormals ? "subnormals flushed to zero" : "IEEE subnormals");
  if (main.repeat > 1)
    std::printf(", median of %lld runs after a warm-up",
                (long long)main.repeat);
  std::printf("\n");
  if (main.restartTime >= 0)
    std::printf("restarted from checkpoint '%s' at base step %lld\n",
                main.restartFile.c_str(), (long long)main.restartTime);
  if (main.state.stage == Stage::Cut) {
    std::string run = main.repeat == 1 ? ""
                      : main.cutRun == 0
                          ? " (in the warm-up)"
                          : " (in run " + std::to_string(main.cutRun) + " of " +
                                std::to_string(main.repeat) + ")";
    std::printf("%s%s\n", cutText(main.state).c_str(), run.c_str());
  }
  std::printf("\n");
}

void printMetrics(const MainRun &main) {
  row("wall time", formatTime(main.wall));
  row("kernel time", formatTime(main.kernel));
  const sim_metrics &metrics = main.metrics;
  row("launches", std::to_string(metrics.launches) +
                      (metrics.graph_launches
                           ? " (" + std::to_string(metrics.graph_launches) +
                                 " graph replays)"
                           : ""));
  row("host syncs", std::to_string(metrics.host_syncs));
  row("memory", formatBytes(main.memoryBytes) + " (limit " +
                    formatBytes(main.memoryLimit) + ")");
  row("big steps", std::to_string(metrics.big_steps));
  if (main.ranks > 0) {
    // Rank 0's: its exchanges and bytes (under lts a slot exchanges only
    // where a block whose items cross the rank's boundary starts a
    // sub-step, so ranks may differ).
    row("ranks", std::to_string(main.ranks));
    row("halo exchanges", std::to_string(metrics.halo_exchanges) + " (" +
                              formatBytes(metrics.exchanged_bytes) +
                              " sent, rank 0's)");
    row("all-reduces", std::to_string(metrics.allreduces));
  }
  std::string sizes;
  for (size_t m = 1; m < main.counts.histogram.size(); ++m)
    if (int64_t count = main.counts.histogram[m])
      sizes += (sizes.empty() ? "" : "  ") + std::to_string(m) + ": " +
               std::to_string(count);
  row("big-step sizes", sizes.empty() ? "-" : sizes);
  std::string evaluations;
  for (const auto &[component, count] : main.counts.evaluations)
    evaluations += (evaluations.empty() ? "" : "  ") + displayName(component) +
                   " " + std::to_string(count);
  row("evaluations", evaluations.empty() ? "-" : evaluations);
}

/// --profile: the kernels of the last run, the most time first (on CUDA,
/// which does not time launches one by one, the most launches first).
void printProfile(const MainRun &main) {
  const std::vector<RunCounts::Kernel> &kernels = main.counts.kernels;
  std::vector<const RunCounts::Kernel *> launched;
  std::vector<std::string> idle;
  bool timed = true;
  double total = 0;
  for (const RunCounts::Kernel &kernel : kernels) {
    if (kernel.launches == 0) {
      idle.push_back(kernel.name);
      continue;
    }
    launched.push_back(&kernel);
    timed = timed && kernel.seconds >= 0;
    total += std::max(kernel.seconds, 0.0);
  }
  std::stable_sort(launched.begin(), launched.end(),
                   [&](const RunCounts::Kernel *a, const RunCounts::Kernel *b) {
                     return timed ? a->seconds > b->seconds
                                  : a->launches > b->launches;
                   });
  size_t width = 6;
  for (const RunCounts::Kernel *kernel : launched)
    width = std::max(width, kernel->name.size());
  std::printf("\nkernels of the %s:\n", main.repeat > 1 ? "last run" : "run");
  std::printf("  %-*s %10s %12s %7s %12s\n", int(width), "kernel", "launches",
              "time", "share", "per launch");
  for (const RunCounts::Kernel *kernel : launched) {
    std::string time = "-", share = "-", each = "-";
    if (timed) {
      time = formatTime(kernel->seconds);
      char text[32];
      std::snprintf(text, sizeof text, "%.1f%%",
                    total > 0 ? 100 * kernel->seconds / total : 0.0);
      share = text;
      each = formatTime(kernel->seconds / double(kernel->launches));
    }
    std::printf("  %-*s %10lld %12s %7s %12s\n", int(width),
                kernel->name.c_str(), (long long)kernel->launches, time.c_str(),
                share.c_str(), each.c_str());
  }
  if (launched.empty())
    std::printf("  (no kernel launched: the run took no base step)\n");
  if (!timed && !launched.empty())
    std::printf("  (the %s backend times the run, not each launch: time its "
                "kernels with Nsight Systems, nsys profile --stats=true)\n",
                main.backend.c_str());
  if (!idle.empty()) {
    std::string names;
    for (const std::string &name : idle)
      names += (names.empty() ? "" : ", ") + name;
    std::printf("  not launched in the run: %s\n", names.c_str());
  }
}

/// The cost of the output times, the checkpoints.
void printTimeline(const Results &results) {
  const MainRun &main = results.main;
  if (results.outputEvery > 0 || main.cuts > 0) {
    std::string text = std::to_string(main.cuts);
    if (results.outputEvery > 0) {
      int64_t extra = 0, all = 0;
      for (const auto &[component, count] : extraEvaluations(main))
        extra += count;
      for (const auto &[component, count] : main.counts.evaluations)
        all += count;
      char share[32] = "";
      if (all > 0)
        std::snprintf(share, sizeof share, ", %.2g%%",
                      100.0 * double(extra) / double(all));
      text += " (" + std::to_string(main.cutsAtOutputs) +
              " at output times: about " + std::to_string(extra) +
              " more evaluations" + share + ")";
    }
    row("cut big steps", text);
  }
  if (results.outputEvery > 0)
    row("output times",
        std::to_string(results.series.recorded) + " every " +
            std::to_string(results.outputEvery) +
            (results.outputEvery == 1 ? " base step, " : " base steps, ") +
            formatTime(main.outputSeconds) +
            (results.outputFile.empty() ? ""
                                        : " (" + results.outputFile + ")"));
  if (!main.checkpointFile.empty())
    row("checkpoint", main.checkpointTime >= 0
                          ? main.checkpointFile + " at base step " +
                                std::to_string(main.checkpointTime) + " (" +
                                std::to_string(main.checkpointsWritten) +
                                " written)"
                          : main.checkpointFile + " (not written)");
  for (const CheckpointFailure &failure : main.checkpointFailures)
    row("checkpoint", "base step " + std::to_string(failure.time) +
                          " not written: " + failure.why);
}

void printReferenceErrors(const Results &results) {
  if (results.referenceKind.empty())
    return;
  std::string label = "error vs " + results.referenceKind;
  if (results.reference.stage != Stage::Done) {
    row(label, notDone(results.reference, "not compared"));
    return;
  }
  for (const ReferenceError &error : results.errors) {
    std::string name = displayName(error.buffer);
    if (error.available)
      row(label, name + "  max-abs " + scientific(error.norms.maxAbs) +
                     "  rms-rel " + scientific(error.norms.rmsRel));
    else
      row(label, name + "  (no exact solution)");
  }
  for (const TotalError &error : results.totalErrors) {
    std::string name = "total " + displayName(error.total);
    if (error.available)
      row(label, name + "  abs " + scientific(error.absolute) + "  rel " +
                     scientific(error.relative) + "  (" +
                     scientific(error.value, 9) + " vs " +
                     scientific(error.reference, 9) + ")");
    else
      row(label, name + "  (" + error.why + ")");
  }
}

std::string formatTotals(const std::vector<std::string> &names,
                         const std::vector<double> &values) {
  std::string text;
  for (size_t t = 0; t < names.size() && t < values.size(); ++t)
    text += (t ? "  " : "") + displayName(names[t]) + " " +
            scientific(values[t], 9);
  return text;
}

void printTotals(const Results &results) {
  const MainRun &main = results.main;
  // The totals at the output times were printed as the run reached them.
  if (!main.totalNames.empty())
    std::printf("\ntotals  %s\n",
                formatTotals(main.totalNames, main.totals).c_str());
}

void printCheck(const Results &results) {
  if (results.checkState.stage == Stage::NotAsked)
    return;
  const MainRun &main = results.main;
  std::printf("\ncheck against the reference executor (strategy %s, group "
              "size %lld, %lld base step%s)",
              main.strategy.c_str(), (long long)main.groupSize,
              (long long)main.steps, main.steps == 1 ? "" : "s");
  if (!results.check) {
    std::printf(": %s\n", notDone(results.checkState, "not compared").c_str());
    return;
  }
  std::printf(":\n");
  const Check &check = *results.check;
  for (const Check::BufferRow &buffer : check.buffers) {
    std::string nonFinite;
    if (buffer.nonFiniteBackend || buffer.nonFiniteReference)
      nonFinite = "  (non-finite: backend " +
                  std::to_string(buffer.nonFiniteBackend) + ", reference " +
                  std::to_string(buffer.nonFiniteReference) + ")";
    std::printf("  buffer %s  max-abs %s  max-ref %s  rms-rel %s  "
                "tolerance %s  %s%s\n",
                displayName(buffer.buffer).c_str(),
                scientific(buffer.norms.maxAbs).c_str(),
                scientific(buffer.maxReference).c_str(),
                scientific(buffer.norms.rmsRel).c_str(),
                scientific(buffer.tolerance, 1).c_str(),
                buffer.pass ? "pass" : "FAIL", nonFinite.c_str());
  }
  // Every number through scientific(), which writes any NaN as "nan".
  for (const Check::TotalRow &total : check.totals)
    std::printf(
        "  total %s  backend %s  reference %s  limit %s  %s\n",
        displayName(total.total).c_str(), scientific(total.backend, 9).c_str(),
        scientific(total.reference, 9).c_str(),
        scientific(total.limit, 1).c_str(), total.pass ? "pass" : "FAIL");
  if (!check.totalsPerOutputTime.empty() && !main.totalNames.empty()) {
    bool all = std::all_of(check.totalsPerOutputTime.begin(),
                           check.totalsPerOutputTime.end(),
                           [](const Check::TotalRow &row) { return row.pass; });
    std::printf("  totals at %zu output times  %s\n",
                check.totalsPerOutputTime.size() / main.totalNames.size(),
                all ? "pass" : "FAIL");
  }
  auto text = [](int64_t count) {
    return count < 0 ? std::string("-") : std::to_string(count);
  };
  auto same = [](bool equal) { return equal ? "equal" : "DIFFER"; };
  for (const Check::CountRow &row : check.evaluations)
    std::printf("  evaluations %s  backend %s  reference %s  %s\n",
                displayName(row.component).c_str(), text(row.backend).c_str(),
                text(row.reference).c_str(),
                same(row.backend == row.reference));
  std::printf("  big steps  backend %lld  reference %lld  %s\n",
              (long long)check.backend.bigSteps,
              (long long)check.reference.bigSteps,
              same(check.backend.bigSteps == check.reference.bigSteps));
  size_t sizes = std::max(check.backend.histogram.size(),
                          check.reference.histogram.size());
  for (size_t m = 1; m < sizes; ++m) {
    int64_t mine =
        m < check.backend.histogram.size() ? check.backend.histogram[m] : 0;
    int64_t theirs =
        m < check.reference.histogram.size() ? check.reference.histogram[m] : 0;
    if (mine || theirs)
      std::printf("  big-step size %zu  backend %lld  reference %lld  %s\n", m,
                  (long long)mine, (long long)theirs, same(mine == theirs));
  }
  std::string verdict = "pass";
  if (!check.pass()) {
    verdict = "FAIL: ";
    for (size_t i = 0; i < check.failures.size(); ++i)
      verdict += (i ? "; " : "") + check.failures[i];
  }
  std::printf("check: %s\n", verdict.c_str());
}

} // namespace

void printTable(const Results &results) {
  if (results.outputEvery > 0)
    std::printf("\n");
  printHeader(results.main);
  printMetrics(results.main);
  printTimeline(results);
  if (results.profile)
    printProfile(results.main);
  printReferenceErrors(results);
  printTotals(results);
  printCheck(results);
  std::fflush(stdout);
}

//===----------------------------------------------------------------------===//
// JSON
//===----------------------------------------------------------------------===//

namespace {

/// JSON has no NaN or infinity: null.
Json number(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

Json histogram(const std::vector<int64_t> &counts) {
  Json sizes = Json::object();
  for (size_t m = 1; m < counts.size(); ++m)
    sizes[std::to_string(m)] = counts[m];
  return sizes;
}

Json evaluations(const RunCounts &counts) {
  Json components = Json::object();
  for (const auto &[component, count] : counts.evaluations)
    components[component] = count;
  return components;
}

/// Launches and kernel time (null where the backend does not time each
/// launch) of every kernel of the plan, in the plan's order.
Json kernelProfile(const RunCounts &counts) {
  Json kernels = Json::array();
  for (const RunCounts::Kernel &kernel : counts.kernels)
    kernels.push_back({{"name", kernel.name},
                       {"launches", kernel.launches},
                       {"seconds", kernel.seconds >= 0 ? number(kernel.seconds)
                                                       : Json(nullptr)}});
  return kernels;
}

Json totals(const std::vector<std::string> &names,
            const std::vector<double> &values) {
  Json object = Json::object();
  for (size_t t = 0; t < names.size() && t < values.size(); ++t)
    object[names[t]] = number(values[t]);
  return object;
}

Json interruption(const Results &results) {
  if (!results.interrupted())
    return nullptr;
  Json during = nullptr, reached = nullptr, of = nullptr;
  Json skipped = Json::array();
  struct Part {
    const char *name;
    const PartState &state;
  };
  std::string mainName =
      results.main.cutRun == 0 && results.main.repeat > 1 ? "warm-up" : "run";
  // In the order they run.
  Part parts[] = {{mainName.c_str(), results.main.state},
                  {"reference", results.reference},
                  {"check", results.checkState}};
  for (const Part &part : parts) {
    if (part.state.stage == Stage::Cut) {
      during = part.name;
      reached = part.state.reached;
      of = part.state.of;
      // The measured runs after a cut one (or after the warm-up) never ran.
      int64_t next = results.main.cutRun + 1, last = results.main.repeat;
      if (&part.state == &results.main.state && results.main.repeat > 1 &&
          next <= last)
        skipped.push_back(next == last ? "run " + std::to_string(last)
                                       : "runs " + std::to_string(next) +
                                             " to " + std::to_string(last));
    } else if (part.state.stage == Stage::Skipped) {
      skipped.push_back(part.name);
    }
  }
  Json object;
  object["signal"] = signalName(results.signal);
  object["during"] = during;
  if (results.main.state.stage == Stage::Cut && results.main.repeat > 1)
    object["run"] = results.main.cutRun;
  object["base_step"] = reached;
  object["of"] = of;
  object["skipped"] = skipped;
  return object;
}

Json checkJson(const Results &results) {
  if (!results.check)
    return nullptr;
  const Check &check = *results.check;
  const MainRun &main = results.main;
  Json object;
  object["strategy"] = main.strategy;
  object["group_size"] = main.groupSize;
  object["steps"] = main.steps;
  object["pass"] = check.pass();
  Json totalRows = Json::object();
  for (const Check::TotalRow &row : check.totals)
    totalRows[row.total] = {{"backend", number(row.backend)},
                            {"reference", number(row.reference)},
                            {"limit", number(row.limit)},
                            {"pass", row.pass}};
  object["totals"] = totalRows;
  Json buffers = Json::object();
  for (const Check::BufferRow &row : check.buffers)
    buffers[row.buffer] = {{"max_abs", number(row.norms.maxAbs)},
                           {"max_reference", number(row.maxReference)},
                           {"rms_rel", number(row.norms.rmsRel)},
                           {"tolerance", number(row.tolerance)},
                           {"limit", number(row.limit)},
                           {"non_finite",
                            {{"backend", row.nonFiniteBackend},
                             {"reference", row.nonFiniteReference}}},
                           {"pass", row.pass}};
  object["buffers"] = buffers;
  object["evaluations"] = {{"backend", evaluations(check.backend)},
                           {"reference", evaluations(check.reference)},
                           {"equal", check.evaluationsEqual()}};
  object["big_steps"] = {
      {"backend", check.backend.bigSteps},
      {"reference", check.reference.bigSteps},
      {"equal", check.backend.bigSteps == check.reference.bigSteps}};
  object["big_step_histogram"] = {
      {"backend", histogram(check.backend.histogram)},
      {"reference", histogram(check.reference.histogram)},
      {"equal", check.backend.histogram == check.reference.histogram}};
  object["failures"] = check.failures;
  return object;
}

Json totalErrorsJson(const Results &results) {
  if (results.referenceKind.empty())
    return nullptr;
  Json object = Json::object();
  if (results.reference.stage == Stage::Done)
    for (const TotalError &error : results.totalErrors)
      if (error.available)
        object[error.total] = {{"value", number(error.value)},
                               {"reference", number(error.reference)},
                               {"abs", number(error.absolute)},
                               {"rel", number(error.relative)}};
  return object;
}

Json initCheckJson(const InitCheckReport &report) {
  if (!report.ran)
    return {{"ran", false}, {"skipped", report.skipped}};
  Json buffers = Json::object();
  for (const InitCheckReport::Row &row : report.rows)
    buffers[row.buffer] = {{"component", row.component},
                           {"consistent", row.consistent()},
                           {"max_abs", number(row.maxAbs)},
                           {"item", row.item},
                           {"lane", row.lane},
                           {"initial", number(row.initial)},
                           {"evaluated", number(row.evaluated)},
                           {"scale", number(row.scale)},
                           {"tolerance", number(row.tolerance)},
                           {"count", row.count},
                           {"non_finite", row.nonFinite},
                           {"interpolated", row.interpolated}};
  return {{"ran", true},
          {"items", report.items},
          {"range", report.range},
          {"buffers", buffers}};
}

Json nonFiniteJson(const Results &results) {
  Json buffers = Json::object(), totals = Json::array();
  for (const NonFiniteValues &found : results.nonFinite) {
    if (found.total)
      totals.push_back(found.name);
    else
      buffers[found.name] = {
          {"count", found.count}, {"item", found.item}, {"lane", found.lane}};
  }
  return {{"buffers", buffers}, {"totals", totals}};
}

Json dumpJson(const Results &results) {
  if (results.dumpDir.empty())
    return nullptr;
  Json files = Json::array();
  auto name = [](const std::string &file) {
    return file.empty() ? Json(nullptr) : Json(file);
  };
  for (const DumpFiles &dump : results.dumpFiles)
    files.push_back({{"buffer", dump.buffer},
                     {"state", name(dump.state)},
                     {"reference", name(dump.reference)},
                     {"check", name(dump.check)}});
  return {{"directory", results.dumpDir}, {"files", files}};
}

} // namespace

std::string toJson(const Results &results) {
  const MainRun &main = results.main;
  Json json;
  json["scene"] = main.scene;
  json["strategy"] = main.strategy;
  json["backend"] = main.backend;
  json["device"] = main.device;
  json["backend_note"] = main.backendNote;
  json["range"] = main.range;
  json["dt"] = number(main.dt);
  // The values the run used, so that a report says which run it was.
  json["params"] = Json::object();
  for (const auto &[name, value] : main.params)
    json["params"][name] = value;
  json["group_size"] = main.groupSize;
  json["subnormals"] = main.flushSubnormals ? "flush-to-zero" : "ieee";
  json["steps"] = main.steps;
  json["steps_done"] =
      main.state.stage == Stage::Cut ? main.state.reached : main.steps;
  json["repeat"] = main.repeat;
  json["interrupted"] = results.interrupted();
  json["interruption"] = interruption(results);
  json["max_memory"] = main.maxMemory;
  json["memory_bytes"] = main.memoryBytes;
  json["memory_limit"] = main.memoryLimit;
  json["wall_seconds"] = number(main.wall);
  json["kernel_seconds"] = number(main.kernel);
  json["wall_seconds_runs"] = Json::array();
  for (double wall : main.walls)
    json["wall_seconds_runs"].push_back(number(wall));
  json["kernel_seconds_runs"] = Json::array();
  for (double kernel : main.kernels)
    json["kernel_seconds_runs"].push_back(number(kernel));
  json["launches"] = main.metrics.launches;
  json["graph_launches"] = main.metrics.graph_launches;
  json["host_syncs"] = main.metrics.host_syncs;
  json["big_steps"] = main.metrics.big_steps;
  if (main.ranks > 0) {
    json["ranks"] = main.ranks;
    json["halo_exchanges"] = main.metrics.halo_exchanges;
    json["exchanged_bytes"] = main.metrics.exchanged_bytes;
    json["allreduces"] = main.metrics.allreduces;
  }
  json["big_step_histogram"] = histogram(main.counts.histogram);
  json["evaluations"] = evaluations(main.counts);
  json["kernels"] = kernelProfile(main.counts);
  json["totals"] = totals(main.totalNames, main.totals);
  json["cut_big_steps"] = main.cuts;
  if (results.outputEvery > 0) {
    const Series &outputs = results.series;
    Json series = Json::array();
    for (size_t k = 0; k < outputs.size(); ++k) {
      Json point;
      point["T"] = outputs.times[k];
      for (size_t t = 0;
           t < main.totalNames.size() && t < outputs.totals[k].size(); ++t)
        point[main.totalNames[t]] = number(outputs.totals[k][t]);
      series.push_back(point);
    }
    json["totals_per_output_time"] = series;
    Json extra = Json::object();
    for (const auto &[component, count] : extraEvaluations(main))
      extra[component] = count;
    json["output"] = {{"every", results.outputEvery},
                      {"file", results.outputFile.empty()
                                   ? Json(nullptr)
                                   : Json(results.outputFile)},
                      {"times", outputs.times},
                      {"cut_big_steps", main.cutsAtOutputs},
                      {"extra_evaluations_estimate", extra},
                      {"seconds", number(main.outputSeconds)}};
  } else {
    json["totals_per_output_time"] = nullptr;
    json["output"] = nullptr;
  }
  Json checkpointFailures = Json::array();
  for (const CheckpointFailure &failure : main.checkpointFailures)
    checkpointFailures.push_back(
        {{"base_step", failure.time}, {"error", failure.why}});
  json["checkpoint"] =
      main.checkpointFile.empty()
          ? Json(nullptr)
          : Json{{"file", main.checkpointFile},
                 {"every", main.checkpointEvery ? Json(main.checkpointEvery)
                                                : Json(nullptr)},
                 {"written", main.checkpointsWritten},
                 {"base_step", main.checkpointTime >= 0
                                   ? Json(main.checkpointTime)
                                   : Json(nullptr)},
                 {"failed", checkpointFailures}};
  json["restart"] =
      main.restartTime >= 0
          ? Json{{"file", main.restartFile}, {"base_step", main.restartTime}}
          : Json(nullptr);
  json["reference"] = results.referenceKind.empty()
                          ? Json(nullptr)
                          : Json(results.referenceKind);
  Json errors = Json::object();
  if (results.reference.stage == Stage::Done)
    for (const ReferenceError &error : results.errors)
      if (error.available)
        errors[error.buffer] = {{"max_abs", number(error.norms.maxAbs)},
                                {"rms_rel", number(error.norms.rmsRel)}};
  json["error"] = errors;
  json["error_totals"] = totalErrorsJson(results);
  json["check"] = checkJson(results);
  json["init_check"] = initCheckJson(results.initCheck);
  json["non_finite"] = nonFiniteJson(results);
  json["dump"] = dumpJson(results);
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

} // namespace simrun
