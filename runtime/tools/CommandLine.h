//===- CommandLine.h - What sim's programs share of CLI11 -------*- C++ -*-===//
//
// sim-run and the hand-written baselines (bench/cpu, bench/cuda) declare
// their options with CLI11 and read the same way to a user: LLVM's help
// layout ("OVERVIEW:", "USAGE:", "OPTIONS:", value names), values checked
// against their domain with messages that quote what was given, and a
// usage error that names the option. This header holds what they share; it
// is header-only so that nvcc can compile it into sim-baseline-cuda too.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TOOLS_COMMANDLINE_H
#define SIM_TOOLS_COMMANDLINE_H

#include <CLI/CLI.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace simcli {

//===----------------------------------------------------------------------===//
// Value parsers
//===----------------------------------------------------------------------===//

/// A decimal integer in [min, max] (an optional '-', digits, nothing else:
/// no spaces, no "0x", no octal), or nullopt.
inline std::optional<int64_t> parseInteger(std::string_view text, int64_t min,
                                           int64_t max) {
  bool negative = !text.empty() && text.front() == '-';
  std::string_view digits = negative ? text.substr(1) : text;
  if (digits.empty())
    return std::nullopt;
  // Accumulate the magnitude as unsigned, so that INT64_MIN parses too.
  uint64_t magnitude = 0;
  for (char c : digits) {
    if (c < '0' || c > '9')
      return std::nullopt;
    uint64_t digit = uint64_t(c - '0');
    if (magnitude > (std::numeric_limits<uint64_t>::max() - digit) / 10)
      return std::nullopt;
    magnitude = magnitude * 10 + digit;
  }
  uint64_t limit = negative ? uint64_t(std::numeric_limits<int64_t>::max()) + 1
                            : uint64_t(std::numeric_limits<int64_t>::max());
  if (magnitude > limit)
    return std::nullopt;
  int64_t value = negative ? int64_t(0 - magnitude) : int64_t(magnitude);
  if (value < min || value > max)
    return std::nullopt;
  return value;
}

//===----------------------------------------------------------------------===//
// Validators: check a value's domain, rewrite it in canonical form
//===----------------------------------------------------------------------===//

/// "'<text>'": the value as the user wrote it, quoted.
inline std::string inQuotes(const std::string &text) {
  return "'" + text + "'";
}

/// An integer option in [min, max]; `domain` describes the range in words
/// ("an integer from 1 to 1024"). The value is written back in plain
/// decimal, so that CLI11's own conversion (which reads "010" as octal)
/// never sees anything else.
inline CLI::Validator integerIn(int64_t min, int64_t max,
                                const std::string &domain) {
  return CLI::Validator(
      [=](std::string &text) -> std::string {
        std::optional<int64_t> value = parseInteger(text, min, max);
        if (!value)
          return inQuotes(text) + " is not " + domain;
        text = std::to_string(*value);
        return "";
      },
      "", "integer");
}

/// One of `names`; `list` names them in words ("linear or cubic").
inline CLI::Validator oneOf(std::vector<std::string> names,
                            const std::string &list) {
  return CLI::Validator(
      [=](std::string &text) -> std::string {
        for (const std::string &name : names)
          if (text == name)
            return "";
        return inQuotes(text) + " is not " + list;
      },
      "", "one of");
}

/// NAME=VALUE with a non-empty NAME.
inline CLI::Validator assignment() {
  return CLI::Validator(
      [](std::string &text) -> std::string {
        size_t equals = text.find('=');
        if (equals == 0 || equals == std::string::npos)
          return inQuotes(text) + " is not NAME=VALUE";
        return "";
      },
      "", "assignment");
}

/// A non-empty path.
inline CLI::Validator path() {
  return CLI::Validator(
      [](std::string &text) -> std::string {
        if (text.empty())
          return "expects a path, not ''";
        return "";
      },
      "", "path");
}

//===----------------------------------------------------------------------===//
// Help and errors
//===----------------------------------------------------------------------===//

/// The layout of LLVM's tools: overview, usage, an introduction, options
/// with their value names ("--steps N"), -h last, then the footer.
class HelpFormatter : public CLI::Formatter {
public:
  HelpFormatter(std::string usage, std::string intro)
      : usage_(std::move(usage)), intro_(std::move(intro)) {
    column_width(30);
  }

  std::string make_help(const CLI::App *app, std::string,
                        CLI::AppFormatMode) const override {
    std::ostringstream out;
    out << "OVERVIEW: " << app->get_description() << "\n\n"
        << "USAGE: " << usage_ << "\n\n"
        << intro_ << "\nOPTIONS:\n";
    const CLI::Option *help = app->get_help_ptr();
    for (const CLI::Option *option : app->get_options())
      if (option->nonpositional() && option != help)
        out << make_option(option, false);
    out << make_option(help, false);
    if (!app->get_footer().empty())
      out << "\n" << app->get_footer();
    return out.str();
  }

  std::string make_option_name(const CLI::Option *option, bool) const override {
    std::string names;
    for (const std::string &name : option->get_snames())
      names += (names.empty() ? "-" : ", -") + name;
    for (const std::string &name : option->get_lnames())
      names += (names.empty() ? "--" : ", --") + name;
    return names;
  }

private:
  std::string usage_, intro_;
};

/// CLI11's message for a parse error, in our words where CLI11's are
/// unclear.
inline std::string describe(const CLI::ParseError &error) {
  std::string message = error.what();
  // "--steps: 1 required N missing"
  const std::string missing = " missing";
  size_t colon = message.find(": ");
  if (error.get_name() == "ArgumentMismatch" && colon != std::string::npos &&
      message.size() > missing.size() &&
      message.compare(message.size() - missing.size(), missing.size(),
                      missing) == 0)
    return message.substr(0, colon) + " expects a value";
  // "check-finite was given a disallowed flag override"
  const std::string override = " was given a disallowed flag override";
  size_t at = message.find(override);
  if (at != std::string::npos && at + override.size() == message.size())
    return "--" + message.substr(0, at) + " takes no value";
  return message;
}

/// The arguments `app` (which allows extras) did not take, as the error a
/// user gets: an unknown option or an argument the program takes none of.
/// Empty when every argument was taken.
inline std::string unexpectedArgument(const CLI::App &app) {
  for (const std::string &arg : app.remaining()) {
    if (arg.size() > 1 && arg[0] == '-')
      return "unknown option '" + arg + "'";
    return "unexpected argument '" + arg + "'";
  }
  return "";
}

} // namespace simcli

#endif // SIM_TOOLS_COMMANDLINE_H
