// fourbar-read-mat: reads one MATLAB recording with libmatio (libhdf5 for
// v7.3) for fourbar, in a process of its own (acquire/mat_reader.cpp says
// why), and writes the contents or the error to stdout (acquire/mat_wire.hpp,
// framed by common/child_process.hpp). Not a user command: fourbar runs it.
//
//   fourbar-read-mat FILE [--rate-variable NAME] [--sample-rate HZ] [--time-column NAME]
//
// Exit status 0 when the result was written (an error reading the file is a
// result), 2 for a bad command line, 4 when stdout cannot be written.

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "acquire/mat_wire.hpp"
#include "common/child_process.hpp"

int main(int argc, char** argv) {
  using namespace fourbar;
  if (argc < 2 || argc % 2 != 0) {
    std::fprintf(stderr, "usage: fourbar-read-mat FILE [--rate-variable NAME] [--sample-rate HZ] [--time-column NAME]\n"
                         "(run by fourbar to read MATLAB recordings; not a command of its own)\n");
    return 2;
  }
  const std::filesystem::path file = argv[1];
  ReaderOptions options;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--rate-variable") options.rate_variable = value;
    else if (key == "--time-column") options.time_column = value;
    else if (key == "--sample-rate") {
      char* end = nullptr;
      options.sample_rate_hz = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0') {
        std::fprintf(stderr, "fourbar-read-mat: --sample-rate %s is not a number\n", value.c_str());
        return 2;
      }
    } else {
      std::fprintf(stderr, "fourbar-read-mat: unknown option %s\n", key.c_str());
      return 2;
    }
  }
  const std::string result = encode_mat_result([&] { return read_mat_contents(file, options); });
  // _exit: the result is out; what libmatio/libhdf5 keep allocated is the
  // system's to free (a leak checker at exit would otherwise turn their
  // leftovers into a failed read of a good file).
  ::_exit(write_framed_result(STDOUT_FILENO, result) ? 0 : 4);
}
