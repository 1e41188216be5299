// See tetgen_run.hpp for why TetGen runs in a child process.
#include "tetgen_run.hpp"

#include <acd/algo/stopwatch.hpp>

#include <sandbox/child_process.hpp>
#include <sandbox/pipe_codec.hpp>

#include <tetgen.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace tetmesh {

namespace {

// Status byte the child sends first.
constexpr std::int32_t kChildOk = 0, kChildTetGenError = 1;

/// Fills TetGen's input from the PLC (arrays allocated with new[], which tetgenio deletes).
void fillInput(const Plc& plc, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(plc.points.size());
  in.pointlist = new REAL[3 * plc.points.size()];
  for (std::size_t i = 0; i < plc.points.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = plc.points[i][k];
  in.numberoffacets = static_cast<int>(plc.facets.size());
  in.facetlist = new tetgenio::facet[plc.facets.size()];
  in.facetmarkerlist = new int[plc.facets.size()];
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::polygon& poly = facet.polygonlist[0];
    tetgenio::init(&poly);
    poly.numberofvertices = static_cast<int>(plc.facets[f].polygon.size());
    poly.vertexlist = new int[plc.facets[f].polygon.size()];
    for (std::size_t k = 0; k < plc.facets[f].polygon.size(); ++k) poly.vertexlist[k] = plc.facets[f].polygon[k];
    in.facetmarkerlist[f] = plc.facets[f].marker;
  }
  in.numberofregions = static_cast<int>(plc.regions.size());
  if (!plc.regions.empty()) {
    in.regionlist = new REAL[5 * plc.regions.size()];
    for (std::size_t r = 0; r < plc.regions.size(); ++r) {
      for (int k = 0; k < 3; ++k) in.regionlist[5 * r + k] = plc.regions[r].seed[k];
      in.regionlist[5 * r + 3] = plc.regions[r].label;
      in.regionlist[5 * r + 4] = -1.0;
    }
  }
}

/// Child side: run TetGen and serialise the result; never returns.
[[noreturn]] void childMain(const Plc& plc, const std::string& switches, int fd) {
  acdsandbox::PipeWriter w;
  // The tetgenio objects are deliberately leaked: after a TetGen error their destructors crash.
  auto* in = new tetgenio;
  auto* out = new tetgenio;
  fillInput(plc, *in);
  std::vector<char> sw(switches.begin(), switches.end());
  sw.push_back('\0');
  try {
    tetgenbehavior b;
    if (!b.parse_commandline(sw.data())) throw 10;
    tetrahedralize(&b, in, out);
  } catch (int code) {
    std::fflush(stdout);
    w.put(kChildTetGenError);
    w.put(static_cast<std::int32_t>(code));
    acdsandbox::writeAll(fd, w.data());
    ::_exit(0);
  }
  std::fflush(stdout);
  w.put(kChildOk);
  const std::int32_t np = out->numberofpoints, nt = out->numberoftetrahedra, nf = out->numberoftrifaces;
  const std::int32_t na = out->numberoftetrahedronattributes;
  w.put(np);
  w.bytes(out->pointlist, sizeof(REAL) * 3 * static_cast<std::size_t>(np));
  w.put(nt);
  for (std::int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k) w.put(static_cast<std::int32_t>(out->tetrahedronlist[t * out->numberofcorners + k]));
  w.put(na);
  for (std::int32_t t = 0; t < nt && na > 0; ++t) w.put(static_cast<double>(out->tetrahedronattributelist[t * na]));
  w.put(nf);
  for (std::int32_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) w.put(static_cast<std::int32_t>(out->trifacelist[3 * f + k]));
  for (std::int32_t f = 0; f < nf; ++f)
    w.put(static_cast<std::int32_t>(out->trifacemarkerlist ? out->trifacemarkerlist[f] : 0));
  acdsandbox::writeAll(fd, w.data());
  ::_exit(0);
}

/// Last line of TetGen's own output that says what went wrong.
std::string tetgenMessage(const std::string& text) {
  std::istringstream in(text);
  std::string line, best, last;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.empty()) continue;
    last = line;
    if (line.find("rror") != std::string::npos || line.find("ntersect") != std::string::npos ||
        line.find("arning") != std::string::npos)
      if (best.empty()) best = line;
  }
  return best.empty() ? last : best;
}

std::string tetgenErrorMeaning(int code) {
  // TetGen 1.5 terminatetetgen() codes.
  switch (code) {
    case 1: return "out of memory";
    case 2: return "internal error";
    case 3: return "self-intersecting or overlapping facets in its input";
    case 4: return "a very small input feature size was detected";
    case 5: return "two very close input facets were detected";
    case 10: return "invalid input or switches";
    default: return "error code " + std::to_string(code);
  }
}

}  // namespace

std::string tetgenSwitches(const TetGenOptions& o) {
  std::ostringstream s;
  s.precision(17);
  s << "p";
  if (o.checkIntersections) {
    s << "d";  // not quiet: the report is the result
    return s.str() + "z";
  } else {
    if (o.radiusEdge > 0) {
      s << "q" << o.radiusEdge;
      if (o.minDihedral > 0) s << "/" << o.minDihedral;
    }
    if (o.maxVolume > 0) s << "a" << o.maxVolume;
    if (o.regions) s << "A";
  }
  s << "Qz";
  return s.str();
}

/// What TetGen cannot check itself without reading out of bounds.
std::string invalidPlc(const Plc& plc) {
  const int n = static_cast<int>(plc.points.size());
  for (int i = 0; i < n; ++i)
    if (!plc.points[i].allFinite()) return "point " + std::to_string(i) + " is not finite";
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    const std::vector<int>& p = plc.facets[f].polygon;
    if (p.size() < 3) return "facet " + std::to_string(f) + " has fewer than 3 corners";
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (p[k] < 0 || p[k] >= n) return "facet " + std::to_string(f) + " refers to point " + std::to_string(p[k]) + ", which does not exist";
      if (p[k] == p[(k + 1) % p.size()]) return "facet " + std::to_string(f) + " repeats point " + std::to_string(p[k]);
    }
  }
  for (std::size_t r = 0; r < plc.regions.size(); ++r)
    if (!plc.regions[r].seed.allFinite()) return "region seed " + std::to_string(r) + " is not finite";
  return {};
}

TetGenResult runTetGen(const Plc& plc, const TetGenOptions& options) {
  TetGenResult r;
  r.switches = tetgenSwitches(options);
  if (const std::string bad = invalidPlc(plc); !bad.empty()) {
    r.error = "invalid input for TetGen: " + bad;
    return r;
  }
  const auto start = acd::Clock::now();

  // TetGen runs in a child process (acd_sandbox) under the time cap; its messages go to a log.
  char logPath[] = "/tmp/tetmesh_tetgen_XXXXXX";
  const int logFd = ::mkstemp(logPath);
  if (logFd < 0) {
    r.error = "cannot create a temporary file for TetGen";
    return r;
  }
  ::close(logFd);
  acdsandbox::ChildOptions child;
  child.pipe = true;
  child.logPath = logPath;
  child.limits.wallSeconds = options.timeoutSeconds;
  const acdsandbox::ChildOutcome outcome = acdsandbox::runInChild(
      [&](int fd) -> int { childMain(plc, r.switches, fd); }, child);
  r.seconds = acd::secondsSince(start);
  std::string log;
  {
    std::ifstream in(logPath);
    std::ostringstream s;
    s << in.rdbuf();
    log = s.str();
  }
  ::unlink(logPath);
  if (outcome.end == acdsandbox::ChildEnd::StartFailed) {
    r.error = "cannot start a process for TetGen: " + outcome.error;
    return r;
  }

  acdsandbox::PipeReader rd(outcome.data);
  std::int32_t kind = -1;
  if (!rd.get(kind)) {
    const std::string said = tetgenMessage(log);
    if (outcome.end == acdsandbox::ChildEnd::TimedOut)
      r.error = "TetGen did not finish within " + std::to_string(options.timeoutSeconds) + " s";
    else if (outcome.end == acdsandbox::ChildEnd::Signaled)
      r.error = std::string("TetGen crashed (") + strsignal(outcome.signal) + ")";
    else
      r.error = "TetGen ended without a result";
    if (!said.empty()) r.error += "; it said: " + said;
    return r;
  }
  if (kind == kChildTetGenError) {
    std::int32_t code = 0;
    rd.get(code);
    r.error = "TetGen refused the input: " + tetgenErrorMeaning(code);
    const std::string said = tetgenMessage(log);
    if (!said.empty()) r.error += "; it said: " + said;
    return r;
  }
  TetMesh& m = r.mesh;
  std::int32_t np = 0, nt = 0, na = 0, nf = 0;
  bool good = rd.get(np) && np >= 0;
  m.points.resize(good ? np : 0);
  for (std::int32_t i = 0; good && i < np; ++i)
    for (int k = 0; k < 3 && good; ++k) good = rd.get(m.points[i][k]);
  good = good && rd.get(nt) && nt >= 0;
  m.tets.resize(good ? nt : 0);
  for (std::int32_t t = 0; good && t < nt; ++t)
    for (int k = 0; k < 4 && good; ++k) {
      std::int32_t v = 0;
      good = rd.get(v) && v >= 0 && v < np;
      m.tets[t][k] = v;
    }
  good = good && rd.get(na);
  m.labels.assign(good ? nt : 0, 0);
  for (std::int32_t t = 0; good && na > 0 && t < nt; ++t) {
    double a = 0;
    good = rd.get(a);
    m.labels[t] = static_cast<int>(std::lround(a));
  }
  good = good && rd.get(nf) && nf >= 0;
  m.faces.resize(good ? nf : 0);
  m.faceMarkers.resize(good ? nf : 0);
  for (std::int32_t f = 0; good && f < nf; ++f)
    for (int k = 0; k < 3 && good; ++k) {
      std::int32_t v = 0;
      good = rd.get(v) && v >= 0 && v < np;
      m.faces[f][k] = v;
    }
  for (std::int32_t f = 0; good && f < nf; ++f) {
    std::int32_t v = 0;
    good = rd.get(v);
    m.faceMarkers[f] = v;
  }
  if (!good) {
    r.error = "TetGen's result could not be read back (truncated or inconsistent)";
    r.mesh = {};
    return r;
  }
  if (options.checkIntersections) {
    // `d` only reports: intersecting facets are listed in its output, not thrown.
    const std::string said = tetgenMessage(log);
    if (log.find("ntersect") != std::string::npos && log.find("No face intersection") == std::string::npos) {
      r.error = "TetGen found intersecting facets: " + said;
      return r;
    }
  }
  // Orient every tet to positive volume.
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t)
    if (tetVolume(m, t) < 0) std::swap(m.tets[t][2], m.tets[t][3]);
  r.ok = true;
  return r;
}

double tetVolume(const TetMesh& mesh, int t) {
  const auto& v = mesh.tets[t];
  const Vec3& a = mesh.points[v[0]];
  return (mesh.points[v[1]] - a).cross(mesh.points[v[2]] - a).dot(mesh.points[v[3]] - a) / 6.0;
}

}  // namespace tetmesh
