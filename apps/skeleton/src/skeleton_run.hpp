// The steps of one skeleton run: the models (the given one, deformed files, deformations made
// here), their decompositions and skeletons, the graph edit distances to the original's.
#pragma once

#include "ged.hpp"
#include "graph.hpp"

#include <appcli/console.hpp>

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace skeleton {

/// "skeleton: ..." on stderr.
inline const appcli::Console kConsole{"skeleton"};

/// A status line on stderr when it is a terminal.
void progress(const std::string& line);

struct RunParameters {
  std::string modelPath, outDir = "skeleton-out";
  std::vector<std::string> deformedPaths, deformSpecs;
  double tau = 0.1;
  int exactMaxNodes = 12, mcfRuns = 1, threads = 0;
  double tubeRadius = 0.0;
  long long maxExpansions = 20000000, mipMaxColumns = 3000;
  bool noMcf = false, quiet = false, handleCycles = false;
};

struct Model {
  std::vector<std::string> repairs;  // what prepareSolid changed
  std::string name;    // file stem in OUT
  std::string source;  // the file, or the deformation spec
  std::string summary; // what the deformation did
  acd::TriMesh mesh;
  Graph acd, acdContracted, mcf, mcfContracted;  // acd: the skeleton of parts (parts.hpp)
  Graph components_, componentsContracted;       // the skeleton of the components themselves
  int components = 0, unresolved = 0, parts = 0, genus = 0, partMerges = 0, droppedAdjacencies = 0;
  int loopGrid = 0;                        // parts.hpp: the grid that shows the handles (0: none)
  std::vector<int> partHandles;             // per part, its own handles on that grid
  std::vector<std::pair<int, int>> loopJoints;  // adjacencies of parts a loop passes through
  std::vector<int> vertexPart;                // per mesh vertex, the part it is a corner of
  std::vector<std::vector<int>> partMembers;  // per part, its components
  std::vector<int> partMatch;                 // per part, the original's part it is matched to by vertices (-1: none)
  bool mcfOk = false;
  std::string mcfError;
  std::vector<int> mcfRunNodes;  // node counts of repeated MCF runs
  std::vector<Graph> mcfRunContracted;  // every run's skeleton, degree-2 nodes contracted
  double decomposeSeconds = 0, mcfSeconds = 0;
  GedResult d, d2, mcfD, mcfD2;
  GedResult componentsD, componentsD2;  // of the component skeletons
  bool sharesVertices = false;          // same vertices and faces as the original: matched by them too
  int correspondenceD = 0, correspondenceD2 = 0;  // cost of the vertex-correspondence edit path
  Graph mcfSecond;               // second CGAL run of the same mesh, for the run-to-run distance
  bool hasSecond = false;
  GedResult runD, runD2;         // CGAL skeleton, run 1 against run 2 of the same mesh
  std::vector<GedResult> mcfRunPairsD2;  // D2 of every run of this mesh against every run of the original
};

/// The ranges of the parameters; kOk or kBadParameter after a message.
int checkParameters(const RunParameters& p);
/// The model and the --deformed files, closed and outward (models[0] is the original);
/// every --deform spec checked before the slow work starts.
int loadModels(const RunParameters& p, std::vector<Model>& models);
/// The output folder, and the --deform deformations of the original, each written as OUT/NAME.off.
int makeDeformations(const RunParameters& p, std::vector<Model>& models);
/// Each model's decomposition (rigid-motion invariant), its ACD skeleton and CGAL's.
int decomposeModels(const RunParameters& p, std::vector<Model>& models);
/// The graph edit distances of every deformed model's skeletons to the original's (and of
/// CGAL's second run to its first: its noise floor; and CGAL's D2 over every pair of runs, since
/// its skeleton differs from run to run).
void compareSkeletons(const RunParameters& p, std::vector<Model>& models);

}  // namespace skeleton
