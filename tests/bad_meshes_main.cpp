// bad_meshes DIR: writes the generated bad-mesh set (tests/bad_meshes.hpp) as DIR/NAME.off and
// DIR/cases.tsv (name, expected outcome, problem) for bench/bad_meshes.sh.
#include <acd/io.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bad_meshes.hpp"

int main(int argc, char** argv) {
  if (argc != 2 || argv[1][0] == '-') {  // --help and the like are not folders
    std::fprintf(stderr, "usage: bad_meshes DIR\n");
    return 1;
  }
  const std::filesystem::path dir = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::ofstream list(dir / "cases.tsv");
  for (const badmeshes::Case& c : badmeshes::all()) {
    const acd::Status s = acd::writeMesh((dir / (c.name + ".off")).string(), c.mesh);
    if (!s.ok()) {
      std::fprintf(stderr, "bad_meshes: %s\n", s.message.c_str());
      return 1;
    }
    const char* outcome = c.outcome == badmeshes::Outcome::Input  ? "input"
                          : c.outcome == badmeshes::Outcome::Wrap ? "wrap"
                                                                  : "refused";
    list << c.name << '\t' << outcome << '\t' << c.problem << '\n';
  }
  return list ? 0 : 1;
}
