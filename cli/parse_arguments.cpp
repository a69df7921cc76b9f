#include <iostream>
#include <sstream>
#include <vector>

#include "cli/command.hpp"
#include "common/error.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

/// The name the usage line gives the positional argument that fills
/// option `option` ("SESSION_DIR"), or empty if `option` is not positional.
std::string positional_name(const std::string& option, std::string_view usage,
                            const po::positional_options_description& positionals) {
  std::string bare = option;
  while (!bare.empty() && bare.front() == '-') bare.erase(0, 1);
  std::istringstream words{std::string(usage)};
  std::vector<std::string> names;  // the usage's words outside [...], in order
  for (std::string w; words >> w;) {
    if (w.front() == '[' || w.starts_with("--")) continue;
    names.push_back(w);
  }
  for (unsigned k = 0; k < positionals.max_total_count() && k < names.size(); ++k)
    if (positionals.name_for_position(k) == bare) return names[k];
  return {};
}

}  // namespace

void add_csv_comments_option(po::options_description& options, bool& flag) {
  options.add_options()("csv-comments", po::bool_switch(&flag),
                        "also put the provenance as '#' lines above each CSV header (by default it is only in the "
                        "JSON beside the CSV, so that pandas, Excel and LibreOffice open it without options)");
}

void add_quiet_option(po::options_description& options, bool& flag) {
  options.add_options()("quiet,q", po::bool_switch(&flag), "no progress on stderr");
}

bool parse_arguments(std::string_view command, std::string_view usage, std::string_view details,
                     po::options_description& options, const po::positional_options_description& positionals,
                     const Invocation& inv, po::variables_map& vm) {
  options.add_options()("help,h", "show this help and exit");
  try {
    po::store(po::command_line_parser(inv.args).options(options).positional(positionals).run(), vm);
    if (vm.count("help")) {
      std::cout << "usage: fourbar " << command << " " << usage << "\n\n" << options << "\n" << details;
      return false;
    }
    po::notify(vm);
  } catch (const po::required_option& e) {
    const std::string name = positional_name(e.get_option_name(), usage, positionals);
    if (!name.empty())
      throw InputError(std::string(command) + ": " + name + " is missing; usage: fourbar " + std::string(command) +
                       " " + std::string(usage));
    throw InputError(std::string(command) + ": " + e.what() + "; see 'fourbar " + std::string(command) + " --help'");
  } catch (const po::error& e) {
    throw InputError(std::string(command) + ": " + e.what() + "; see 'fourbar " + std::string(command) + " --help'");
  }
  return true;
}

}  // namespace fourbar::cli
