//===- CApiTest.cpp - runs the C test of the C API ------------------------===//

#include "TestBundle.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

extern "C" int sim_c_api_test(const char *path, char *message, size_t capacity);

using namespace sim::test;

TEST(CApi, WorksFromC) {
  std::string dir = makeTempDir();
  std::string path = dir + "/decay.simb";
  writeFile(path, decayBundle());
  char message[1024];
  EXPECT_EQ(sim_c_api_test(path.c_str(), message, sizeof message), 0)
      << message;
  std::remove(path.c_str());
  rmdir(dir.c_str());
}
