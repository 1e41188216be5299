// Decomposes the L-shape with an installed libacd through its facade, acd/acd.hpp; prints
// "acd VERSION: N components".
#include <acd/acd.hpp>

#include <cstdio>

int main() {
  const acd::Decomposition d = acd::decompose(acd::shapes::lShape());
  if (!d.status.ok()) {
    std::fprintf(stderr, "consumer: %s\n", d.status.message.c_str());
    return 1;
  }
  std::printf("acd %s: %zu components\n", ACD_VERSION, d.components.size());
  return d.components.empty() ? 1 : 0;
}
