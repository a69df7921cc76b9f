#pragma once
// The fourbar subcommand table. Each subcommand lives in its own file and is
// listed once in commands.cpp; main.cpp dispatches and maps errors to exit
// codes (see common/error.hpp).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <boost/program_options.hpp>

namespace fourbar::cli {

/// Arguments after the subcommand name, plus the whole command line for provenance.
struct Invocation {
  std::vector<std::string> args;
  std::string command_line;
};

struct Command {
  std::string_view name;
  std::string_view summary;
  int (*run)(const Invocation&);
};

std::span<const Command> commands();

/// Parses `inv.args` against `options` (+ positionals). Returns false when
/// --help was given (help already printed to stdout). Bad arguments throw
/// InputError that names the subcommand and points to its --help.
bool parse_arguments(std::string_view command, std::string_view usage, std::string_view details,
                     boost::program_options::options_description& options,
                     const boost::program_options::positional_options_description& positionals,
                     const Invocation& inv, boost::program_options::variables_map& vm);

/// Adds --csv-comments to `options`: the provenance also as `#` lines above
/// each CSV header, as fourbar wrote it before (by default a CSV holds one
/// header row and data, and its provenance is in the JSON beside it).
void add_csv_comments_option(boost::program_options::options_description& options, bool& flag);

/// Adds -q/--quiet (no progress on stderr), the same in every command that shows progress.
void add_quiet_option(boost::program_options::options_description& options, bool& flag);

// Subcommands (one file each).
int run_sim(const Invocation& inv);
int run_rig(const Invocation& inv);
int run_sweep(const Invocation& inv);
int run_acquire(const Invocation& inv);
int run_virtual_rig(const Invocation& inv);
int run_report(const Invocation& inv);
int run_analyze(const Invocation& inv);
int run_inspect(const Invocation& inv);
int run_fit(const Invocation& inv);
int run_tap(const Invocation& inv);

}  // namespace fourbar::cli
