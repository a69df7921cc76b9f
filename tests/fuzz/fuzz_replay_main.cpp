// Replays fuzz inputs without libFuzzer: each argument is a file, or a
// folder whose files are all replayed. Used by CTest (normal and sanitized
// builds) to run the seed corpora and every crash found so far
// (tests/fuzz/regressions/<target>/) through the fuzz target's code.
// An input that runs longer than kSecondsPerInput is a hang: the replay
// names it and fails (CTest's TIMEOUT is the outer guard).
#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

constexpr unsigned kSecondsPerInput = 60;
char current_input[4096] = "";

void on_alarm(int) {
  const char prefix[] = "replay: input hangs (over 60 s): ";
  [[maybe_unused]] auto a = write(STDERR_FILENO, prefix, sizeof prefix - 1);
  [[maybe_unused]] auto b = write(STDERR_FILENO, current_input, std::char_traits<char>::length(current_input));
  [[maybe_unused]] auto c = write(STDERR_FILENO, "\n", 1);
  _exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGALRM, on_alarm);
  std::size_t replayed = 0;
  for (int i = 1; i < argc; ++i) {
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(argv[i])) {
      for (const auto& e : std::filesystem::directory_iterator(argv[i]))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (std::filesystem::exists(argv[i])) {
      files.emplace_back(argv[i]);
    }
    for (const auto& f : files) {
      const std::string name = f.string();
      name.copy(current_input, sizeof current_input - 1);
      current_input[std::min(name.size(), sizeof current_input - 1)] = '\0';
      std::ifstream in(f, std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      alarm(kSecondsPerInput);
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      alarm(0);
      ++replayed;
    }
  }
  std::printf("replayed %zu inputs\n", replayed);
  return replayed > 0 ? 0 : 1;
}
