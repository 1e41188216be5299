#include "batch.hpp"

#include "batch_inputs.hpp"
#include "batch_job.hpp"
#include "exit_codes.hpp"
#include "report.hpp"
#include "sha256.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace acdcli {

namespace {

struct Forwarded {
  CLI::Option* option;
  std::string name;  // the long name (or short), as passed on
  bool flag;
};

struct BatchArgs {
  std::vector<std::string> inputs;
  std::string out;
  int jobs = 0;
  int threads = 1;
  double timeLimit = 600;
  double memoryGiB = 0;
  std::string cache;
  bool retryFailed = false;
  bool quiet = false;
  bool report = false;
  bool plan = false, worker = false, summary = false;
  std::string name;
  std::string dask;
  std::vector<Forwarded> forwarded;
};
BatchArgs args;

using Clock = std::chrono::steady_clock;

std::string duration(double s) {
  char b[32];
  if (s < 60)
    std::snprintf(b, sizeof b, "%.0fs", s);
  else if (s < 3600)
    std::snprintf(b, sizeof b, "%dm%02ds", int(s) / 60, int(s) % 60);
  else
    std::snprintf(b, sizeof b, "%dh%02dm", int(s) / 3600, int(s) % 3600 / 60);
  return b;
}

/// A one-line bar on a terminal's standard error: done, failures, elapsed, estimated rest.
class Progress {
 public:
  Progress(std::size_t total, bool shown) : total_(total), shown_(shown) {}
  void add(const json& record) {
    ++done_;
    if (isFailure(record.value("status", ""))) ++failed_;
    if (!record.value("cached", false)) ++ran_, ranSeconds_ = elapsed();
    draw();
  }
  void draw() const {
    if (!shown_) return;
    const int width = 30;
    const int filled = total_ ? int(width * done_ / total_) : width;
    // The cache answers at once: estimate from the meshes that ran.
    const std::size_t left = total_ - done_;
    const std::string eta = ran_ > 0 && left > 0 ? ", ETA " + duration(ranSeconds_ / ran_ * left) : "";
    std::fprintf(stderr, "\r  [%s%s] %zu/%zu meshes, %zu failed, %s%s   ", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), done_, total_, failed_, duration(elapsed()).c_str(),
                 eta.c_str());
    std::fflush(stderr);
  }
  void finish() const {
    if (shown_) std::fprintf(stderr, "\n");
  }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  std::size_t total_, done_ = 0, failed_ = 0, ran_ = 0;
  double ranSeconds_ = 0;
  bool shown_;
  Clock::time_point start_ = Clock::now();
};

std::string cell(const json& v, const char* format) {
  if (!v.is_number()) return "-";
  char b[32];
  std::snprintf(b, sizeof b, format, v.get<double>());
  return b;
}

/// The batch's exit code: 0 when every mesh is ok, 4 when some are unresolved and none failed,
/// 7 when any failed.
int batchExit(const std::vector<json>& records) {
  bool failed = false, unresolved = false;
  for (const json& r : records) {
    const std::string status = r.value("status", "");
    failed = failed || isFailure(status);
    unresolved = unresolved || status == "unresolved";
  }
  return failed ? kBatchFailures : unresolved ? kUnresolved : kOk;
}

/// Prints the summary table of a batch; returns its exit code.
int summarize(std::vector<json> records, double wallSeconds, bool table, const std::string& out) {
  std::sort(records.begin(), records.end(),
            [](const json& a, const json& b) { return a.value("name", "") < b.value("name", ""); });
  std::map<std::string, int> counts;
  int cached = 0;
  double workerSeconds = 0;
  for (const json& r : records) {
    ++counts[r.value("status", "?")];
    cached += r.value("cached", false);
    if (!r.value("cached", false)) workerSeconds += r.value("seconds", 0.0);
  }
  const bool all = records.size() <= 40;
  if (table) {
    std::printf("\n  %-28s %-11s %6s %9s %9s  %s\n", "mesh", "status", "parts", "time s", "MiB", "note");
    int shown = 0;
    for (const json& r : records) {
      const std::string status = r.value("status", "?");
      if (!all && !isFailure(status)) continue;
      if (++shown > 40) break;
      std::string note = r.value("error", "");
      if (r.value("cached", false)) note = "(cached) " + note;
      if (note.size() > 70) note = note.substr(0, 67) + "...";
      std::printf("  %-28.28s %-11s %6s %9s %9s  %s\n", r.value("name", "").c_str(), status.c_str(),
                  cell(r["parts"], "%.0f").c_str(), cell(r["seconds"], "%.2f").c_str(),
                  cell(r["peak_memory_mib"], "%.0f").c_str(), note.c_str());
    }
    if (!all) std::printf("  (%s; every mesh is in %s/batch.jsonl)\n", shown ? "failures only" : "no failures", out.c_str());
  }
  std::string line;
  for (const auto& [status, n] : counts) line += (line.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  std::printf("\n  %zu meshes: %s%s\n", records.size(), line.empty() ? "none" : line.c_str(),
              cached ? (" (" + std::to_string(cached) + " from the cache)").c_str() : "");
  if (wallSeconds > 0)
    std::printf("  wall %s, %.1f meshes/min; worker time %.1f s\n", duration(wallSeconds).c_str(),
                60.0 * records.size() / wallSeconds, workerSeconds);
  std::printf("  results in %s/ (one line per mesh in batch.jsonl)\n", out.c_str());
  return batchExit(records);
}

std::string hashOfSelf(std::string& executable) {
  executable = acdsandbox::selfExecutable("acd");
  std::string hex, error;
  if (!sha256File(executable, hex, error)) return "unknown";
  return hex;
}

BatchSettings settings() {
  BatchSettings s;
  s.out = args.out;
  s.cache = args.cache.empty() ? (fs::path(args.out) / "cache").string() : args.cache;
  s.threads = args.threads;
  s.limits.wallSeconds = args.timeLimit;
  s.limits.memoryBytes = static_cast<std::uint64_t>(args.memoryGiB * double(1ull << 30));
  s.retryFailed = args.retryFailed;
  s.executableHash = hashOfSelf(s.executable);
  for (const Forwarded& f : args.forwarded) {
    if (f.flag) {
      for (std::size_t k = 0; k < f.option->count(); ++k) s.decomposeArgs.push_back(f.name), s.keyItems.push_back(f.name);
      continue;
    }
    for (const std::string& v : f.option->results()) {
      s.decomposeArgs.insert(s.decomposeArgs.end(), {f.name, v});
      s.keyItems.push_back(f.name + "=" + v);
    }
  }
  std::sort(s.keyItems.begin(), s.keyItems.end());
  return s;
}

CLI::Option* memoryOption = nullptr;
bool memoryGiven = false;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

/// The command a scheduler runs for one mesh: this acd in --worker mode with this batch's options.
std::vector<std::string> workerCommand(const BatchInput& m, const BatchSettings& s) {
  std::error_code ec;
  std::vector<std::string> c{s.executable, "batch", "--worker", m.path, "--name", m.name,
                             "-o", fs::absolute(s.out, ec).string(), "--threads", std::to_string(s.threads),
                             "--time-limit", number(s.limits.wallSeconds)};
  if (memoryGiven) c.insert(c.end(), {"--memory-limit", number(args.memoryGiB)});
  if (!args.cache.empty()) c.insert(c.end(), {"--cache", fs::absolute(args.cache, ec).string()});
  if (s.retryFailed) c.push_back("--retry-failed");
  c.insert(c.end(), s.decomposeArgs.begin(), s.decomposeArgs.end());
  return c;
}

int runSummary() {
  const fs::path jsonl = fs::path(args.out) / "batch.jsonl";
  std::ifstream in(jsonl);
  if (!in) return fail("batch", acd::Status::error(acd::StatusCode::FileUnreadable, "cannot read " + jsonl.string()));
  std::vector<json> records;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    try {
      records.push_back(json::parse(line));
    } catch (const std::exception&) {
      return fail("batch", acd::Status::error(acd::StatusCode::FileUnreadable, jsonl.string() + ": not JSON lines"));
    }
  }
  return summarize(records, 0, true, args.out);
}

}  // namespace

CLI::App* addBatchCommand(CLI::App& app, const CLI::App& decompose) {
  auto* b = app.add_subcommand(
      "batch", "Decompose many meshes (folders, files, manifests), each in its own capped worker process, "
               "with a cache: re-runs skip finished meshes");
  b->add_option("inputs", args.inputs, "Folders (searched recursively for .off .obj .ply .stl), mesh files, or "
                                       "manifests (one path per line)");
  b->add_option("-o,--out", args.out, "Output folder: OUT/NAME/ per mesh, OUT/batch.jsonl, OUT/logs/")->required();
  b->add_option("-j,--jobs", args.jobs, "Meshes decomposed at the same time (default: the number of cores)");
  b->add_option("--threads", args.threads, "Threads of each decomposition")->capture_default_str();
  b->add_option("--time-limit", args.timeLimit, "Wall-clock cap per mesh in seconds, 0 = none")->capture_default_str();
  memoryOption = b->add_option("--memory-limit", args.memoryGiB,
                "Address-space cap per mesh in GiB, 0 = none (default: physical memory / jobs)");
  b->add_option("--cache", args.cache, "Cache folder, may be shared between batches and hosts (default OUT/cache)");
  b->add_flag("--retry-failed", args.retryFailed, "Run again the meshes whose cached outcome is a failure");
  b->add_flag("-q,--quiet", args.quiet, "No progress bar and no summary table");
  b->add_flag("--report", args.report, "Write OUT/index.html at the end (as acd report OUT)");
  b->add_flag("--plan", args.plan, "Print the meshes found and their names as JSON lines; decompose nothing");
  b->add_flag("--worker", args.worker,
              "Decompose the given mesh files here, one after the other, and print their records as JSON lines "
              "(for schedulers; OUT/batch.jsonl is left to the caller)");
  b->add_option("--name", args.name, "With --worker and one mesh: its name under OUT (default: from --plan's rules)");
  b->add_option("--dask", args.dask,
                "Run on a Dask cluster: a scheduler address (tcp://HOST:8786), a scheduler file, or local:N for N "
                "local worker processes (runs python3 -m acd.batch)");
  b->add_flag("--summary", args.summary, "Print the summary table of OUT/batch.jsonl and exit with the batch's code");
  const std::string group = "Decomposition options (as for acd decompose)";
  for (const CLI::Option* o : decompose.get_options()) {
    if (o->get_positional() || (o->get_lnames().empty() && o->get_snames().empty())) continue;
    const std::string first = o->get_lnames().empty() ? o->get_snames()[0] : o->get_lnames()[0];
    if (first == "help" || first == "out" || first == "quiet" || first == "threads") continue;
    std::string names;
    for (const auto& s : o->get_snames()) names += (names.empty() ? "-" : ",-") + s;
    for (const auto& l : o->get_lnames()) names += (names.empty() ? "--" : ",--") + l;
    const bool flag = o->get_type_size_max() == 0;
    CLI::Option* copy = flag ? b->add_flag(names) : b->add_option(names, CLI::callback_t{}, "");
    copy->description(o->get_description())->group(group);
    if (!flag) {  // take as many values as decompose does (--format urdf glb, or urdf,glb)
      copy->type_size(o->get_type_size_min(), o->get_type_size_max());
      copy->expected(o->get_expected_min(), o->get_expected_max());
      copy->delimiter(o->get_delimiter());
      copy->allow_extra_args(o->get_allow_extra_args());
    }
    args.forwarded.push_back({copy, o->get_lnames().empty() ? "-" + first : "--" + first, flag});
  }
  return b;
}

/// --dask: the same command line, less --dask, handed to python/acd/batch.py (Debian's python3).
/// The file is run as a script, not as `-m acd.batch`: it needs nothing else of the package.
int runOnDask() {
  const std::string self = acdsandbox::selfExecutable("acd");
  // The copy next to this executable (the build tree's python/), else the source tree's.
  std::string script;
  for (const fs::path& dir : {fs::path(self).parent_path().parent_path() / "python", fs::path(ACD_PYTHON_SOURCE_DIR)})
    if (fs::exists(dir / "acd" / "batch.py")) {
      script = (dir / "acd" / "batch.py").string();
      break;
    }
  if (script.empty()) return std::fprintf(stderr, "acd: batch: --dask needs python/acd/batch.py, not found\n"), kInternal;
  std::vector<std::string> argv{"/usr/bin/python3", script, "--scheduler", args.dask, "--acd", self};
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> given;
  for (std::string part; std::getline(in, part, '\0');) given.push_back(part);
  bool afterBatch = false;
  for (std::size_t i = 1; i < given.size(); ++i) {
    if (!afterBatch) {
      afterBatch = given[i] == "batch";
      continue;
    }
    if (given[i] == "--dask") {
      ++i;
      continue;
    }
    if (given[i].rfind("--dask=", 0) == 0) continue;
    argv.push_back(given[i]);
  }
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  std::fflush(nullptr);
  ::execv(cargv[0], cargv.data());
  std::fprintf(stderr, "acd: batch: cannot run /usr/bin/python3 (apt-get install python3-distributed): %s\n",
               std::strerror(errno));
  return kInternal;
}

int runBatch() {
  if (args.summary) return runSummary();
  if (!args.dask.empty()) return runOnDask();
  if (args.inputs.empty()) return std::fprintf(stderr, "acd: batch: no INPUT given\n"), kUsage;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (args.jobs <= 0) args.jobs = static_cast<int>(cores);
  if (args.threads < 0 || !(args.timeLimit >= 0) || !(args.memoryGiB >= 0) || !std::isfinite(args.timeLimit))
    return std::fprintf(stderr, "acd: invalid parameter: --threads, --time-limit and --memory-limit must be >= 0\n"),
           kBadParameter;
  memoryGiven = memoryOption->count() > 0;
  if (!memoryGiven) {  // a worker does not know how many run beside it: assume one per core
    const double physical = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
    args.memoryGiB = physical > 0 ? physical / double(1ull << 30) / (args.worker ? cores : args.jobs) : 0;
  }

  std::vector<BatchInput> meshes;
  std::string error;
  if (!resolveBatchInputs(args.inputs, meshes, error))
    return fail("batch", acd::Status::error(acd::StatusCode::FileUnreadable, error));
  if (!args.name.empty()) {
    if (meshes.size() != 1) return std::fprintf(stderr, "acd: batch: --name needs exactly one mesh\n"), kUsage;
    meshes[0].name = args.name;
  }
  if (args.plan) {
    const BatchSettings s = settings();
    std::error_code ec;
    const std::string cwd = fs::current_path(ec).string();
    for (const BatchInput& m : meshes) {
      json j = {{"name", m.name}, {"input", m.path}, {"command", workerCommand(m, s)}, {"cwd", cwd}};
      if (!m.problem.empty()) j["problem"] = m.problem;
      std::cout << j.dump() << "\n";
    }
    return kOk;
  }
  if (meshes.empty()) {
    std::string all;
    for (const auto& i : args.inputs) all += (all.empty() ? "" : " ") + i;
    return fail("batch", acd::Status::error(acd::StatusCode::FileUnreadable, "no meshes (.off .obj .ply .stl) in " + all));
  }

  const BatchSettings s = settings();
  std::error_code ec;
  fs::create_directories(s.cache, ec);
  if (!ec) fs::create_directories(fs::path(s.out) / "logs", ec);
  if (ec) return outputFailed(s.cache + " (" + ec.message() + ")");

  if (args.worker) {  // one record per line for the scheduler; it writes batch.jsonl
    int code = kOk;
    for (const BatchInput& m : meshes) {
      const json r = runBatchJob(m, s);
      std::cout << r.dump() << std::endl;
      if (r.value("status", "") == "bad_options") code = r.value("exit_code", kUsage);
    }
    return code;
  }

  removeStalePartials(s.cache);
  const fs::path jsonlPath = fs::path(s.out) / "batch.jsonl";
  std::ofstream jsonl(jsonlPath, std::ios::trunc);
  if (!jsonl) return outputFailed(jsonlPath.string());
  Progress progress(meshes.size(), !args.quiet && isatty(fileno(stderr)));
  progress.draw();
  std::vector<json> records;
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  json refusal;
  auto work = [&] {
    for (std::size_t i; !stop && (i = next++) < meshes.size();) {
      json r = runBatchJob(meshes[i], s);
      std::lock_guard<std::mutex> lock(mutex);
      if (r.value("status", "") == "bad_options") {  // the options, not the mesh: stop the batch
        if (!stop.exchange(true)) refusal = r;
        continue;
      }
      jsonl << r.dump() << std::endl;  // flushed per mesh: an interrupted batch keeps its lines
      progress.add(r);
      records.push_back(std::move(r));
    }
  };
  std::vector<std::thread> pool;
  const int workers = std::min<int>(args.jobs, static_cast<int>(meshes.size()));
  for (int k = 0; k < workers; ++k) pool.emplace_back(work);
  for (auto& t : pool) t.join();
  progress.finish();
  if (stop) {
    std::fprintf(stderr, "acd: batch: the decomposition options were refused: %s\n", refusal.value("error", "").c_str());
    return refusal.value("exit_code", kUsage);
  }
  if (!jsonl) return outputFailed(jsonlPath.string());
  const int code = args.quiet ? batchExit(records) : summarize(records, progress.elapsed(), true, s.out);
  if (args.report) {
    ReportOptions r;
    r.out = s.out;
    r.jobs = args.jobs;
    const int written = writeReport(r);
    if (written != kOk) return written;
  }
  return code;
}

}  // namespace acdcli
