#pragma once
// CLI::App, declared only: the command headers need its name. CLI11 itself costs about 6 s of
// compile time in every file that includes it (measured, -O2), so only the files that add
// options include <CLI/CLI.hpp>.
namespace CLI {
class App;
}  // namespace CLI
