//===- Executor.cpp - range, dt and parameters of a session ---------------===//

#include "Executor.h"
#include "Error.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <unistd.h>

namespace sim::rt {

std::string listNames(const std::vector<std::string> &names) {
  std::string list;
  for (const std::string &name : names)
    list += (list.empty() ? "" : ", ") + name;
  return list.empty() ? "none" : list;
}

int64_t runEnd(int64_t begin, int64_t steps) {
  if (steps < 0)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "cannot run " + std::to_string(steps) + " base steps");
  if (steps > std::numeric_limits<int64_t>::max() - begin)
    fail(SIM_ERROR_INVALID_ARGUMENT, "cannot run " + std::to_string(steps) +
                                         " base steps from " +
                                         std::to_string(begin));
  return begin + steps;
}

int64_t runPause(int64_t begin, int64_t steps, int64_t pause) {
  if (pause >= steps)
    return begin + steps;
  if (pause < 1)
    fail(SIM_ERROR_INVALID_ARGUMENT, "cannot pause a run after " +
                                         std::to_string(pause) +
                                         " base steps (at least 1)");
  return begin + pause;
}

int64_t saturatingMul(int64_t a, int64_t b) {
  int64_t product;
  if (a < 0 || b < 0 || __builtin_mul_overflow(a, b, &product))
    return std::numeric_limits<int64_t>::max();
  return product;
}

int64_t saturatingAdd(int64_t a, int64_t b) {
  int64_t sum;
  if (a < 0 || b < 0 || __builtin_add_overflow(a, b, &sum))
    return std::numeric_limits<int64_t>::max();
  return sum;
}

int64_t physicalMemoryBytes() {
  long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0)
    return 0;
  return saturatingMul(pages, pageSize);
}

std::string formatBytes(int64_t bytes) {
  if (bytes == std::numeric_limits<int64_t>::max())
    return "more than 8 EiB";
  const char *units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024)
    return std::to_string(bytes) + " bytes";
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

void Executor::setMemoryLimit(int64_t requested, int64_t deviceBytes) {
  if (requested < 0)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "max_memory " + std::to_string(requested) + " is negative");
  memoryLimit_ = requested         ? requested
                 : deviceBytes > 0 ? deviceBytes / 4 * 3
                                   : std::numeric_limits<int64_t>::max();
}

void Executor::checkMemory(int64_t range, const std::string &what) const {
  int64_t needed = memoryBytes(range);
  if (needed <= memoryLimit_)
    return;
  fail(SIM_ERROR_MEMORY_LIMIT,
       what + " needs " + formatBytes(needed) + " for the state of scene '" +
           scene().name + "', more than the limit of " +
           formatBytes(memoryLimit_) +
           " (a smaller range, or a larger max_memory / --max-memory)");
}

void Executor::failInterrupted(int64_t begin, int64_t reached,
                               int64_t end) const {
  fail(SIM_ERROR_INTERRUPTED, "interrupted at base step " +
                                  std::to_string(reached) + " of a run from " +
                                  std::to_string(begin) + " to " +
                                  std::to_string(end));
}

Settings::Settings(const Bundle &bundle)
    : bundle(&bundle), range(bundle.scene().range),
      dt(Value::of(*bundle.scene().dt)) {
  for (const auto &param : bundle.scene().params)
    params.push_back(Value::of(*param->value));
}

bool Settings::set(const std::string &name, const std::string &text,
                   const std::function<void(int64_t)> &checkRange) {
  if (name == "range") {
    Value value = parseValue(ScalarType::I64, text, "range");
    if (value.i < 1 || value.i > kMaxRange)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "range: " + text + " is not a number of items from 1 to 2^40");
    checkRange(value.i);
    bool changed = value.i != range;
    range = value.i;
    return changed;
  }
  if (name == "dt") {
    Value value = parseValue(dt.type, text, "dt");
    double asUsed =
        value.type == ScalarType::F32 ? double(float(value.f)) : value.f;
    if (!std::isfinite(asUsed) || !(asUsed > 0))
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "dt: " + text + " is not a positive finite time step");
    // A subnormal dt (below 2^-126 in f32, 2^-1022 in f64) has fewer
    // significant bits than its type, t + dt is t once t is a few steps
    // in, and a bundle compiled with --sim-ftz computes with 0: the run
    // would advance nothing.
    bool normal = value.type == ScalarType::F32 ? std::isnormal(float(value.f))
                                                : std::isnormal(value.f);
    if (!normal)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "dt: " + text + " is subnormal in " + scalarTypeName(value.type) +
               " (below " +
               (value.type == ScalarType::F32 ? "1.17549435e-38"
                                              : "2.2250738585072014e-308") +
               ", the smallest normal value): too small for t + dt to "
               "advance t; give a positive normal time step");
    dt = value;
    return false;
  }
  const schema::SceneT &scene = bundle->scene();
  if (name == "max_steps") {
    // Compiled into the plans (their step caps, clocks and histograms):
    // only the value the bundle has is accepted.
    Value value = parseValue(ScalarType::I32, text, "max_steps");
    if (value.i == scene.max_steps)
      return false;
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "max_steps is fixed when a scene is compiled (bundle '" +
             bundle->name + "' has " + std::to_string(scene.max_steps) +
             "): compile the scene with sim-translate --sim-to-bundle "
             "--sim-set-params=max_steps=" +
             text + ", or give sim-run the .mlir scene");
  }
  int index = bundle->findParam(name);
  if (index < 0) {
    std::vector<std::string> names;
    for (const auto &param : scene.params)
      names.push_back(param->name);
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "'" + name + "' is not range, dt or a parameter of scene '" +
             scene.name + "' (parameters: " + listNames(names) + ")");
  }
  params[index] = parseValue(scene.params[index]->value->type(), text,
                             "parameter '" + name + "'");
  return false;
}

std::string Settings::get(const std::string &name) const {
  if (name == "range")
    return std::to_string(range);
  if (name == "dt")
    return dt.text();
  if (name == "max_steps")
    return std::to_string(bundle->scene().max_steps);
  int index = bundle->findParam(name);
  if (index < 0)
    fail(SIM_ERROR_INVALID_ARGUMENT, "'" + name +
                                         "' is not range, dt or a parameter "
                                         "of scene '" +
                                         bundle->scene().name + "'");
  return params[index].text();
}

} // namespace sim::rt
