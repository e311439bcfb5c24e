//===- SimRunToolTest.cpp - sim-run's parts, called directly --------------===//
//
// The pieces of sim-run that decide what a bad input does: the value
// parsers of the options, the dump file names made from buffer names, the
// output paths that are refused, the atomic write, --check's verdict on
// non-finite values, and what the output times keep. SimRunTest.cpp runs the
// binary end to end.
//
//===----------------------------------------------------------------------===//

#include "TestBundle.h"
#include "TestUtil.h"

#include "simrun/Compare.h"
#include "simrun/Options.h"
#include "simrun/Output.h"
#include "simrun/Progress.h"
#include "simrun/Report.h"
#include "simrun/Safety.h"
#include "simrun/Series.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

using namespace sim::test;
using namespace simrun;

namespace {

/// The message of the Exit that `body` throws, checking its status.
template <typename Body> std::string exitOf(Body &&body, int status) {
  try {
    body();
  } catch (const Exit &exit) {
    EXPECT_EQ(exit.status, status) << exit.message;
    return exit.message;
  }
  ADD_FAILURE() << "no Exit";
  return "";
}

Options parse(std::vector<const char *> args) {
  args.insert(args.begin(), "sim-run");
  return parseOptions(int(args.size()), args.data());
}

} // namespace

//===----------------------------------------------------------------------===//
// Values
//===----------------------------------------------------------------------===//

TEST(SimRunValues, ParsesDecimalIntegersOnly) {
  EXPECT_EQ(parseInteger("0", 0, 10), 0);
  EXPECT_EQ(parseInteger("010", 0, 100), 10); // not octal
  EXPECT_EQ(parseInteger("-5", -10, 10), -5);
  EXPECT_EQ(parseInteger("9223372036854775807", 0,
                         std::numeric_limits<int64_t>::max()),
            std::numeric_limits<int64_t>::max());
  EXPECT_EQ(parseInteger("-9223372036854775808",
                         std::numeric_limits<int64_t>::min(), 0),
            std::numeric_limits<int64_t>::min());
  for (const char *bad : {"", "-", "+5", " 5", "5 ", "0x10", "1e3", "5.0",
                          "9223372036854775808", "99999999999999999999"})
    EXPECT_FALSE(parseInteger(bad, std::numeric_limits<int64_t>::min(),
                              std::numeric_limits<int64_t>::max()))
        << bad;
  EXPECT_FALSE(parseInteger("11", 0, 10));
  EXPECT_FALSE(parseInteger("-1", 0, 10));
}

TEST(SimRunValues, ParsesSizesInPowersOf1024) {
  EXPECT_EQ(parseSize("0"), 0);
  EXPECT_EQ(parseSize("4096"), 4096);
  EXPECT_EQ(parseSize("2K"), 2048);
  EXPECT_EQ(parseSize("2k"), 2048);
  EXPECT_EQ(parseSize("3M"), 3 << 20);
  EXPECT_EQ(parseSize("5G"), int64_t(5) << 30);
  EXPECT_EQ(parseSize("7t"), int64_t(7) << 40);
  EXPECT_EQ(parseSize("8388607T"), int64_t(8388607) << 40);
  for (const char *bad : {"", "K", "-1", "-1G", "1.5G", "12X", "1KB", "1 G",
                          "8388608T", "9223372036854775808", "0x10"})
    EXPECT_FALSE(parseSize(bad)) << bad;
}

TEST(SimRunValues, ParsesNonNegativeFiniteNumbers) {
  EXPECT_EQ(parseNonNegative("1e-3"), 1e-3);
  EXPECT_EQ(parseNonNegative("2"), 2.0);
  EXPECT_EQ(parseNonNegative("0"), 0.0);
  EXPECT_FALSE(std::signbit(*parseNonNegative("-0")));
  EXPECT_EQ(parseNonNegative("1e-310"), 1e-310); // subnormal, not 0
  for (const char *bad : {"", "-1", "-1e-300", "nan", "inf", "-inf", "1e999",
                          "1e-3x", " 1", "0x1p-3", "1e-400"})
    EXPECT_FALSE(parseNonNegative(bad)) << bad;
}

TEST(SimRunValues, ReadsNumbersAsSetDoes) {
  // The reasons of a floating-point --set value (parseValue), for the same
  // texts.
  struct Case {
    const char *text, *why;
  } cases[] = {
      {"0x1p-3", "is hexadecimal; give a number in decimal"},
      {"-0X10", "is hexadecimal; give a number in decimal"},
      {"1e999", "is out of range for f64"},
      {"1e-400", "underflows to 0 in f64"},
      {"1e-3x", "is not a finite number >= 0"},
      {"-1", "is not a finite number >= 0"},
  };
  for (const Case &c : cases) {
    std::string why;
    EXPECT_FALSE(parseNonNegative(c.text, &why)) << c.text;
    EXPECT_EQ(why, c.why) << c.text;
  }
}

TEST(SimRunOptions, TakesEveryOption) {
  Options options = parse({"scene.simb",
                           "--backend=cuda",
                           "--strategy",
                           "simple",
                           "--steps",
                           "010",
                           "--repeat",
                           "3",
                           "--output-every",
                           "5",
                           "--output",
                           "out.npz",
                           "--checkpoint",
                           "out.simc",
                           "--checkpoint-every",
                           "7",
                           "--restart",
                           "in.simc",
                           "--set",
                           "k=1",
                           "--set",
                           "range=10",
                           "--group-size",
                           "64",
                           "--reference",
                           "exact",
                           "--check",
                           "--check-tolerance",
                           "1e-6",
                           "--dump",
                           "out",
                           "--json",
                           "out.json",
                           "--check-finite",
                           "--threads",
                           "2",
                           "--device",
                           "1",
                           "--cuda-graph",
                           "--max-memory",
                           "2G",
                           "--progress",
                           "--profile"});
  EXPECT_EQ(options.input, "scene.simb");
  EXPECT_EQ(options.backend, SIM_BACKEND_CUDA);
  EXPECT_EQ(options.strategy, SIM_STRATEGY_SIMPLE);
  EXPECT_EQ(options.steps, 10);
  EXPECT_EQ(options.repeat, 3);
  EXPECT_EQ(options.outputEvery, 5);
  EXPECT_EQ(options.output, "out.npz");
  EXPECT_EQ(options.checkpoint, "out.simc");
  EXPECT_EQ(options.checkpointEvery, 7);
  EXPECT_EQ(options.restart, "in.simc");
  ASSERT_EQ(options.sets.size(), 2u);
  EXPECT_EQ(options.sets[1],
            std::make_pair(std::string("range"), std::string("10")));
  EXPECT_EQ(options.groupSize, 64);
  EXPECT_EQ(options.reference, "exact");
  EXPECT_TRUE(options.check);
  EXPECT_EQ(options.checkTolerance, 1e-6);
  EXPECT_EQ(options.dump, "out");
  EXPECT_EQ(options.json, "out.json");
  EXPECT_TRUE(options.checkFinite);
  EXPECT_EQ(options.threads, 2);
  EXPECT_EQ(options.device, 1);
  EXPECT_TRUE(options.cudaGraph);
  EXPECT_EQ(options.maxMemory, int64_t(2) << 30);
  EXPECT_TRUE(options.progress);
  EXPECT_FALSE(parse({"a.simb"}).progress);
  EXPECT_TRUE(options.profile);
  EXPECT_FALSE(parse({"a.simb"}).profile);
  // The last of a repeated option counts.
  EXPECT_EQ(parse({"a.simb", "--steps", "1", "--steps", "2"}).steps, 2);
  // --report-every is the old name of --output-every.
  EXPECT_EQ(parse({"a.simb", "--report-every", "4"}).outputEvery, 4);
  EXPECT_EQ(parse({"a.simb", "--report-every", "4", "--output-every", "4"})
                .outputEvery,
            4);
}

TEST(SimRunOptions, RejectsValuesOutsideTheirDomain) {
  struct Case {
    std::vector<const char *> args;
    const char *message;
  } cases[] = {
      {{"a", "--steps", "-1"},
       "--steps: '-1' is not an integer from 0 to 1000000000000"},
      {{"a", "--steps", "1000000000001"}, "--steps: '1000000000001' is not"},
      {{"a", "--repeat", "9223372036854775807"},
       "--repeat: '9223372036854775807' is not an integer from 1 to 1000000"},
      {{"a", "--group-size", "4097"}, "--group-size: '4097' is not"},
      {{"a", "--threads", "0"}, "--threads: '0' is not"},
      {{"a", "--device", "-1"}, "--device: '-1' is not a device ordinal"},
      {{"a", "--report-every", "0"}, "--report-every: '0' is not"},
      {{"a", "--output-every", "0"}, "--output-every: '0' is not"},
      {{"a", "--checkpoint", "c", "--checkpoint-every", "x"},
       "--checkpoint-every: 'x' is not an integer from 1 to"},
      {{"a", "--checkpoint-every", "5"},
       "--checkpoint-every requires --checkpoint"},
      {{"a", "--output", "o.npz"}, "--output needs --output-every"},
      {{"a", "--backend", "reference", "--threads", "3"},
       "--threads sets the CPU backend's threads; the reference executor "
       "runs on one"},
      {{"a", "--backend", "cpu", "--cuda-graph"},
       "--cuda-graph applies to the CUDA backend; --backend cpu runs on this "
       "machine's CPU"},
      {{"a", "--backend", "reference", "--device", "0"},
       "--device applies to the CUDA backend; --backend reference runs on"},
      {{"a", "--output-every", "3", "--report-every", "4"},
       "--report-every 4 and --output-every 3 disagree"},
      {{"a", "--restart", ""}, "--restart: expects a path"},
      {{"a", "--check", "--check-tolerance", "inf"},
       "--check-tolerance: 'inf' is not a finite number >= 0"},
      {{"a", "--check", "--check-tolerance", "0x1p-3"},
       "--check-tolerance: '0x1p-3' is hexadecimal; give a number in "
       "decimal"},
      {{"a", "--max-memory", "-1"}, "--max-memory: '-1' is not a size"},
      {{"a", "--strategy", "best"}, "--strategy: unknown strategy 'best'"},
      {{"a", "--backend", "tpu"}, "--backend: unknown backend 'tpu'"},
      {{"a", "--reference", "cubic"},
       "--reference: 'cubic' is not simple or exact"},
      {{"a", "--set", "=1"}, "--set: '=1' is not NAME=VALUE"},
      {{"a", "--set", "max_steps=0"},
       "--set: max_steps '0' is not an integer from 1 to 1048576"},
      {{"a", "--set", "max_steps=4x"}, "--set: max_steps '4x' is not"},
      {{"a", "--progress=1"}, "--progress takes no value"},
      {{"a", "--profile=yes"}, "--profile takes no value"},
      {{"a", "--backend", "reference", "--profile"},
       "--profile lists the kernels of a plan; the reference executor runs "
       "none"},
      {{"a", "--json", ""}, "--json: expects a path"},
      {{"a", "--steps"}, "--steps expects a value"},
      {{"a", "--cuda-graph=yes"}, "--cuda-graph takes no value"},
      {{"a", "--fast"}, "unknown option '--fast'"},
      {{"a", "b"}, "more than one input: 'a' and 'b'"},
      {{}, "no input scene"},
  };
  for (const Case &c : cases) {
    std::string message = exitOf([&] { parse(c.args); }, kExitUsage);
    EXPECT_TRUE(contains(message, c.message)) << message;
    EXPECT_TRUE(contains(message, "(see sim-run --help)")) << message;
  }
}

TEST(SimRunOptions, PrintsTheHelpOfEveryOption) {
  std::string help = helpText();
  for (const char *option : {"--backend B ",
                             "--strategy S ",
                             "--steps N ",
                             "--repeat K ",
                             "--output-every N ",
                             "--report-every N ",
                             "--output FILE ",
                             "--checkpoint FILE ",
                             "--checkpoint-every N ",
                             "--restart FILE ",
                             "--set NAME=VALUE ",
                             "--group-size G ",
                             "--reference simple|exact ",
                             "--check ",
                             "--check-tolerance X ",
                             "--dump DIR ",
                             "--json FILE ",
                             "--check-finite ",
                             "--threads N ",
                             "--device N ",
                             "--cuda-graph ",
                             "--max-memory SIZE ",
                             "--no-init-check ",
                             "--progress ",
                             "--profile ",
                             "-h, --help "})
    EXPECT_TRUE(contains(help, "\n  " + std::string(option))) << option;
  EXPECT_TRUE(contains(help, "130 or 143")) << help;
  EXPECT_TRUE(contains(help, "3 when the run\nended with NaN")) << help;
}

//===----------------------------------------------------------------------===//
// Dump file names
//===----------------------------------------------------------------------===//

TEST(SimRunNames, KeepsPlainNamesAndEncodesTheRest) {
  EXPECT_EQ(sanitiseName("X"), "X");
  EXPECT_EQ(sanitiseName("pos_2.x-y"), "pos_2.x-y");
  EXPECT_EQ(sanitiseName("../../x"), "%2E.%2F..%2Fx");
  EXPECT_EQ(sanitiseName("a/b"), "a%2Fb");
  EXPECT_EQ(sanitiseName(".hidden"), "%2Ehidden");
  EXPECT_EQ(sanitiseName("."), "%2E");
  EXPECT_EQ(sanitiseName(".."), "%2E.");
  EXPECT_EQ(sanitiseName(""), "_");
  EXPECT_EQ(sanitiseName("a b\tc\n"), "a%20b%09c%0A");
  EXPECT_EQ(sanitiseName(std::string("nul\0x", 5)), "nul%00x");
  EXPECT_EQ(sanitiseName("\xff\xfe"), "%FF%FE"); // invalid UTF-8
  EXPECT_EQ(sanitiseName("\xce\xa9"), "%CE%A9"); // valid UTF-8 too
  EXPECT_EQ(sanitiseName("100%"), "100%25");     // '%' itself
  EXPECT_EQ(sanitiseName("C:\\x"), "C%3A%5Cx");
}

TEST(SimRunNames, NeverMakesAPathOrAnOddName) {
  // Every byte value, alone and after a letter.
  for (int c = 0; c < 256; ++c) {
    for (std::string name :
         {std::string(1, char(c)), "a" + std::string(1, char(c))}) {
      std::string stem = sanitiseName(name);
      ASSERT_FALSE(stem.empty());
      EXPECT_NE(stem[0], '.') << c;
      EXPECT_NE(stem, "..");
      for (char s : stem)
        EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(s)) || s == '_' ||
                    s == '.' || s == '-' || s == '%')
            << c << ": " << stem;
    }
  }
}

TEST(SimRunNames, CutsLongNamesOutsideAnEscape) {
  std::string stem = sanitiseName(std::string(300, '/'));
  EXPECT_LE(stem.size(), kMaxStem);
  EXPECT_EQ(stem.size() % 3, 0u); // whole %2F triples
  EXPECT_EQ(sanitiseName(std::string(300, 'a')).size(), kMaxStem);
  for (const char *suffix : kDumpSuffixes)
    EXPECT_LE(kMaxStem + 8 + std::string(suffix).size(), 255u);
}

TEST(SimRunNames, MakesEveryDumpFileUnique) {
  // "X.reference" would write X's reference file; the second "_" (an empty
  // name) and the long names cut alike would overwrite the first.
  std::string longA = std::string(250, 'a') + "1";
  std::string longB = std::string(250, 'a') + "2";
  std::vector<std::string> stems =
      dumpStems({"X", "X.reference", "", "_", longA, longB, "_-2"});
  EXPECT_EQ(stems[0], "X");
  EXPECT_EQ(stems[1], "X.reference-2");
  EXPECT_EQ(stems[2], "_");
  EXPECT_EQ(stems[3], "_-2");
  EXPECT_EQ(stems[4], std::string(kMaxStem, 'a'));
  EXPECT_EQ(stems[5], std::string(kMaxStem, 'a') + "-2");
  EXPECT_EQ(stems[6], "_-2-2");
  std::set<std::string> files;
  for (const std::string &stem : stems)
    for (const char *suffix : kDumpSuffixes)
      EXPECT_TRUE(files.insert(stem + suffix).second) << stem + suffix;
}

//===----------------------------------------------------------------------===//
// Output paths
//===----------------------------------------------------------------------===//

class SimRunOutput : public ::testing::Test {
protected:
  void SetUp() override {
    dir = makeTempDir();
    input = dir + "/scene.simb";
    writeFile(input, "bundle bytes");
  }
  void TearDown() override { std::system(("rm -rf '" + dir + "'").c_str()); }

  std::string dir, input;
};

TEST_F(SimRunOutput, ResolvesPathsThatDoNotExistYet) {
  std::string real = resolveDirectory(dir);
  EXPECT_EQ(resolveOutputPath(dir + "/new/../scene.simb"),
            real + "/scene.simb");
  EXPECT_EQ(resolveOutputPath(dir + "/./a/b/../c.json"), real + "/a/c.json");
  ASSERT_EQ(symlink(dir.c_str(), (dir + "/link").c_str()), 0);
  EXPECT_EQ(resolveOutputPath(dir + "/link/x.json"), real + "/x.json");
  // The last component is not followed: a rename replaces the link.
  EXPECT_EQ(resolveOutputPath(dir + "/link"), real + "/link");
}

TEST_F(SimRunOutput, RefusesToWriteOntoTheInput) {
  ASSERT_EQ(symlink(dir.c_str(), (dir + "/via").c_str()), 0);
  ASSERT_EQ(link(input.c_str(), (dir + "/hard.simb").c_str()), 0);
  ASSERT_EQ(symlink("scene.simb", (dir + "/soft.simb").c_str()), 0);
  for (std::string path :
       {input, dir + "/./scene.simb", dir + "/via/scene.simb",
        dir + "/missing/../scene.simb", dir + "/hard.simb"}) {
    OutputPlan plan;
    plan.addInput(input);
    std::string message =
        exitOf([&] { plan.addFile("--json", path); }, kExitUsage);
    EXPECT_TRUE(contains(message,
                         "--json: '" + path + "' is the input '" + input + "'"))
        << message;
  }
  // An input given through a symlink: neither the link nor its target.
  for (std::string path : {dir + "/soft.simb", input}) {
    OutputPlan plan;
    plan.addInput(dir + "/soft.simb");
    exitOf([&] { plan.addFile("--json", path); }, kExitUsage);
  }
  // A symlink to the input as the output is fine: it is replaced.
  OutputPlan plan;
  plan.addInput(input);
  plan.addFile("--json", dir + "/soft.simb");
}

TEST_F(SimRunOutput, RefusesTwoOutputsOnOneFile) {
  OutputPlan plan;
  plan.addInput(input);
  plan.addDirectory("--dump", dir + "/out");
  plan.addFile("--json", dir + "/out/X.npy");
  std::string message =
      exitOf([&] { plan.addFile("--dump (buffer 'X')", dir + "/out/./X.npy"); },
             kExitUsage);
  EXPECT_TRUE(contains(message, "is also the file of --json")) << message;
}

TEST_F(SimRunOutput, RefusesAFileWhereAFolderMustBe) {
  // --dump's folder or the folder of another output is where a file goes:
  // the run used to end with the folder made and the file lost, or the
  // other way round.
  {
    OutputPlan plan;
    plan.addInput(input);
    plan.addDirectory("--dump", dir + "/j.json");
    std::string message =
        exitOf([&] { plan.addFile("--json", dir + "/j.json"); }, kExitUsage);
    EXPECT_TRUE(contains(message, "--json: '" + dir +
                                      "/j.json' is where --dump needs the "
                                      "folder"))
        << message;
  }
  {
    OutputPlan plan;
    plan.addInput(input);
    plan.addFile("--checkpoint", dir + "/c.simc");
    std::string message =
        exitOf([&] { plan.addDirectory("--dump", dir + "/c.simc/./sub"); },
               kExitUsage);
    EXPECT_TRUE(contains(message, "must be a folder, but it is where "
                                  "--checkpoint writes the file"))
        << message;
  }
  for (bool fileFirst : {false, true}) {
    OutputPlan plan;
    plan.addInput(input);
    std::function<void()> addFile = [&] {
      plan.addFile("--checkpoint", dir + "/ck");
    };
    std::function<void()> addInside = [&] {
      plan.addFile("--json", dir + "/ck/a/x.json");
    };
    if (fileFirst)
      addFile();
    else
      addInside();
    std::string message = exitOf(fileFirst ? addInside : addFile, kExitUsage);
    EXPECT_TRUE(contains(message, "'ck") || contains(message, "/ck"))
        << message;
  }
  // A file inside --dump's folder, beside its dumps, is fine.
  OutputPlan plan;
  plan.addInput(input);
  plan.addDirectory("--dump", dir + "/out");
  plan.addFile("--json", dir + "/out/run.json");
}

TEST_F(SimRunOutput, RefusesFoldersThatCannotBeUsed) {
  OutputPlan plan;
  EXPECT_TRUE(
      contains(exitOf([&] { plan.addDirectory("--dump", input); }, kExitUsage),
               "--dump: '" + input + "' is not a directory"));
  EXPECT_TRUE(contains(
      exitOf([&] { plan.addDirectory("--dump", input + "/sub"); }, kExitUsage),
      "is not a directory"));
  EXPECT_TRUE(contains(exitOf([&] { plan.addFile("--json", dir); }, kExitUsage),
                       "--json: '" + dir + "' is a directory, not a file"));
  EXPECT_TRUE(
      contains(exitOf([&] { plan.addFile("--json", dir + "/"); }, kExitUsage),
               "is a directory, not a file"));
  // Missing folders that can be created are fine.
  plan.addDirectory("--dump", dir + "/a/b/c");
  plan.addFile("--json", dir + "/x/y.json");
  if (geteuid() != 0) {
    // (root writes anywhere)
    ASSERT_EQ(mkdir((dir + "/ro").c_str(), 0555), 0);
    EXPECT_TRUE(
        contains(exitOf([&] { plan.addDirectory("--dump", dir + "/ro/sub"); },
                        kExitUsage),
                 "--dump: cannot create directory"));
    EXPECT_TRUE(contains(
        exitOf([&] { plan.addFile("--json", dir + "/ro/x.json"); }, kExitUsage),
        "--json: cannot write into directory"));
  }
}

TEST_F(SimRunOutput, RefusesDevicesFifosAndSymlinksToThem) {
  // An output replaces the file at its path: a FIFO (or, as root, a device
  // such as /dev/null) there would be replaced by a regular file. Only a
  // FIFO here: a test that went wrong on /dev/null would break the machine.
  std::string fifo = dir + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  std::string link = dir + "/to-fifo";
  ASSERT_EQ(symlink(fifo.c_str(), link.c_str()), 0);
  OutputPlan plan;
  EXPECT_TRUE(
      contains(exitOf([&] { plan.addFile("--json", fifo); }, kExitUsage),
               "--json: '" + fifo +
                   "' is a FIFO, not a regular file; sim-run "
                   "replaces an output file whole, so name a "
                   "regular file"));
  EXPECT_TRUE(
      contains(exitOf([&] { plan.addFile("--checkpoint", link); }, kExitUsage),
               "--checkpoint: '" + link +
                   "' is a symlink to a FIFO, not to a "
                   "regular file"));
  // A symlink into /proc (as /dev/stdout is) whatever it leads to: here
  // this process's standard input, a file, a pipe or a terminal.
  std::string stdinLink = dir + "/stdin";
  ASSERT_EQ(symlink("/proc/self/fd/0", stdinLink.c_str()), 0);
  EXPECT_TRUE(
      contains(exitOf([&] { plan.addFile("--json", stdinLink); }, kExitUsage),
               "--json: '" + stdinLink +
                   "' is a symlink to '/proc/self/fd/0', a "
                   "process's file"));
  struct stat info;
  ASSERT_EQ(lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

TEST_F(SimRunOutput, ProbesFoldersThatAccessCallsWritable) {
  // access() says yes to root for /proc, where no file can be created: the
  // check creates (and removes) one instead, before the run.
  struct stat info;
  if (stat("/proc/self", &info) != 0)
    GTEST_SKIP() << "no /proc";
  OutputPlan plan;
  EXPECT_TRUE(contains(
      exitOf([&] { plan.addDirectory("--dump", "/proc"); }, kExitUsage),
      "--dump: cannot write into directory '/proc'"));
  EXPECT_TRUE(contains(
      exitOf([&] { plan.addFile("--json", "/proc/sim-missing/j.json"); },
             kExitUsage),
      "--json: cannot create directory '/proc/sim-missing'"));
  // Writable folders leave nothing behind.
  plan.addDirectory("--dump", dir);
  plan.addFile("--json", dir + "/new/j.json");
  EXPECT_NE(stat((dir + "/new").c_str(), &info), 0);
}

TEST_F(SimRunOutput, ReplacesASymlinkInsteadOfFollowingIt) {
  std::string target = dir + "/target";
  writeFile(target, "keep me");
  std::string path = dir + "/out.json";
  ASSERT_EQ(symlink(target.c_str(), path.c_str()), 0);
  writeFileAtomically(path, "{}\n");
  EXPECT_EQ(readFile(target), "keep me");
  struct stat info;
  ASSERT_EQ(lstat(path.c_str(), &info), 0);
  EXPECT_TRUE(S_ISREG(info.st_mode));
  EXPECT_EQ(readFile(path), "{}\n");
  // No temporary file is left, and missing folders are made.
  writeFileAtomically(dir + "/new/dir/x.npy", "x");
  EXPECT_EQ(readFile(dir + "/new/dir/x.npy"), "x");
  std::string listing = dir + "/listing";
  std::system(("ls -A '" + dir + "' '" + dir + "/new/dir' > '" + listing + "'")
                  .c_str());
  EXPECT_FALSE(contains(readFile(listing), ".sim-run-")) << readFile(listing);
}

TEST_F(SimRunOutput, GivesFilesTheUsualPermissions) {
  mode_t old = umask(027);
  captureUmask();
  writeFileAtomically(dir + "/perm", "x");
  umask(old);
  captureUmask();
  struct stat info;
  ASSERT_EQ(stat((dir + "/perm").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

//===----------------------------------------------------------------------===//
// --check and non-finite values
//===----------------------------------------------------------------------===//

namespace {

Buffer doubles(const std::string &name, std::vector<double> values) {
  Buffer buffer;
  buffer.name = name;
  buffer.scalarBytes = 8;
  buffer.bytes.resize(values.size() * 8);
  std::memcpy(buffer.bytes.data(), values.data(), buffer.bytes.size());
  return buffer;
}

} // namespace

TEST(SimRunCheck, FailsOnNonFiniteValuesEvenWhenBothSidesAgree) {
  Buffer nan = doubles("X", {1, NAN, 2, NAN});
  Check check = compareWithReference({nan}, {nan}, {}, {}, -1);
  ASSERT_EQ(check.buffers.size(), 1u);
  EXPECT_FALSE(check.buffers[0].pass);
  EXPECT_EQ(check.buffers[0].nonFiniteBackend, 2u);
  EXPECT_EQ(check.buffers[0].nonFiniteReference, 2u);
  ASSERT_EQ(check.failures.size(), 1u);
  EXPECT_EQ(check.failures[0], "buffer X has 2 non-finite values on the "
                               "backend and 2 on the reference executor");

  Buffer inf = doubles("V", {INFINITY, 0});
  Buffer fine = doubles("V", {0, 0});
  check = compareWithReference({inf}, {fine}, {}, {}, -1);
  EXPECT_EQ(check.failures,
            std::vector<std::string>{
                "buffer V has 1 non-finite value on the backend"});
  check = compareWithReference({fine}, {inf}, {}, {}, -1);
  EXPECT_EQ(check.failures,
            std::vector<std::string>{
                "buffer V has 1 non-finite value on the reference executor"});
  check = compareWithReference({fine}, {fine}, {}, {}, -1);
  EXPECT_TRUE(check.pass());
}

TEST(SimRunCheck, ToleranceZeroAsksForEqualValues) {
  Buffer reference = doubles("X", {1, 2, 3});
  Buffer oneUlpOff = doubles("X", {1, std::nextafter(2.0, 3.0), 3});
  Check check = compareWithReference({reference}, {reference}, {}, {}, 0);
  EXPECT_TRUE(check.pass());
  EXPECT_EQ(check.buffers[0].limit, 0.0);
  check = compareWithReference({oneUlpOff}, {reference}, {}, {}, 0);
  EXPECT_FALSE(check.pass());
  // By default (a negative tolerance) one ulp of a double passes.
  check = compareWithReference({oneUlpOff}, {reference}, {}, {}, -1);
  EXPECT_TRUE(check.pass());
}

TEST(SimRunCheck, FailsOnNonFiniteTotals) {
  std::vector<Check::TotalRow> rows;
  std::vector<std::string> failures;
  compareTotals({"E", "P"}, 10, {NAN, INFINITY}, {NAN, INFINITY}, {1e-8, 1e-8},
                rows, failures);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_FALSE(rows[0].pass);
  EXPECT_FALSE(rows[1].pass);
  ASSERT_EQ(failures.size(), 2u);
  EXPECT_TRUE(contains(failures[0], "total E at base step 10 is not finite"))
      << failures[0];
  EXPECT_TRUE(contains(failures[1], "total P at base step 10 is not finite"))
      << failures[1];
}

TEST(SimRunCheck, NamesControlCharactersVisibly) {
  EXPECT_EQ(displayName("a\x01\nb\x7f"), "a\\x01\\x0Ab\\x7F");
  EXPECT_EQ(displayName("X"), "X");
}

//===----------------------------------------------------------------------===//
// Progress
//===----------------------------------------------------------------------===//

TEST(SimRunProgress, FormatsRatesAndTimesLeft) {
  EXPECT_EQ(formatRate(0), "0");
  EXPECT_EQ(formatRate(812.4), "812");
  EXPECT_EQ(formatRate(999.6), "1.00k");
  EXPECT_EQ(formatRate(45321), "45.3k");
  EXPECT_EQ(formatRate(1.2e6), "1.20M");
  EXPECT_EQ(formatRate(3.5e15), "3500T");
  EXPECT_EQ(formatEta(0), "ETA 0 s");
  EXPECT_EQ(formatEta(18.2), "ETA 19 s");
  EXPECT_EQ(formatEta(125), "ETA 2 min 05 s");
  EXPECT_EQ(formatEta(3 * 3600 + 7 * 60 + 30), "ETA 3 h 07 min");
  EXPECT_EQ(formatEta(NAN), "ETA -");
  EXPECT_EQ(progressLine("check: ", 250000, 1000000, 2),
            "sim-run: check: base step 250000 of 1000000 (25%), 125k base "
            "steps/s, ETA 6 s");
  EXPECT_EQ(progressLine("", 0, 10, 1.5),
            "sim-run: base step 0 of 10 (0%), 0 base steps/s, ETA -");
  // After a restart at base step 500000 the rate counts only the steps
  // this process ran.
  EXPECT_EQ(progressLine("", 750000, 1000000, 2, 500000),
            "sim-run: base step 750000 of 1000000 (75%), 125k base "
            "steps/s, ETA 2 s");
}

namespace {

/// What a Progress writes to a temporary file for the reports `calls`
/// (done, seconds) of a run of 1000 base steps.
std::string progressOutput(bool terminal, bool forced,
                           std::vector<std::pair<int64_t, double>> calls) {
  std::FILE *file = std::tmpfile();
  Progress progress(terminal, forced, file);
  for (auto [done, seconds] : calls)
    progress.report(done, 1000, seconds);
  progress.end();
  std::string text(size_t(std::ftell(file)), '\0');
  std::rewind(file);
  size_t read = std::fread(text.data(), 1, text.size(), file);
  text.resize(read);
  std::fclose(file);
  return text;
}

} // namespace

TEST(SimRunProgress, ShowsALineOnATerminalFromTheFirstSecond) {
  // Nothing before the first second, then the line rewritten in place at
  // most every quarter of a second, and cleared at the end.
  std::string out =
      progressOutput(true, false, {{10, 0.5}, {20, 1.0}, {25, 1.1}, {50, 2}});
  EXPECT_EQ(out, "\rsim-run: base step 20 of 1000 (2%), 20 base steps/s, "
                 "ETA 49 s\033[K"
                 "\rsim-run: base step 50 of 1000 (5%), 25 base steps/s, "
                 "ETA 38 s\033[K"
                 "\r\033[K");
}

TEST(SimRunProgress, IsQuietInLogsUnlessForced) {
  EXPECT_EQ(progressOutput(false, false, {{20, 1.0}, {500, 30}, {900, 60}}),
            "");
  // --progress: whole lines, one per ten seconds.
  EXPECT_EQ(progressOutput(false, true, {{20, 1.0}, {30, 5}, {500, 25}}),
            "sim-run: base step 20 of 1000 (2%), 20 base steps/s, ETA 49 "
            "s\n"
            "sim-run: base step 500 of 1000 (50%), 20 base steps/s, ETA "
            "25 s\n");
}

TEST(SimRunProgress, CountsTheRateFromARestartsBaseStep) {
  // A run restarted at base step 600 towards 1000, in two session runs
  // (an output time at 800): 300 steps in 20 seconds is 15 per second,
  // not the 45 that counting the steps before the restart would give.
  std::FILE *file = std::tmpfile();
  Progress progress(false, true, file);
  progress.begin(nullptr, "");
  progress.resume(nullptr, 600, 1000);
  progress.report(200, 200, 8);
  progress.resume(nullptr, 800, 1000);
  progress.report(100, 200, 20);
  progress.end();
  std::string text(size_t(std::ftell(file)), '\0');
  std::rewind(file);
  text.resize(std::fread(text.data(), 1, text.size(), file));
  std::fclose(file);
  EXPECT_EQ(text, "sim-run: base step 800 of 1000 (80%), 25 base steps/s, "
                  "ETA 8 s\n"
                  "sim-run: base step 900 of 1000 (90%), 15 base steps/s, "
                  "ETA 7 s\n");
}

//===----------------------------------------------------------------------===//
// Warnings: the init check and non-finite results
//===----------------------------------------------------------------------===//

TEST(SimRunWarnings, NamesTheFirstNonFiniteValueAndHowMany) {
  Buffer x = doubles("X", {1, 2, NAN, 4, INFINITY, 6});
  x.lanes = 2;
  std::optional<NonFiniteValues> found = findNonFinite(x);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->count, 2);
  EXPECT_EQ(found->item, 1);
  EXPECT_EQ(found->lane, 0);
  EXPECT_EQ(nonFiniteWarning(*found),
            "sim-run: warning: buffer 'X' holds 2 NaN or infinite values at "
            "the end of the run (the first: nan at item 1, lane 0)");
  EXPECT_FALSE(findNonFinite(doubles("V", {0, 1, -1e308})));
  Buffer one = doubles("V", {0, -INFINITY});
  EXPECT_EQ(nonFiniteWarning(*findNonFinite(one)),
            "sim-run: warning: buffer 'V' holds 1 NaN or infinite value at "
            "the end of the run (the first: -inf at item 1)");

  std::vector<NonFiniteValues> totals =
      findNonFiniteTotals({"E", "P", "Q"}, {1, NAN, INFINITY});
  ASSERT_EQ(totals.size(), 2u);
  EXPECT_EQ(nonFiniteWarning(totals[0]),
            "sim-run: warning: total 'P' is not finite at the end of the run "
            "(nan)");
  EXPECT_EQ(nonFiniteWarning(totals[1]),
            "sim-run: warning: total 'Q' is not finite at the end of the run "
            "(inf)");
}

TEST(SimRunWarnings, SaysWhichInitDisagreesWithItsWriter) {
  InitCheckReport report;
  report.ran = true;
  report.items = 64;
  report.range = 64;
  InitCheckReport::Row y;
  y.buffer = "Y";
  y.component = "Fall";
  y.maxAbs = 0.25;
  y.item = 3;
  y.initial = -0.25;
  y.evaluated = 0;
  y.scale = 0.63;
  y.tolerance = 1e-5;
  y.count = 1;
  y.interpolated = true;
  InitCheckReport::Row s = y;
  s.buffer = "S";
  s.component = "Shadow";
  s.count = 0;
  s.nonFinite = 2;
  s.nonFiniteItem = 5;
  s.lanes = 3;
  report.rows = {y, s};
  std::vector<std::string> messages = initCheckMessages(report);
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[0],
            "sim-run: warning: the init of buffer 'Y' disagrees with its "
            "writer 'Fall' evaluated with n = 0 at t = 0\n"
            "  largest difference 2.500e-01 at item 3 (init "
            "-2.500000000e-01, evaluate 0.000000000e+00); 1 of 64 values "
            "differ by more than 1.0e-05 of the largest, 6.300e-01\n"
            "  hip and hip-cache interpolate from the init in the first big "
            "step: make the init what 'Fall' computes");
  EXPECT_EQ(messages[1],
            "sim-run: note: the init check skips 2 values of buffer 'S': "
            "its init or 'Shadow' evaluated with n = 0 at t = 0 is NaN or "
            "infinite there (the first at item 5), as when a body divides "
            "by n");

  // Part of a large range; a check that could not run.
  report.range = 1000000;
  report.rows.clear();
  EXPECT_EQ(initCheckMessages(report),
            std::vector<std::string>{
                "sim-run: note: the init check evaluated 64 of the 1000000 "
                "items (the first 32 and the last 32)"});
  InitCheckReport failed;
  failed.skipped = "a reference body read buffer 9";
  EXPECT_EQ(initCheckMessages(failed),
            std::vector<std::string>{"sim-run: note: the init check did not "
                                     "run: a reference body read buffer 9"});
  failed.skipped = "the bundle has no reference functions";
  EXPECT_TRUE(initCheckMessages(failed).empty());
}

TEST(SimRunReport, ComparesTotalsWithTheirReference) {
  TotalError error = compareTotal("E", 1.5, 2);
  EXPECT_TRUE(error.available);
  EXPECT_EQ(error.absolute, 0.5);
  EXPECT_EQ(error.relative, 0.25);
  EXPECT_EQ(compareTotal("E", 1, 0).relative, INFINITY);
  EXPECT_EQ(compareTotal("E", 0, 0).relative, 0);
  EXPECT_TRUE(std::isnan(compareTotal("E", NAN, 1).absolute));
}

TEST(SimRunReport, ListsTheMeasuredRunsASignalSkipped) {
  // SIGINT in the warm-up of --repeat 3: the three measured runs and the
  // reference never ran.
  Results results;
  results.main.repeat = 3;
  results.main.steps = 10;
  results.main.cutRun = 0;
  results.main.state = {Stage::Cut, 4, 10};
  results.reference = {Stage::Skipped, 0, 0};
  results.signal = SIGINT;
  nlohmann::json json = nlohmann::json::parse(toJson(results));
  EXPECT_EQ(json["interruption"]["during"], "warm-up");
  EXPECT_EQ(json["interruption"]["skipped"],
            nlohmann::json::array({"runs 1 to 3", "reference"}));
  // In the second of three: the third is skipped.
  results.main.cutRun = 2;
  json = nlohmann::json::parse(toJson(results));
  EXPECT_EQ(json["interruption"]["during"], "run");
  EXPECT_EQ(json["interruption"]["skipped"],
            nlohmann::json::array({"run 3", "reference"}));
  // In the last one: nothing of the main run is skipped.
  results.main.cutRun = 3;
  json = nlohmann::json::parse(toJson(results));
  EXPECT_EQ(json["interruption"]["skipped"],
            nlohmann::json::array({"reference"}));
}

//===----------------------------------------------------------------------===//
// Output times
//===----------------------------------------------------------------------===//

TEST(SimRunSeries, KeepsOnlyTheLastRowWhenNothingReadsThem) {
  // --output-every 1 without --output, --json or --check: the table prints
  // each row, and a run of any length holds one.
  Series series;
  series.range = 4;
  series.totalNames = {"E"};
  series.buffers.push_back({"X", 8, 1, true, false});
  Buffer x;
  x.name = "X";
  x.bytes.assign(32, 0);
  for (bool keep : {false, true}) {
    series.keepRows = keep;
    series.clear();
    for (int64_t t = 0; t < 1000; ++t)
      series.add(t, {double(t)}, {x}, {x});
    EXPECT_EQ(series.recorded, 1000);
    ASSERT_EQ(series.size(), keep ? 1000u : 1u);
    EXPECT_EQ(series.times.back(), 999);
    EXPECT_EQ(series.totals.back(), std::vector<double>{999});
    EXPECT_EQ(series.errors.size(), series.size());
  }
}

TEST(SimRunSeries, RefusesOutputTimesThatDoNotFitInMemory) {
  // What every output time keeps grows with --json and --check, and with
  // the totals, also without --output's buffers.
  int64_t plain = rowOverheadBytes(2, 1, false, false);
  int64_t json = rowOverheadBytes(2, 1, true, false);
  EXPECT_GT(plain, 0);
  EXPECT_GT(json, plain);
  EXPECT_GT(rowOverheadBytes(3, 1, true, false), json);
  EXPECT_GT(rowOverheadBytes(2, 1, true, true), json);
  // 1 MiB of memory: half of it holds this many rows.
  double memory = 1 << 20;
  int64_t fit = int64_t(memory / 2) / json;
  EXPECT_EQ(seriesMemoryError("--json", fit, json, memory), "");
  std::string message = seriesMemoryError("--json", fit * 2, json, memory);
  EXPECT_TRUE(contains(message, "--json: " + std::to_string(fit * 2) +
                                    " output times of " + formatBytes(json) +
                                    " each take "))
      << message;
  EXPECT_TRUE(contains(message, "more than half of this machine's memory "
                                "(1.00 MiB); choose a larger --output-every"))
      << message;
  // --steps 10^12 --output-every 1: no overflow.
  EXPECT_FALSE(seriesMemoryError("--output and --json", 1000000000001,
                                 int64_t(1) << 40, 1e12)
                   .empty());
}

TEST(SimRunReport, ProfilesKernelsWhereTheBackendTimesThem) {
  // The CPU times every launch: the table sorts by time. A backend that
  // times only the whole run (CUDA, seconds -1) gets launches, dashes and
  // where to get the times; --json has null there.
  Results results;
  results.profile = true;
  results.main.backend = "cuda";
  results.main.counts.kernels = {
      {"advance", 9, -1}, {"substep_C1", 8, -1}, {"init_X", 0, -1}};
  testing::internal::CaptureStdout();
  printTable(results);
  std::string table = testing::internal::GetCapturedStdout();
  EXPECT_TRUE(contains(table, "  advance             9            -       -  "
                              "          -\n"))
      << table;
  EXPECT_TRUE(contains(table, "the cuda backend times the run, not each "
                              "launch: time its kernels with Nsight Systems"))
      << table;
  EXPECT_TRUE(contains(table, "not launched in the run: init_X")) << table;
  nlohmann::json json = nlohmann::json::parse(toJson(results));
  EXPECT_EQ(json["kernels"][1], nlohmann::json({{"name", "substep_C1"},
                                                {"launches", 8},
                                                {"seconds", nullptr}}));

  results.main.backend = "cpu";
  results.main.counts.kernels = {
      {"advance", 9, 2e-6}, {"substep_C1", 8, 6e-3}, {"init_X", 0, 0}};
  testing::internal::CaptureStdout();
  printTable(results);
  table = testing::internal::GetCapturedStdout();
  size_t substep = table.find("  substep_C1 "),
         advance = table.find("  advance ");
  ASSERT_NE(substep, std::string::npos) << table;
  ASSERT_NE(advance, std::string::npos) << table;
  EXPECT_LT(substep, advance) << table;
  EXPECT_TRUE(contains(
      table, "substep_C1          8     6.000 ms  100.0%     750.0 us"))
      << table;
  EXPECT_TRUE(contains(
      table, "advance             9       2.0 us    0.0%       222 ns"))
      << table;
  EXPECT_FALSE(contains(table, "Nsight")) << table;
  json = nlohmann::json::parse(toJson(results));
  EXPECT_EQ(json["kernels"][1]["seconds"], 6e-3);

  // Without --profile: no table, the JSON as before.
  results.profile = false;
  testing::internal::CaptureStdout();
  printTable(results);
  EXPECT_FALSE(contains(testing::internal::GetCapturedStdout(), "kernels of"));
}
