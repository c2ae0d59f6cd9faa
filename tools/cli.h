// The one place where a tool turns outcomes into exit codes and stderr lines:
//   0 success; 1 bad input or failure ("tool: path:line: message"); 2 usage error.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace foldsketch {

int run_tool(CLI::App& app, int argc, char** argv, const std::function<void()>& body);

// Milliseconds since `start` (std::chrono::steady_clock).
double elapsed_ms(std::chrono::steady_clock::time_point start);

} // namespace foldsketch
