//===- Series.cpp - the output times of one run ---------------------------===//

#include "Series.h"

#include "Output.h"
#include "Report.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace simrun {

void Series::add(int64_t time, const std::vector<double> &rowTotals,
                 const std::vector<Buffer> &rowValues,
                 const std::vector<std::optional<Buffer>> &references) {
  ++recorded;
  if (!keepRows) {
    // Nothing reads the earlier rows: the table printed them.
    times.clear();
    totals.clear();
    errors.clear();
  }
  times.push_back(time);
  totals.push_back(rowTotals);
  std::vector<ErrorNorms> rowErrors(buffers.size());
  values.resize(buffers.size());
  exact.resize(buffers.size());
  for (size_t b = 0; b < buffers.size(); ++b) {
    const std::optional<Buffer> &reference =
        b < references.size() ? references[b] : std::nullopt;
    if (buffers[b].hasReference && reference && b < rowValues.size())
      rowErrors[b] = compare(rowValues[b], *reference);
    if (!keepValues)
      continue;
    if (b < rowValues.size())
      values[b].append(rowValues[b].bytes.begin(), rowValues[b].bytes.end());
    if (buffers[b].hasExact && reference)
      exact[b].append(reference->bytes.begin(), reference->bytes.end());
  }
  errors.push_back(std::move(rowErrors));
}

void Series::clear() {
  recorded = 0;
  times.clear();
  totals.clear();
  errors.clear();
  values.clear();
  exact.clear();
}

int64_t rowBytes(const Series &series) {
  int64_t bytes = 0;
  if (!series.keepValues)
    return 0;
  for (const Series::Column &column : series.buffers) {
    int64_t one = series.range * column.lanes * column.scalarBytes;
    bytes += one * (column.hasExact ? 2 : 1);
  }
  return bytes;
}

int64_t rowOverheadBytes(size_t totals, size_t buffers, bool json, bool check) {
  int64_t t = int64_t(totals), b = int64_t(buffers);
  // The time, and two vectors with their heap blocks (totals, errors).
  int64_t bytes = 8 + 2 * (24 + 16) + 8 * t + 16 * b;
  // nlohmann's tree: an element of "times", an object (a std::map) in
  // "totals_per_output_time" with a node per key ("T" and every total);
  // then the text, indented, with up to 24 characters per number.
  if (json)
    bytes += 16 + 64 + 128 * (1 + t) + 64 + 64 * (1 + t);
  // The reference executor's totals at the output time, and a compared
  // row (names, values, limit) per total.
  if (check)
    bytes += 8 + 24 + 16 + 8 * t + 128 * t;
  return bytes;
}

std::string seriesMemoryError(const std::string &what, int64_t times,
                              int64_t row, double memory) {
  double needed = double(row) * double(times);
  if (row <= 0 || memory <= 0 || needed <= memory / 2)
    return "";
  return what + ": " + std::to_string(times) + " output times of " +
         formatBytes(row) + " each take " +
         formatBytes(int64_t(std::min(needed, 9e18))) +
         ", more than half of this machine's memory (" +
         formatBytes(int64_t(memory)) + "); choose a larger --output-every";
}

//===----------------------------------------------------------------------===//
// The table
//===----------------------------------------------------------------------===//

namespace {

/// The columns after t and time: a title and a width each.
struct Layout {
  std::vector<std::pair<std::string, int>> totals, errors;
};

Layout layoutOf(const Series &series) {
  Layout layout;
  for (const std::string &name : series.totalNames) {
    std::string title = displayName(name);
    layout.totals.emplace_back(title, std::max<int>(17, int(title.size()) + 2));
  }
  for (const Series::Column &column : series.buffers) {
    if (!column.hasReference)
      continue;
    for (const char *norm : {" max-abs", " rms-rel"}) {
      std::string title = displayName(column.name) + norm;
      layout.errors.emplace_back(title,
                                 std::max<int>(11, int(title.size()) + 2));
    }
  }
  return layout;
}

} // namespace

void printSeriesHeader(const Series &series) {
  Layout layout = layoutOf(series);
  std::string errors;
  if (!series.referenceKind.empty())
    errors = ", error vs " + series.referenceKind;
  std::printf("output every %lld base step%s (t: base step, time: t * dt%s):\n",
              (long long)series.every, series.every == 1 ? "" : "s",
              errors.c_str());
  std::string line =
      "  " + std::string(10, ' ') + "t" + std::string(13, ' ') + "time";
  for (const auto &[title, width] : layout.totals)
    line += std::string(size_t(width) - title.size(), ' ') + title;
  for (const auto &[title, width] : layout.errors)
    line += std::string(size_t(width) - title.size(), ' ') + title;
  std::printf("%s\n  %s\n", line.c_str(),
              std::string(line.size() - 2, '-').c_str());
  std::fflush(stdout);
}

void printSeriesRow(const Series &series, size_t row) {
  Layout layout = layoutOf(series);
  std::string line;
  char text[64];
  // Numbers through scientific(), which writes any NaN as "nan" (printf
  // writes "-nan" for one with its sign bit set).
  std::snprintf(text, sizeof text, "  %11lld  %15s",
                (long long)series.times[row],
                scientific(double(series.times[row]) * series.dt, 9).c_str());
  line += text;
  for (size_t t = 0; t < layout.totals.size(); ++t) {
    std::snprintf(text, sizeof text, "%*s", layout.totals[t].second,
                  scientific(series.totals[row][t], 9).c_str());
    line += text;
  }
  size_t column = 0;
  for (size_t b = 0; b < series.buffers.size(); ++b) {
    if (!series.buffers[b].hasReference)
      continue;
    for (double value :
         {series.errors[row][b].maxAbs, series.errors[row][b].rmsRel}) {
      std::snprintf(text, sizeof text, "%*s", layout.errors[column].second,
                    scientific(value, 3).c_str());
      line += text;
      ++column;
    }
  }
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

//===----------------------------------------------------------------------===//
// The .npz
//===----------------------------------------------------------------------===//

std::vector<NpzArray> seriesArrays(const Series &series,
                                   const std::string &scene,
                                   const std::string &strategy,
                                   const std::string &backend,
                                   std::vector<std::string> &storage) {
  int64_t rows = int64_t(series.size());
  // Every piece the arrays point to lives in `storage` (reserved, so that
  // it never moves) or in `series`.
  storage.clear();
  storage.reserve(16 + 2 * series.totalNames.size() +
                  8 * series.buffers.size());
  auto keep = [&](std::string text) -> std::string_view {
    storage.push_back(std::move(text));
    return storage.back();
  };
  std::vector<NpzArray> arrays;
  auto add = [&](const std::string &key, const std::string &descr,
                 std::vector<int64_t> shape,
                 std::vector<std::string_view> pieces) {
    arrays.push_back({key, npyHeader(descr, shape), std::move(pieces)});
  };

  std::string t, time;
  for (int64_t at : series.times) {
    double seconds = double(at) * series.dt;
    t.append(reinterpret_cast<const char *>(&at), sizeof at);
    time.append(reinterpret_cast<const char *>(&seconds), sizeof seconds);
  }
  add("t", "<i8", {rows}, {keep(t)});
  add("time", "<f8", {rows}, {keep(time)});

  std::vector<std::string> names;
  for (const Series::Column &column : series.buffers)
    names.push_back(column.name);
  std::vector<std::string> stems = dumpStems(names);
  if (series.keepValues) {
    for (size_t b = 0; b < series.buffers.size(); ++b) {
      const Series::Column &column = series.buffers[b];
      std::vector<int64_t> shape = {rows, series.range};
      if (column.lanes > 1)
        shape.push_back(column.lanes);
      std::string descr = floatDescr(column.scalarBytes);
      add("buffer/" + stems[b], descr, shape,
          {b < series.values.size() ? std::string_view(series.values[b])
                                    : std::string_view()});
      if (column.hasExact)
        add("exact/" + stems[b], descr, shape,
            {b < series.exact.size() ? std::string_view(series.exact[b])
                                     : std::string_view()});
    }
  }

  std::vector<std::string> totalStems = dumpStems(series.totalNames);
  for (size_t k = 0; k < series.totalNames.size(); ++k) {
    std::string data;
    for (const std::vector<double> &row : series.totals)
      data.append(reinterpret_cast<const char *>(&row[k]), sizeof(double));
    add("total/" + totalStems[k], "<f8", {rows}, {keep(data)});
  }

  for (size_t b = 0; b < series.buffers.size(); ++b) {
    if (!series.buffers[b].hasReference)
      continue;
    std::string maxAbs, rmsRel;
    for (const std::vector<ErrorNorms> &row : series.errors) {
      maxAbs.append(reinterpret_cast<const char *>(&row[b].maxAbs),
                    sizeof(double));
      rmsRel.append(reinterpret_cast<const char *>(&row[b].rmsRel),
                    sizeof(double));
    }
    add("error/" + stems[b] + "/max_abs", "<f8", {rows}, {keep(maxAbs)});
    add("error/" + stems[b] + "/rms_rel", "<f8", {rows}, {keep(rmsRel)});
  }

  for (const auto &[key, text] :
       {std::pair<const char *, const std::string &>{"meta/scene", scene},
        {"meta/strategy", strategy},
        {"meta/backend", backend}}) {
    std::string file = npyString(text);
    // npyString made a whole file: split it into header and data.
    size_t header =
        10 + (size_t(uint8_t(file[8])) | size_t(uint8_t(file[9])) << 8);
    arrays.push_back(
        {key, file.substr(0, header), {keep(file.substr(header))}});
  }
  return arrays;
}

} // namespace simrun
