//===- Safety.cpp - sim-run's warnings about a scene and a run ------------===//

#include "Safety.h"

#include <cmath>
#include <cstdio>

namespace simrun {

namespace {

/// "item 3" or "item 3, lane 1".
std::string itemText(int64_t item, int32_t lane, int32_t lanes) {
  std::string text = "item " + std::to_string(item);
  if (lanes > 1)
    text += ", lane " + std::to_string(lane);
  return text;
}

/// "nan", "inf", "-inf" or the number.
std::string valueText(double value) {
  if (std::isnan(value))
    return "nan";
  if (std::isinf(value))
    return value > 0 ? "inf" : "-inf";
  return scientific(value, 9);
}

std::string plural(int64_t count, const char *one, const char *many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

} // namespace

InitCheckReport checkInit(sim_session *session, const sim_bundle *bundle) {
  InitCheckReport report;
  report.range = sim_session_range(session);
  if (!sim_bundle_has_reference(bundle)) {
    report.skipped = "the bundle has no reference functions";
    return report;
  }
  int32_t count = 0;
  if (sim_session_check_init(session, 0, 0, &count) != SIM_OK) {
    report.skipped = sim_last_error();
    return report;
  }
  report.ran = true;
  for (int32_t i = 0; i < count; ++i) {
    sim_init_check found;
    if (sim_session_init_check(session, i, &found) != SIM_OK)
      continue;
    InitCheckReport::Row row;
    row.buffer = found.buffer;
    row.component = found.component;
    for (int32_t b = 0; b < sim_bundle_num_buffers(bundle); ++b) {
      sim_buffer_info info;
      if (sim_bundle_buffer(bundle, b, &info) == SIM_OK &&
          row.buffer == info.name)
        row.lanes = info.lanes;
    }
    row.maxAbs = found.max_abs;
    row.initial = found.initial;
    row.evaluated = found.evaluated;
    row.scale = found.scale;
    row.tolerance = found.tolerance;
    row.item = found.item;
    row.lane = found.lane;
    row.count = found.count;
    row.nonFinite = found.non_finite;
    row.nonFiniteItem = found.non_finite_item;
    row.interpolated = found.interpolated;
    report.items = found.items;
    report.rows.push_back(row);
  }
  return report;
}

std::vector<std::string> initCheckMessages(const InitCheckReport &report) {
  std::vector<std::string> messages;
  if (!report.ran) {
    if (report.skipped != "the bundle has no reference functions" &&
        report.skipped != "--no-init-check")
      messages.push_back("sim-run: note: the init check did not run: " +
                         report.skipped);
    return messages;
  }
  if (report.items < report.range) {
    int64_t tail = report.items / 2;
    messages.push_back("sim-run: note: the init check evaluated " +
                       std::to_string(report.items) + " of the " +
                       std::to_string(report.range) + " items (the first " +
                       std::to_string(report.items - tail) + " and the last " +
                       std::to_string(tail) + ")");
  }
  for (const InitCheckReport::Row &row : report.rows) {
    std::string buffer = "'" + displayName(row.buffer) + "'";
    std::string component = "'" + displayName(row.component) + "'";
    if (!row.consistent()) {
      char tolerance[32];
      std::snprintf(tolerance, sizeof tolerance, "%.1e", row.tolerance);
      std::string message =
          "sim-run: warning: the init of buffer " + buffer +
          " disagrees with its writer " + component +
          " evaluated with n = 0 at t = 0\n  largest difference " +
          scientific(row.maxAbs) + " at " +
          itemText(row.item, row.lane, row.lanes) + " (init " +
          valueText(row.initial) + ", evaluate " + valueText(row.evaluated) +
          "); " + std::to_string(row.count) + " of " +
          plural(report.items * row.lanes, "value", "values") +
          " differ by more than " + tolerance + " of the largest, " +
          scientific(row.scale);
      if (row.interpolated)
        message += "\n  hip and hip-cache interpolate from the init in the "
                   "first big step: make the init what " +
                   component + " computes";
      messages.push_back(message);
    }
    if (row.nonFinite)
      messages.push_back(
          "sim-run: note: the init check skips " +
          plural(row.nonFinite, "value", "values") + " of buffer " + buffer +
          ": its init or " + component +
          " evaluated with n = 0 at t = 0 is NaN or infinite there (the "
          "first at item " +
          std::to_string(row.nonFiniteItem) + "), as when a body divides by n");
  }
  return messages;
}

std::optional<NonFiniteValues> findNonFinite(const Buffer &buffer) {
  NonFiniteValues found;
  found.name = buffer.name;
  found.lanes = buffer.lanes;
  for (size_t i = 0; i < buffer.values(); ++i) {
    double value = buffer.at(i);
    if (std::isfinite(value))
      continue;
    if (found.count++ == 0) {
      found.item = int64_t(i / size_t(buffer.lanes));
      found.lane = int32_t(i % size_t(buffer.lanes));
      found.value = value;
    }
  }
  if (!found.count)
    return std::nullopt;
  return found;
}

std::vector<NonFiniteValues>
findNonFiniteTotals(const std::vector<std::string> &names,
                    const std::vector<double> &values) {
  std::vector<NonFiniteValues> found;
  for (size_t t = 0; t < names.size() && t < values.size(); ++t)
    if (!std::isfinite(values[t])) {
      NonFiniteValues total;
      total.name = names[t];
      total.total = true;
      total.count = 1;
      total.value = values[t];
      found.push_back(total);
    }
  return found;
}

std::string nonFiniteWarning(const NonFiniteValues &found) {
  std::string name = "'" + displayName(found.name) + "'";
  if (found.total)
    return "sim-run: warning: total " + name +
           " is not finite at the end of the run (" + valueText(found.value) +
           ")";
  return "sim-run: warning: buffer " + name + " holds " +
         plural(found.count, "NaN or infinite value",
                "NaN or infinite values") +
         " at the end of the run (the first: " + valueText(found.value) +
         " at " + itemText(found.item, found.lane, found.lanes) + ")";
}

std::string nonFiniteStateText(const NonFiniteValues &found) {
  return "buffer '" + displayName(found.name) + "' holds " +
         plural(found.count, "NaN or infinite value",
                "NaN or infinite values") +
         " (the first: " + valueText(found.value) + " at " +
         itemText(found.item, found.lane, found.lanes) + ")";
}

std::string exactNonFiniteWarning(const NonFiniteValues &found) {
  return "sim-run: warning: the exact solution of buffer '" +
         displayName(found.name) + "' holds " +
         plural(found.count, "NaN or infinite value",
                "NaN or infinite values") +
         " at the end of the run (the first: " + valueText(found.value) +
         " at " + itemText(found.item, found.lane, found.lanes) +
         "), so its errors are not finite; the scene's exact body does not "
         "hold at these settings";
}

} // namespace simrun
