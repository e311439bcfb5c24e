//===- KernelNamesTest.cpp - kernel names from symbol names ---------------===//
//
// The escaping of symbols into kernel names (KernelNames.h): every result is
// an identifier, ordinary names stay as they are, different symbols stay
// apart, long names are bounded, and a container never gets a name twice.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/SimCommon/KernelNames.h"

#include "mlir/IR/Builders.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/MLIRContext.h"

#include "gtest/gtest.h"

#include <set>

using namespace mlir;
using namespace mlir::sim;

namespace {

TEST(KernelNamesTest, OrdinarySymbolsKeepTheirNames) {
  for (const char *symbol : {"C0", "B", "my_buffer", "x_", "a_1_b", "4B"})
    EXPECT_EQ(escapeKernelSymbol(symbol), symbol);
  EXPECT_EQ(getKernelName(nullptr, "evaluate", "C0"), "evaluate_C0");
  EXPECT_EQ(getKernelName(nullptr, "advance"), "advance");
}

TEST(KernelNamesTest, OtherBytesAreEscaped) {
  EXPECT_EQ(escapeKernelSymbol("B 4"), "B__204");
  EXPECT_EQ(escapeKernelSymbol("a b"), "a__20b");
  EXPECT_EQ(escapeKernelSymbol("a__b"), "a__5f_b");
  EXPECT_EQ(escapeKernelSymbol("a_ b"), "a__5f__20b");
  EXPECT_EQ(escapeKernelSymbol("x.y-z$"), "x__2ey__2dz__24");
  EXPECT_EQ(escapeKernelSymbol("\xce\x94x"), "__ce__94x");
  EXPECT_EQ(escapeKernelSymbol(""), "");
}

TEST(KernelNamesTest, EveryNameIsAnIdentifierAndSymbolsStayApart) {
  std::vector<std::string> symbols = {"a b",
                                      "a_b",
                                      "a__b",
                                      "a__20b",
                                      "a_20b",
                                      "a__5f_b",
                                      "a___b",
                                      "_",
                                      "__",
                                      "___",
                                      "_a",
                                      "a_",
                                      "a__",
                                      "",
                                      " ",
                                      "\xce\x94",
                                      "4.x$",
                                      "4__2ex__24",
                                      "C0",
                                      "c0",
                                      "-1",
                                      "x\n",
                                      std::string("nul\0in", 6)};
  std::set<std::string> names;
  for (const std::string &symbol : symbols) {
    std::string name = getKernelName(nullptr, "init", symbol);
    EXPECT_TRUE(isKernelIdentifier(name)) << name;
    EXPECT_TRUE(names.insert(name).second) << "two symbols escape to " << name;
  }
}

TEST(KernelNamesTest, LongNamesAreCutAndKeptApart) {
  std::string a(1000, 'a'), b = a;
  b.back() = 'b';
  std::string escapedA = escapeKernelSymbol(a);
  std::string escapedB = escapeKernelSymbol(b);
  EXPECT_EQ(escapedA.size(), kMaxKernelSymbolChars);
  EXPECT_EQ(escapedB.size(), kMaxKernelSymbolChars);
  EXPECT_NE(escapedA, escapedB);
  EXPECT_TRUE(isKernelIdentifier(escapedA));
  // Non-ASCII bytes take four characters each: cut too.
  std::string wide;
  for (int i = 0; i < 100; ++i)
    wide += "\xce\x94";
  EXPECT_EQ(escapeKernelSymbol(wide).size(), kMaxKernelSymbolChars);
  EXPECT_EQ(escapeKernelSymbol(std::string(kMaxKernelSymbolChars, 'x')),
            std::string(kMaxKernelSymbolChars, 'x'));
}

TEST(KernelNamesTest, AContainerNeverGetsANameTwice) {
  MLIRContext context;
  OpBuilder builder(&context);
  OwningOpRef<ModuleOp> container = ModuleOp::create(builder.getUnknownLoc());
  builder.setInsertionPointToEnd(container->getBody());
  auto add = [&](StringRef name) {
    ModuleOp::create(builder, builder.getUnknownLoc(), name);
  };
  // `substep_` + @estimate_G and `substep_estimate_` + @G.
  std::string first = getKernelName(*container, "substep_estimate", "G");
  EXPECT_EQ(first, "substep_estimate_G");
  add(first);
  std::string second = getKernelName(*container, "substep", "estimate_G");
  EXPECT_EQ(second, "substep_estimate_G_1");
  add(second);
  EXPECT_EQ(getKernelName(*container, "substep", "estimate_G"),
            "substep_estimate_G_2");
  add("advance");
  EXPECT_EQ(getKernelName(*container, "advance"), "advance_1");
}

} // namespace
