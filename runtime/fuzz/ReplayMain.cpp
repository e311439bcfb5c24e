//===- ReplayMain.cpp - run a fuzz target over files, without libFuzzer ---===//
//
// `replay PATH...` calls LLVMFuzzerTestOneInput once per file (a directory:
// once per file in it, in name order) and prints how many it ran. Builds
// without -fsanitize=fuzzer link this, so the kept corpus of every fuzz
// target runs as an ordinary regression test.
//
//===----------------------------------------------------------------------===//

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace {

int runFile(const std::filesystem::path &path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
    return 1;
  }
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                             std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  auto usage = [&](std::FILE *out) {
    std::fprintf(out,
                 "usage: %s FILE|DIR...\n\n"
                 "Runs the fuzz target once per FILE (once per file of a DIR, "
                 "in name order)\nwithout libFuzzer, and prints how many it "
                 "ran: the kept corpus as a\nregression test "
                 "(docs/Testing.md).\n",
                 argv[0]);
  };
  if (argc == 2 &&
      (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    usage(stdout);
    return 0;
  }
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  size_t count = 0;
  for (int i = 1; i < argc; ++i) {
    // The error_code overloads: the compiler's tools build without
    // exceptions.
    std::filesystem::path path(argv[i]);
    std::vector<std::filesystem::path> files;
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
      for (std::filesystem::directory_iterator it(path, error), end;
           !error && it != end; it.increment(error))
        if (it->is_regular_file(error))
          files.push_back(it->path());
      if (error) {
        std::fprintf(stderr, "replay: cannot list %s: %s\n", path.c_str(),
                     error.message().c_str());
        return 1;
      }
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(path);
    }
    for (const auto &file : files) {
      if (runFile(file))
        return 1;
      ++count;
    }
  }
  std::printf("replayed %zu inputs\n", count);
  return 0;
}
