// acd-table: a benchmark harness, not part of the acd program; see docs/TABLE.md.
#include "exit_codes.hpp"
#include "table.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"acd-table: the paper's Table 1 over corpus models (solid and surface ACD against exact\n"
               "decomposition), and with --sweep-taus the data of Figures 18-19. Every cell is one run of acd."};
  acdcli::addTableOptions(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? acdcli::kOk : acdcli::kUsage;
  }
  return acdcli::runTable();
}
