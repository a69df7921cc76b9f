#include <iostream>

#include "cli/command.hpp"
#include "common/error.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

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
  } catch (const po::error& e) {
    throw InputError(std::string(command) + ": " + e.what() + "; see 'fourbar " + std::string(command) + " --help'");
  }
  return true;
}

}  // namespace fourbar::cli
