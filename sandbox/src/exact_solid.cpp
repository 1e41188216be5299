// The exact solid decomposition in a capped child (runInChild): the child runs
// acd::decomposeExactSolids and sends each stage, piece and finished solid as a tagged message
// (pipe_codec) as soon as it has it; the parent parses the stream as it arrives, so a run stopped
// by a cap still says where it was and keeps the pieces of the solids it finished.
#include <sandbox/child_process.hpp>
#include <sandbox/exact_solid.hpp>
#include <sandbox/pipe_codec.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace acdsandbox {

namespace {

// Messages from the child, each a tag byte and a fixed or counted payload.
enum Tag : char {
  kStage = 'S',      // ExactStage, u64 solid
  kPiece = 'P',      // u32 n, then 3n doubles: the vertices of one convex piece
  kSolidDone = 'D',  // u64 solid, u64 pieces of that solid
  kError = 'E',      // text: why the child stopped
};

// ---------------------------------------------------------------- child side
/// Writes each message into the pipe: stages and finished solids at once, pieces in blocks.
class PipeListener : public acd::ExactListener {
 public:
  explicit PipeListener(int fd) : fd_(fd) {}
  void stage(acd::ExactStage stage, std::size_t solid) override {
    w_.put(kStage), w_.put(stage), w_.put(static_cast<std::uint64_t>(solid));
    flush();
  }
  void piece(const std::vector<acd::Vec3>& vertices) override {
    w_.put(kPiece), w_.put(static_cast<std::uint32_t>(vertices.size()));
    for (const acd::Vec3& p : vertices) w_.put(p.x()), w_.put(p.y()), w_.put(p.z());
    if (w_.data().size() > (1u << 16)) flush();
  }
  void solidDone(std::size_t solid, std::uint64_t pieces) override {
    w_.put(kSolidDone), w_.put(static_cast<std::uint64_t>(solid)), w_.put(pieces);
    flush();
  }
  void error(const std::string& message) {
    w_.put(kError), w_.text(message);
    flush();
  }
  void flush() {
    if (!writeAll(fd_, w_.data())) ::_exit(3);  // the parent is gone: nobody to report to
    w_ = PipeWriter();
  }

 private:
  int fd_;
  PipeWriter w_;
};

int runChild(int fd, const std::vector<acd::TriMesh>& solids, const acd::ExactOptions& options) {
  PipeListener out(fd);
  try {
    acd::decomposeExactSolids(solids, options.maxPieces, out);
  } catch (const std::bad_alloc&) {
    out.error("memory cap of " + std::to_string(options.memoryLimitBytes >> 20) + " MiB reached");
    return 2;
  } catch (const std::exception& e) {
    out.error(e.what());
    return 2;
  }
  out.flush();
  return 0;
}

// ---------------------------------------------------------------- parent side
struct ChildState {
  acd::ExactStage stage = acd::ExactStage::Starting;  // last stage seen
  std::uint64_t solid = 0;                            // solid of that stage
  std::size_t solidsDone = 0;
  std::uint64_t pieceCount = 0;
  std::size_t piecesOfDoneSolids = 0;  // pieces received up to the last finished solid
  std::vector<std::vector<acd::Vec3>> pieces;
  std::string error;
};

/// Reads one message; false when it is not complete yet (nothing of it is kept then) or
/// `malformed` when its tag is unknown.
bool parseOne(PipeReader& in, ChildState& st, bool& malformed) {
  char tag = 0;
  if (!in.get(tag)) return false;
  switch (tag) {
    case kStage: {
      acd::ExactStage stage{};
      std::uint64_t solid = 0;
      if (!in.get(stage) || !in.get(solid)) return false;
      st.stage = stage, st.solid = solid;
      return true;
    }
    case kPiece: {
      std::uint32_t n = 0;
      if (!in.get(n) || !in.fits(n, 3 * sizeof(double))) return false;
      std::vector<acd::Vec3> points(n);
      for (acd::Vec3& p : points) {
        double x = 0, y = 0, z = 0;
        in.get(x), in.get(y), in.get(z);
        p = acd::Vec3(x, y, z);
      }
      st.pieces.push_back(std::move(points));
      return true;
    }
    case kSolidDone: {
      std::uint64_t solid = 0, pieces = 0;
      if (!in.get(solid) || !in.get(pieces)) return false;
      st.pieceCount += pieces;
      ++st.solidsDone;
      st.piecesOfDoneSolids = st.pieces.size();
      return true;
    }
    case kError: return in.text(st.error);
    default: malformed = true; return false;
  }
}

/// Takes every complete message of `buffer` (the rest stays for the next chunk); false on a
/// malformed stream.
bool parse(std::string& buffer, ChildState& st) {
  PipeReader in(buffer);
  std::size_t consumed = 0;
  bool malformed = false;
  while (in.left() > 0 && parseOne(in, st, malformed)) consumed = buffer.size() - in.left();
  buffer.erase(0, consumed);
  return !malformed;
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

}  // namespace

acd::ExactDecomposition exactSolidDecomposition(const acd::TriMesh& closedMesh, const acd::ExactOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  if (!(options.timeLimitSeconds == options.timeLimitSeconds)) {  // NaN
    acd::ExactDecomposition out;
    out.status = acd::Status::error(acd::StatusCode::InvalidParameter, "time limit is not a number");
    return out;
  }
  std::vector<acd::TriMesh> solids;
  acd::ExactDecomposition out = acd::prepareExactSolids(closedMesh, options, solids);
  if (!out.status.ok()) return out;

  ChildState st;
  std::string buffer;
  bool malformed = false;
  auto where = [&] { return acd::exactStageText(st.stage, st.solid, out.solids); };
  ChildOptions child;
  child.pipe = true;
  // (no address-space cap under ASan: runInChild leaves it out, acd/algo/address_sanitizer.hpp)
  child.limits.memoryBytes = options.memoryLimitBytes;
  if (options.timeLimitSeconds > 0)  // the cap counts from the call, the input's checks included
    child.limits.wallSeconds = std::max(1e-6, options.timeLimitSeconds - elapsed());
  child.onData = [&](std::string_view bytes) {
    buffer.append(bytes);
    if (!parse(buffer, st)) {
      malformed = true;
      return false;  // stop the child
    }
    if (options.progress) options.progress(where(), elapsed());
    return true;
  };
  if (options.progress) child.onTick = [&] { options.progress(where(), elapsed()); };
  const ChildOutcome r = runInChild([&](int fd) { return runChild(fd, solids, options); }, child);
  if (r.end == ChildEnd::StartFailed) {
    out.status = acd::Status::error(acd::StatusCode::InternalError, r.error);
    return out;
  }
  const bool timedOut = r.end == ChildEnd::TimedOut;

  st.pieces.resize(st.piecesOfDoneSolids);  // a solid stopped half-way gives no pieces
  out.pieceCount = st.pieceCount;
  out.finished = st.solidsDone == out.solids && !timedOut && !malformed && st.error.empty();
  out.unfinishedSolids = out.solids - st.solidsDone;
  const std::string stopped = where();
  if (timedOut)
    out.note = "not finished within " + seconds(options.timeLimitSeconds) + " s: stopped while " + stopped + " (" +
               std::to_string(out.reflexEdges) + " reflex edges in the input)";
  else if (!st.error.empty())
    out.note = "stopped while " + stopped + ": " + st.error;
  else if (malformed)
    out.status = acd::Status::error(acd::StatusCode::InternalError, "exact decomposition: malformed worker output");
  else if (!out.finished) {
    const std::string how = r.end == ChildEnd::Signaled ? "killed by signal " + std::to_string(r.signal)
                                                        : "exit code " + std::to_string(r.exitCode);
    out.note = "worker ended (" + how + ") while " + stopped;
  }
  if (out.finished && st.pieceCount > st.pieces.size())
    out.note = "only the first " + std::to_string(st.pieces.size()) + " of " + std::to_string(st.pieceCount) +
               " pieces returned (maxPieces)";
  acd::addExactPieces(st.pieces, out);
  out.seconds = elapsed();
  return out;
}

}  // namespace acdsandbox
