#include "cli.h"

#include <iostream>

#include "core/error.h"

namespace foldsketch {

int run_tool(CLI::App& app, int argc, char** argv, const std::function<void()>& body) {
  const std::string tool = app.get_name();
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": " << e.what() << "\n" << tool << ": run '" << tool << " --help' for usage\n";
    return 2;
  }
  try {
    body();
    return 0;
  } catch (const InputError& e) {
    std::cerr << tool << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << e.what() << "\n";
  }
  return 1;
}

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace foldsketch
