// fourbar: the one command of the toolchain. Dispatches to a subcommand from
// the table in commands.cpp and turns errors into `fourbar: ` messages on
// stderr with the documented exit codes (0 ok, 1 run failed, 2 bad input).

#include <exception>
#include <iostream>
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
        "the report names them), 2 bad arguments or input\n";
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
    std::cerr << "fourbar: unknown command '" << first << "'; run 'fourbar --help' for the list\n";
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
