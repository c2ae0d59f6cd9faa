// The one place where a tool turns outcomes into exit codes and stderr lines:
//   0 success; 1 bad input or failure ("tool: path:line: message"); 2 usage error.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace foldsketch {

// Parses the arguments, runs body and turns its outcome into the exit code.
int run_tool(CLI::App& app, int argc, char** argv, const std::function<void()>& body);

// For the tools that simulate, first thing in main. glibc's malloc keeps even large matrices
// on 4 KiB pages unless its tunables ask for transparent huge pages (GLIBC_TUNABLES=
// glibc.malloc.hugetlb=1), and it reads them only when a process starts. First touching those
// pages is a large share of a drape's time on the machines we measured (a page fault costs
// about 6 us in their virtual machines): the 20K skirt's fast re-drape took 56K page faults
// and 2.15 s, with huge pages 13K and 1.90 s (bench/drape_bench.txt, session 42). So when the
// kernel gives huge pages on request (transparent_hugepage "madvise"; "always" needs nothing,
// "never" gains nothing), this executes the program again with the tunable added. The restart
// costs a second start (about 20 ms for drape-free), so tools that do little computing, or
// load many libraries (export-dxf starts in 0.19 s), do not call it. It returns, doing
// nothing, when GLIBC_TUNABLES already names glibc.malloc.hugetlb (the user's own setting,
// glibc.malloc.hugetlb=0 to opt out, and the restarted process) and when the restart fails.
void restart_with_huge_pages(char** argv);

// The GLIBC_TUNABLES value that adds glibc.malloc.hugetlb=1 to `current` (null: unset), or
// nothing when `current` already sets glibc.malloc.hugetlb.
std::optional<std::string> huge_page_tunables(const char* current);

// Milliseconds since `start` (std::chrono::steady_clock).
double elapsed_ms(std::chrono::steady_clock::time_point start);

} // namespace foldsketch
