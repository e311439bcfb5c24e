//===- Executor.cpp - range, dt and parameters of a session ---------------===//

#include "Executor.h"
#include "Error.h"

#include <limits>

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

Settings::Settings(const Scene &scene)
    : scene(&scene), range(scene.range), dt(scene.dt) {
  for (const SceneParam &param : scene.params)
    params.push_back(param.defaultValue);
}

bool Settings::set(const std::string &name, const std::string &text,
                   const std::function<void(int64_t)> &checkRange) {
  if (name == "range") {
    Value value = parseValue(ScalarType::I64, text, "range");
    if (value.i < 1)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "range: " + text + " is not a positive number of items");
    checkRange(value.i);
    bool changed = value.i != range;
    range = value.i;
    return changed;
  }
  if (name == "dt") {
    dt = parseValue(dt.type, text, "dt");
    return false;
  }
  int index = scene->findParam(name);
  if (index < 0) {
    std::vector<std::string> names;
    for (const SceneParam &param : scene->params)
      names.push_back(param.name);
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "'" + name + "' is not range, dt or a parameter of scene '" +
             scene->name + "' (parameters: " + listNames(names) + ")");
  }
  params[index] =
      parseValue(scene->params[index].type, text, "parameter '" + name + "'");
  return false;
}

std::string Settings::get(const std::string &name) const {
  if (name == "range")
    return std::to_string(range);
  if (name == "dt")
    return dt.text();
  int index = scene->findParam(name);
  if (index < 0)
    fail(SIM_ERROR_INVALID_ARGUMENT, "'" + name +
                                         "' is not range, dt or a parameter "
                                         "of scene '" +
                                         scene->name + "'");
  return params[index].text();
}

} // namespace sim::rt
