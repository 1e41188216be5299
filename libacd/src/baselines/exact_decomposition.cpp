// Exact convex decomposition with CGAL's convex_decomposition_3 (Nef polyhedra, exact kernel).
// The CGAL call cannot be interrupted, so it runs in a forked worker that streams its progress
// and the pieces' vertices through a pipe; the parent enforces the time cap by killing it.
// This is the only translation unit that includes the Nef headers (they compile slowly).
#include <acd/algo/address_sanitizer.hpp>
#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/hull.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace acd {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// Messages from the worker, each a tag byte and a fixed or counted payload.
enum Tag : char {
  kBuilding = 'B',     // u32 solid: converting it to a Nef polyhedron
  kDecomposing = 'C',  // u32 solid: convex_decomposition_3 running
  kExtracting = 'X',   // u32 solid: reading the pieces out
  kPiece = 'P',        // u32 n, then 3n doubles: the vertices of one convex piece
  kSolidDone = 'D',    // u32 solid, u64 pieces of that solid
  kError = 'E',        // u32 length, then the message
};

// ---------------------------------------------------------------- worker side
class Writer {
 public:
  explicit Writer(int fd) : fd_(fd) {}
  void tag(char t) { raw(&t, 1); }
  void u32(std::uint32_t v) { raw(&v, sizeof v); }
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void text(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    raw(s.data(), s.size());
  }
  void flush() {
    std::size_t done = 0;
    while (done < buffer_.size()) {
      const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) ::_exit(3);  // the parent is gone: nobody to report to
      done += static_cast<std::size_t>(n);
    }
    buffer_.clear();
  }

 private:
  void raw(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    buffer_.insert(buffer_.end(), c, c + n);
    if (buffer_.size() > (1u << 16)) flush();
  }
  int fd_;
  std::vector<char> buffer_;
};

// Collects the vertices of one shell (CGAL's shell-visitor interface).
struct ShellPoints {
  std::vector<Vec3>* out;
  void visit(Nef::Vertex_const_handle v) {
    const auto& p = v->point();
    out->emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  void visit(Nef::Halfedge_const_handle) {}
  void visit(Nef::Halffacet_const_handle) {}
  void visit(Nef::SHalfedge_const_handle) {}
  void visit(Nef::SHalfloop_const_handle) {}
  void visit(Nef::SFace_const_handle) {}
};

Nef toNef(const TriMesh& mesh) {
  SurfaceMesh sm;
  copyToSurfaceMesh(mesh, sm, RefusedFace::Skip);
  return Nef(sm);
}

[[noreturn]] void runWorker(int fd, const std::vector<TriMesh>& solids, std::size_t maxPieces,
                            std::size_t memoryLimit) {
  if (memoryLimit > 0 && !kAddressSanitizer) {  // (no cap under ASan: acd/algo/address_sanitizer.hpp)
    rlimit limit{memoryLimit, memoryLimit};
    ::setrlimit(RLIMIT_AS, &limit);
  }
  Writer w(fd);
  std::size_t sent = 0;
  try {
    for (std::uint32_t s = 0; s < solids.size(); ++s) {
      w.tag(kBuilding), w.u32(s), w.flush();
      Nef nef = toNef(solids[s]);
      if (!nef.is_simple()) throw std::runtime_error("solid " + std::to_string(s) + " is not a 2-manifold Nef polyhedron");
      w.tag(kDecomposing), w.u32(s), w.flush();
      CGAL::convex_decomposition_3(nef);
      w.tag(kExtracting), w.u32(s), w.flush();
      std::uint64_t pieces = 0;
      // The first volume is the unbounded outside; marked volumes are the convex pieces.
      for (auto c = ++nef.volumes_begin(); c != nef.volumes_end(); ++c) {
        if (!c->mark()) continue;
        ++pieces;
        if (sent >= maxPieces) continue;
        std::vector<Vec3> points;
        ShellPoints visitor{&points};
        for (auto shell = c->shells_begin(); shell != c->shells_end(); ++shell)
          nef.visit_shell_objects(Nef::SFace_const_handle(shell), visitor);
        w.tag(kPiece), w.u32(static_cast<std::uint32_t>(points.size()));
        for (const Vec3& p : points) w.f64(p.x()), w.f64(p.y()), w.f64(p.z());
        ++sent;
      }
      w.tag(kSolidDone), w.u32(s), w.u64(pieces), w.flush();
    }
  } catch (const std::bad_alloc&) {
    w.tag(kError), w.text("memory cap of " + std::to_string(memoryLimit >> 20) + " MiB reached"), w.flush();
    ::_exit(2);
  } catch (const std::exception& e) {
    w.tag(kError), w.text(e.what()), w.flush();
    ::_exit(2);
  }
  w.flush();
  ::_exit(0);
}

// ---------------------------------------------------------------- parent side
class Reader {
 public:
  void append(const char* p, std::size_t n) { data_.insert(data_.end(), p, p + n); }
  bool has(std::size_t n) const { return data_.size() - at_ >= n; }
  template <class T>
  T take() {
    T v;
    std::memcpy(&v, data_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::size_t mark() const { return at_; }
  void rewind(std::size_t m) { at_ = m; }
  void compact() {
    data_.erase(data_.begin(), data_.begin() + static_cast<std::ptrdiff_t>(at_));
    at_ = 0;
  }
  std::string text(std::size_t n) {
    std::string s(data_.data() + at_, n);
    at_ += n;
    return s;
  }

 private:
  std::vector<char> data_;
  std::size_t at_ = 0;
};

struct WorkerState {
  char stage = 0;            // last stage tag seen
  std::uint32_t solid = 0;   // solid of that stage
  std::size_t solidsDone = 0;
  std::uint64_t pieceCount = 0;
  std::size_t piecesOfDoneSolids = 0;  // pieces received up to the last finished solid
  std::vector<std::vector<Vec3>> pieces;
  std::string error;
};

// Parses every complete message in the buffer; returns false on a malformed stream.
bool parse(Reader& in, WorkerState& st) {
  for (;;) {
    const std::size_t m = in.mark();
    if (!in.has(1)) break;
    const char tag = in.take<char>();
    bool complete = true;
    switch (tag) {
      case kBuilding:
      case kDecomposing:
      case kExtracting:
        if ((complete = in.has(4))) st.stage = tag, st.solid = in.take<std::uint32_t>();
        break;
      case kPiece: {
        if (!(complete = in.has(4))) break;
        const auto n = in.take<std::uint32_t>();
        if (!(complete = in.has(std::size_t(n) * 24))) break;
        std::vector<Vec3> points(n);
        for (auto& p : points) {
          const double x = in.take<double>(), y = in.take<double>(), z = in.take<double>();
          p = Vec3(x, y, z);
        }
        st.pieces.push_back(std::move(points));
        break;
      }
      case kSolidDone:
        if ((complete = in.has(12))) {
          in.take<std::uint32_t>();
          st.pieceCount += in.take<std::uint64_t>();
          ++st.solidsDone;
          st.piecesOfDoneSolids = st.pieces.size();
        }
        break;
      case kError: {
        if (!(complete = in.has(4))) break;
        const auto n = in.take<std::uint32_t>();
        if ((complete = in.has(n))) st.error = in.text(n);
        break;
      }
      default:
        return false;
    }
    if (!complete) {
      in.rewind(m);
      break;
    }
  }
  in.compact();
  return true;
}

const char* stageName(char stage) {
  switch (stage) {
    case kBuilding: return "building the Nef polyhedron of";
    case kDecomposing: return "decomposing";
    case kExtracting: return "extracting the pieces of";
    default: return "starting on";
  }
}

std::string where(const WorkerState& st, std::size_t solids) {
  return std::string(stageName(st.stage)) + " solid " + std::to_string(st.solid + 1) + " of " + std::to_string(solids);
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

/// Reads the worker's messages until it is done (or dies), the time limit passes (`timedOut`)
/// or a message does not parse (`malformed`), reporting progress on the way.
template <class Elapsed>
void followWorker(int fd, const ExactOptions& options, const Elapsed& elapsed, std::size_t solids, WorkerState& st,
                  bool& timedOut, bool& malformed) {
  Reader in;
  std::vector<char> chunk(1 << 16);
  for (;;) {
    int wait = -1;
    if (options.timeLimitSeconds > 0) {
      const double left = options.timeLimitSeconds - elapsed();
      if (left <= 0) {
        timedOut = true;
        break;
      }
      wait = static_cast<int>(left * 1000.0) + 1;
    }
    if (options.progress) wait = wait < 0 ? 1000 : std::min(wait, 1000);
    pollfd p{fd, POLLIN, 0};
    const int r = ::poll(&p, 1, wait);
    if (options.progress) options.progress(where(st, solids), elapsed());
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) continue;  // the deadline is checked at the top
    const ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // worker finished (or died)
    in.append(chunk.data(), static_cast<std::size_t>(n));
    if (!parse(in, st)) {
      malformed = true;
      break;
    }
  }
}

}  // namespace

ExactDecomposition exactSolidDecomposition(const TriMesh& closedMesh, const ExactOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  ExactDecomposition out;
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  if (!(options.timeLimitSeconds == options.timeLimitSeconds)) {  // NaN
    out.status = Status::error(StatusCode::InvalidParameter, "time limit is not a number");
    return out;
  }
  PrepareOptions prepare;
  prepare.openMeshes = options.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  const PreparedSolid prepared = prepareSolid(closedMesh, prepare);
  if (!prepared.status.ok()) {
    out.status = prepared.status;
    return out;
  }
  out.holesFilled = prepared.holesFilled;
  out.repairs = prepared.repairs;
  TriMesh all;  // the repaired solids together: self-intersections between them count too
  for (const TriMesh& c : prepared.components) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const Face& f : c.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  if (countSelfIntersections(all, 1) > 0) {
    out.status = Status::error(StatusCode::DegenerateFace,
                               "the surface intersects itself (see `acd info`): it bounds no solid that an exact "
                               "decomposition could partition");
    return out;
  }
  out.solids = prepared.components.size();
  out.reflexEdges = countNotches(all);

  int fds[2];
  if (::pipe(fds) != 0) {
    out.status = Status::error(StatusCode::InternalError, std::string("pipe: ") + std::strerror(errno));
    return out;
  }
  std::fflush(nullptr);  // the child must not flush the parent's buffered output again
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    out.status = Status::error(StatusCode::InternalError, std::string("fork: ") + std::strerror(errno));
    return out;
  }
  if (pid == 0) {
    ::close(fds[0]);
    // Never outlive the caller: an interrupted run must not leave hours of work behind.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(3);
    runWorker(fds[1], prepared.components, options.maxPieces, options.memoryLimitBytes);
  }
  ::close(fds[1]);

  WorkerState st;
  bool timedOut = false, malformed = false;
  followWorker(fds[0], options, elapsed, out.solids, st, timedOut, malformed);
  if (timedOut || malformed) ::kill(pid, SIGKILL);
  ::close(fds[0]);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }

  st.pieces.resize(st.piecesOfDoneSolids);  // a solid stopped half-way gives no pieces
  // Pieces are convex, so each is the hull of its vertices (no facet triangulation needed).
  std::size_t degenerate = 0;
  for (const auto& points : st.pieces) {
    TriMesh hull = hullMesh(points);
    if (hull.faces.empty()) {
      ++degenerate;  // a sliver flattened by rounding to doubles
      continue;
    }
    out.pieces.push_back(std::move(hull));
  }
  out.pieceCount = st.pieceCount;
  out.finished = st.solidsDone == out.solids && !timedOut && !malformed && st.error.empty();
  out.unfinishedSolids = out.solids - st.solidsDone;
  const std::string stopped = where(st, out.solids);
  if (timedOut)
    out.note = "not finished within " + seconds(options.timeLimitSeconds) + " s: stopped while " + stopped + " (" +
               std::to_string(out.reflexEdges) + " reflex edges in the input)";
  else if (!st.error.empty())
    out.note = "stopped while " + stopped + ": " + st.error;
  else if (malformed)
    out.status = Status::error(StatusCode::InternalError, "exact decomposition: malformed worker output");
  else if (!out.finished) {
    const std::string how = WIFSIGNALED(wstatus) ? "killed by signal " + std::to_string(WTERMSIG(wstatus))
                                                 : "exit code " + std::to_string(WEXITSTATUS(wstatus));
    out.note = "worker ended (" + how + ") while " + stopped;
  }
  if (out.finished && st.pieceCount > st.pieces.size())
    out.note = "only the first " + std::to_string(st.pieces.size()) + " of " + std::to_string(st.pieceCount) +
               " pieces returned (maxPieces)";
  if (degenerate > 0)
    out.note += (out.note.empty() ? "" : "; ") + std::to_string(degenerate) +
                " sliver pieces have no volume in double precision and were left out";
  out.seconds = elapsed();
  return out;
}

}  // namespace acd
