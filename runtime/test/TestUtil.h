//===- TestUtil.h - helpers shared by the runtime's gtests ------*- C++ -*-===//
//
// Small helpers that several test files need: parsing bundle bytes, the
// message of an expected runtime Error, and substring checks.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_TEST_TESTUTIL_H
#define SIM_RUNTIME_TEST_TESTUTIL_H

#include "Bundle.h"
#include "Error.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace sim::test {

/// A bundle parsed from `bytes`, named `name` in messages.
inline std::shared_ptr<const rt::Bundle>
parseBytes(const std::string &bytes, const std::string &name = "test.simb") {
  return rt::Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                           bytes.size(), name);
}

/// The message of the Error `body` throws, checking its status.
template <typename Body> std::string errorOf(Body &&body, sim_status expected) {
  try {
    body();
  } catch (const rt::Error &error) {
    EXPECT_EQ(error.status, expected) << error.what();
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

inline bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

} // namespace sim::test

#endif // SIM_RUNTIME_TEST_TESTUTIL_H
