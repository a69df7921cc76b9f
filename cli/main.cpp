// fourbar: the one command of the toolchain. Dispatches to a subcommand from
// the table in commands.cpp and turns errors into `fourbar: ` messages on
// stderr with the documented exit codes (0 ok, 1 run failed, 2 bad input).

#include <exception>
#include <algorithm>
#include <iostream>
#include <optional>
#include <string_view>
#include <vector>
#include <string>

#include "cli/command.hpp"
#include "cluster/mpi_session.hpp"
#include "common/error.hpp"
#include "common/version.hpp"

namespace {

void print_usage(std::ostream& os) {
  os << "usage: fourbar <command> [options]   (fourbar <command> --help for its options)\n\n"
        "Four-bar linkage test rig with clearance in the coupler-rocker bearing.\n\ncommands:\n";
  for (const auto& c : fourbar::cli::commands()) {
    os << "  " << c.name << std::string(16 - std::min<std::size_t>(15, c.name.size()), ' ') << c.summary << "\n";
  }
  os << "\n  --help, -h      show this help\n  --version       print the version\n\n"
        "exit status: 0 success, 1 the run failed (report: some recordings failed,\n"
        "the report names them), 2 bad arguments or input\n\n"
        "environment: FOURBAR_READ_MAT  path of fourbar-read-mat, the program that reads\n"
        "MATLAB recordings, when it is not beside fourbar\n";
}

/// Optimal string alignment distance (Damerau–Levenshtein with adjacent
/// transpositions): "reprot" is 1 from "report".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

/// The subcommand a mistyped one most likely meant (at most 2 edits away).
std::optional<std::string_view> closest_command(std::string_view typed) {
  std::optional<std::string_view> best;
  std::size_t best_distance = 3;
  for (const auto& c : fourbar::cli::commands())
    if (const std::size_t d = edit_distance(typed, c.name); d < best_distance) best = c.name, best_distance = d;
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fourbar;
  if (argc < 2) {
    print_usage(std::cerr);
    return kExitInputError;
  }
  const std::string first = argv[1];
  if (first == "--help" || first == "-h" || first == "help") {
    print_usage(std::cout);
    return kExitOk;
  }
  if (first == "--version") {
    std::cout << "fourbar " << kVersion << "\n";
    return kExitOk;
  }

  cli::Invocation inv;
  inv.command_line = "fourbar";
  for (int i = 1; i < argc; ++i) inv.command_line += std::string(" ") + argv[i];
  for (int i = 2; i < argc; ++i) inv.args.emplace_back(argv[i]);

  try {
    for (const auto& c : cli::commands())
      if (c.name == first) return c.run(inv);
    std::cerr << "fourbar: unknown command '" << first << "'";
    if (const auto near = closest_command(first)) std::cerr << "; did you mean '" << *near << "'?";
    std::cerr << " (run 'fourbar --help' for the list)\n";
    return kExitInputError;
  } catch (const InputError& e) {
    std::cerr << "fourbar: " << e.what() << "\n";
    MpiSession::abort_all(kExitInputError);  // the other ranks of an MPI job would wait for this one
    return kExitInputError;
  } catch (const RunError& e) {
    std::cerr << "fourbar: " << e.what() << "\n";
    MpiSession::abort_all(kExitRunError);
    return kExitRunError;
  } catch (const std::exception& e) {
    std::cerr << "fourbar: internal error: " << e.what() << " (please report it with the input files)\n";
    MpiSession::abort_all(kExitRunError);
    return kExitRunError;
  }
}
