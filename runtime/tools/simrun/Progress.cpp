//===- Progress.cpp - sim-run's progress line -----------------------------===//

#include "Progress.h"

#include <cmath>

namespace simrun {

std::string formatRate(double perSecond) {
  const char *suffixes[] = {"", "k", "M", "G", "T"};
  int suffix = 0;
  while (perSecond >= 999.5 && suffix < 4) {
    perSecond /= 1000;
    ++suffix;
  }
  char text[32];
  int decimals = suffix == 0 || perSecond >= 99.95 ? 0
                 : perSecond >= 9.995              ? 1
                                                   : 2;
  std::snprintf(text, sizeof text, "%.*f%s", decimals, perSecond,
                suffixes[suffix]);
  return text;
}

std::string formatEta(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0)
    return "ETA -";
  long long whole = (long long)std::ceil(seconds);
  char text[48];
  if (whole < 60)
    std::snprintf(text, sizeof text, "ETA %lld s", whole);
  else if (whole < 3600)
    std::snprintf(text, sizeof text, "ETA %lld min %02lld s", whole / 60,
                  whole % 60);
  else
    std::snprintf(text, sizeof text, "ETA %lld h %02lld min", whole / 3600,
                  whole / 60 % 60);
  return text;
}

std::string progressLine(const std::string &label, int64_t done, int64_t total,
                         double seconds, int64_t started) {
  double rate = seconds > 0 ? double(done - started) / seconds : 0;
  double left = rate > 0 ? double(total - done) / rate : NAN;
  double percent = total ? 100.0 * double(done) / double(total) : 100.0;
  char text[160];
  std::snprintf(text, sizeof text,
                "base step %lld of %lld (%.0f%%), %s base steps/s, ",
                (long long)done, (long long)total, std::floor(percent),
                formatRate(rate).c_str());
  return "sim-run: " + label + text + formatEta(left);
}

void Progress::begin(sim_session *session, std::string runLabel) {
  label = std::move(runLabel);
  start = std::chrono::steady_clock::now();
  last = 0;
  shown = false;
  offset = whole = 0;
  started = -1;
  sim_session_set_progress(session, enabled ? &Progress::callback : nullptr,
                           this);
}

void Progress::resume(sim_session *session, int64_t from, int64_t end) {
  offset = from;
  whole = end;
  if (started < 0)
    started = from;
  sim_session_set_progress(session, enabled ? &Progress::callback : nullptr,
                           this);
}

void Progress::pause() {
  if (shown && terminal) {
    std::fputs("\r\033[K", out);
    std::fflush(out);
  }
}

void Progress::callback(void *user, int64_t done, int64_t total) {
  auto *self = static_cast<Progress *>(user);
  double seconds = std::chrono::duration<double>(
                       std::chrono::steady_clock::now() - self->start)
                       .count();
  self->report(done, total, seconds);
}

void Progress::report(int64_t done, int64_t total, double seconds) {
  if (!enabled || seconds < kProgressDelay ||
      (shown && seconds - last <
                    (terminal ? kProgressTerminalPeriod : kProgressLogPeriod)))
    return;
  last = seconds;
  shown = true;
  int64_t since = 0;
  if (whole > 0) {
    done += offset;
    total = whole;
    since = started;
  }
  std::string line = progressLine(label, done, total, seconds, since);
  if (terminal)
    std::fprintf(out, "\r%s\033[K", line.c_str());
  else
    std::fprintf(out, "%s\n", line.c_str());
  std::fflush(out);
}

void Progress::end() {
  if (shown && terminal) {
    std::fputs("\r\033[K", out);
    std::fflush(out);
  }
  shown = false;
}

} // namespace simrun
