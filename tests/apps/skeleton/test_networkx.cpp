// Agreement with networkx's exact graph_edit_distance (Debian's python3-networkx) on random
// small graphs, for the branch and bound and the binary program. Skipped only when networkx cannot be imported.
#include "ged.hpp"
#include "ged_mip.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

using namespace skeleton;

namespace {

std::string encode(const Graph& g) {
  std::string s = std::to_string(g.nodeCount());
  for (std::size_t i = 0; i < g.edges.size(); ++i)
    s += (i ? "," : " ") + std::to_string(g.edges[i].first) + "-" + std::to_string(g.edges[i].second);
  return s;
}

}  // namespace

TEST(Networkx, ExactDistanceAgreesOnRandomGraphs) {
  if (std::system((std::string(SKELETON_PYTHON) + " -c 'import networkx' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "networkx not importable by " << SKELETON_PYTHON;
  std::mt19937 rng(1234);
  std::vector<std::pair<Graph, Graph>> pairs;
  for (int trial = 0; trial < 40; ++trial) {
    Graph g[2];
    for (Graph& x : g) {
      const int n = std::uniform_int_distribution<int>(0, 6)(rng);
      std::bernoulli_distribution coin(std::uniform_real_distribution<double>(0.1, 0.7)(rng));
      x = makeGraph(n, {});
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
          if (coin(rng)) x.addEdge(a, b);
    }
    pairs.push_back({g[0], g[1]});
  }
  const std::string input = testing::TempDir() + "skeleton_nx_" + std::to_string(::getpid()) + ".txt";
  {
    std::ofstream out(input);
    for (const auto& [a, b] : pairs) out << encode(a) << " | " << encode(b) << '\n';
  }
  const std::string cmd = std::string(SKELETON_PYTHON) + " " + SKELETON_NX_SCRIPT + " < " + input;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = ::pclose(pipe);
  std::remove(input.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "networkx script failed: " << output;
  std::istringstream lines(output);
  int compared = 0, nonZero = 0;
  for (const auto& [a, b] : pairs) {
    std::string word;
    ASSERT_TRUE(static_cast<bool>(lines >> word)) << "networkx gave fewer answers than pairs";
    ASSERT_NE(word, "timeout");
    const int reference = std::stoi(word);
    const GedResult ours = exactGed(a, b);
    ASSERT_TRUE(ours.exact);
    EXPECT_EQ(ours.distance, reference) << encode(a) << " | " << encode(b);
    const GedResult program = mipGed(a, b, bipartiteGed(a, b));
    EXPECT_TRUE(program.exact);
    EXPECT_EQ(program.distance, reference) << encode(a) << " | " << encode(b);
    ++compared;
    nonZero += reference > 0;
  }
  EXPECT_EQ(compared, 40);
  EXPECT_GT(nonZero, 30);
}
