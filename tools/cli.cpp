#include "cli.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include "core/error.h"

namespace foldsketch {

namespace {

constexpr const char* kHugePageTunable = "glibc.malloc.hugetlb=1";

// transparent_hugepage "madvise": huge pages only where a program asks, as the tunable does.
bool huge_pages_on_request() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return modes.find("[madvise]") != std::string::npos;
}

} // namespace

std::optional<std::string> huge_page_tunables(const char* current) {
  const std::string now = current ? current : "";
  if (now.find("glibc.malloc.hugetlb") != std::string::npos) return std::nullopt;
  return now.empty() ? std::string(kHugePageTunable) : now + ":" + kHugePageTunable;
}

void restart_with_huge_pages(char** argv) {
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::optional<std::string> tunables = huge_page_tunables(current);
  if (!tunables || !huge_pages_on_request()) return;
  const std::string before = current ? current : "";
  if (::setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  // Not restarted (no /proc, say): run as we are, with the environment as it was.
  if (current)
    ::setenv("GLIBC_TUNABLES", before.c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

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
