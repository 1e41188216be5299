#include "batch_job.hpp"

#include "sha256.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace acdcli {

namespace {

constexpr const char* kKeyVersion = "acd-batch-cache-1";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool readJson(const fs::path& p, json& j) {
  std::ifstream in(p);
  if (!in) return false;
  try {
    in >> j;
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

/// The worker's last "acd: ..." line (its one-line error), else its last line.
std::string lastError(const fs::path& log) {
  std::istringstream in(slurp(log));
  std::string line, last, lastAcd;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.rfind("acd: ", 0) == 0 && line.find("warning:") == std::string::npos) lastAcd = line.substr(5);
  }
  return lastAcd.empty() ? last : lastAcd;
}

std::string hostName() {
  char b[256] = {0};
  if (::gethostname(b, sizeof b - 1) != 0) return "host";
  return b;
}

/// Test-only (tests/test_batch.cpp, docs/ERRORS.md): ACD_BATCH_TEST_FAULT="abort:FILE,hang:FILE"
/// makes the worker for the mesh file named FILE abort or hang instead of decomposing, to show
/// that one bad mesh does not stop a batch. Never set it otherwise.
char testFault(const std::string& meshPath) {
  const char* spec = std::getenv("ACD_BATCH_TEST_FAULT");
  if (spec == nullptr) return 0;
  const std::string file = fs::path(meshPath).filename().string();
  std::istringstream in(spec);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos || item.substr(colon + 1) != file) continue;
    if (item.compare(0, colon, "abort") == 0) return 'a';
    if (item.compare(0, colon, "hang") == 0) return 'h';
  }
  return 0;
}

std::string statusOf(const acdsandbox::ChildOutcome& o) {
  switch (o.end) {
    case acdsandbox::ChildEnd::TimedOut: return "time_cap";
    case acdsandbox::ChildEnd::MemoryCap: return "memory_cap";
    case acdsandbox::ChildEnd::Signaled: return "crashed";
    case acdsandbox::ChildEnd::StartFailed:
    case acdsandbox::ChildEnd::Stopped: return "failed";
    case acdsandbox::ChildEnd::Exited: break;
  }
  switch (o.exitCode) {
    case 0: return "ok";
    case 4: return "unresolved";
    case 2: return "refused";
    case 1:
    case 3: return "bad_options";  // the same for every mesh: the batch stops
    default: return "failed";
  }
}

/// Whether a cached outcome stands for a run under the current settings.
bool stillValid(const json& r, const BatchSettings& s) {
  const std::string status = r.value("status", "");
  if (status == "ok" || status == "unresolved") return true;
  if (s.retryFailed) return false;
  if (status == "time_cap")  // only a cap at most as long would stop it again
    return s.limits.wallSeconds > 0 && s.limits.wallSeconds <= r.value("time_limit", 0.0);
  if (status == "memory_cap")
    return s.limits.memoryBytes > 0 && double(s.limits.memoryBytes >> 20) <= r.value("memory_limit_mib", 0.0);
  return status == "refused" || status == "crashed" || status == "failed";
}

/// OUT/NAME/ becomes a copy of the cached files; report.json names this input and thread count,
/// as a plain `acd decompose` of it would.
bool materialize(const fs::path& entry, const BatchInput& mesh, const BatchSettings& s, std::string& error) {
  const fs::path dest = fs::path(s.out) / mesh.name;
  std::error_code ec;
  fs::remove_all(dest, ec);
  fs::create_directories(fs::path(s.out) / "logs", ec);
  fs::copy_file(entry / "worker.log", fs::path(s.out) / "logs" / (mesh.name + ".log"),
                fs::copy_options::overwrite_existing, ec);
  if (!fs::exists(entry / "files")) return true;
  fs::copy(entry / "files", dest, fs::copy_options::recursive, ec);
  if (ec) {
    error = "cannot copy the results to " + dest.string() + ": " + ec.message();
    return false;
  }
  const fs::path report = dest / "report.json";
  json j;
  if (readJson(report, j) && j.is_object()) {
    bool changed = false;
    if (j.contains("model") && j["model"] != mesh.path) j["model"] = mesh.path, changed = true;
    if (j.contains("parameters") && j["parameters"].contains("threads") && j["parameters"]["threads"] != s.threads)
      j["parameters"]["threads"] = s.threads, changed = true;
    if (changed) std::ofstream(report) << j.dump(2) << "\n";  // the layout `acd decompose` writes
  }
  return true;
}

json baseRecord(const BatchInput& mesh, const std::string& key) {
  return {{"name", mesh.name}, {"input", mesh.path},     {"key", key},          {"status", ""},
          {"exit_code", nullptr}, {"signal", nullptr},   {"parts", nullptr},    {"unresolved", nullptr},
          {"max_concavity", nullptr}, {"seconds", 0.0},  {"peak_memory_mib", 0.0}, {"error", ""},
          {"cached", false},     {"time_limit", 0.0},    {"memory_limit_mib", 0.0}, {"log", ""}};
}

}  // namespace

bool isFailure(const std::string& status) { return status != "ok" && status != "unresolved"; }

bool batchKey(const std::string& meshPath, const BatchSettings& s, std::string& key, std::string& error) {
  std::string content;
  if (!sha256File(meshPath, content, error)) return false;
  // --threads and the input's path are not part of the key: they do not change the output.
  Sha256 sha;
  sha.update(std::string(kKeyVersion) + "\n" + s.executableHash + "\n" + content + "\n");
  for (const std::string& item : s.keyItems) sha.update(item + "\n");
  key = sha.hex();
  return true;
}

json runBatchJob(const BatchInput& mesh, const BatchSettings& s) {
  std::string key, error;
  if (!mesh.problem.empty() || !batchKey(mesh.path, s, key, error)) {
    json r = baseRecord(mesh, "");
    r["status"] = "unreadable";
    r["error"] = mesh.path + ": " + (mesh.problem.empty() ? error : mesh.problem);
    std::error_code ec;
    fs::remove_all(fs::path(s.out) / mesh.name, ec);
    return r;
  }
  const fs::path entry = fs::path(s.cache) / key;
  json cached;
  if (readJson(entry / "record.json", cached) && stillValid(cached, s)) {
    json r = baseRecord(mesh, key);
    for (auto& [field, value] : cached.items())
      if (field != "name" && field != "input") r[field] = value;
    r["cached"] = true;
    r["log"] = "logs/" + mesh.name + ".log";
    if (!materialize(entry, mesh, s, error)) r["status"] = "failed", r["error"] = error;
    return r;
  }

  // A private folder, renamed into place when complete: concurrent workers (other jobs, other
  // hosts on a shared cache) never see half an entry.
  static std::atomic<int> serial{0};
  const fs::path partial = fs::path(s.cache) / (".partial-" + key.substr(0, 16) + "-" + hostName() + "-" +
                                                std::to_string(::getpid()) + "-" + std::to_string(serial++));
  std::error_code ec;
  fs::remove_all(partial, ec);
  fs::create_directories(partial / "files", ec);
  json r = baseRecord(mesh, key);
  r["time_limit"] = s.limits.wallSeconds;
  r["memory_limit_mib"] = double(s.limits.memoryBytes >> 20);
  if (ec) {
    r["status"] = "failed";
    r["error"] = "cannot create " + partial.string() + ": " + ec.message();
    return r;
  }
  std::vector<std::string> argv{s.executable, "decompose", mesh.path};
  argv.insert(argv.end(), s.decomposeArgs.begin(), s.decomposeArgs.end());
  argv.insert(argv.end(), {"--threads", std::to_string(s.threads), "-q", "-o", (partial / "files").string()});
  std::vector<char*> args;  // prepared before the fork: the child only calls execv
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const char fault = testFault(mesh.path);
  acdsandbox::ChildOptions options;
  options.limits = s.limits;
  options.logPath = (partial / "worker.log").string();
  const acdsandbox::ChildOutcome o = acdsandbox::runInChild(
      [&](int) {
        if (fault == 'a') ::abort();
        while (fault == 'h') ::pause();
        ::execv(args[0], args.data());
        return 127;
      },
      options);

  const std::string status = statusOf(o);
  r["status"] = status;
  if (o.end == acdsandbox::ChildEnd::Exited || (o.end == acdsandbox::ChildEnd::MemoryCap && o.signal == 0))
    r["exit_code"] = o.exitCode;
  if (o.signal != 0) r["signal"] = o.signal;
  r["seconds"] = o.seconds;
  r["peak_memory_mib"] = double(o.peakMemoryBytes) / double(1 << 20);
  json report;
  if ((status == "ok" || status == "unresolved") && readJson(partial / "files" / "report.json", report)) {
    const json totals = report.value("totals", json::object());
    if (totals.contains("components")) r["parts"] = totals["components"];
    if (totals.contains("unresolved")) r["unresolved"] = totals["unresolved"];
    if (totals.contains("max_concavity")) r["max_concavity"] = totals["max_concavity"];
  }
  if (status != "ok") {
    const std::string said = lastError(partial / "worker.log");
    const std::string how = o.describe(s.limits);
    r["error"] = status == "unresolved" || status == "refused" || said.empty() ? (said.empty() ? how : said)
                                                                               : how + ": " + said;
  }
  if (isFailure(status)) fs::remove_all(partial / "files", ec);  // no half results
  if (status == "bad_options" || o.end == acdsandbox::ChildEnd::StartFailed) {
    fs::remove_all(partial, ec);  // not the mesh's fault: nothing to remember
    return r;
  }
  std::ofstream(partial / "record.json") << r.dump(2) << "\n";
  // An entry that no longer stood (a failure retried, a larger cap) is replaced.
  const fs::path stale = partial.string() + ".stale";
  if (fs::exists(entry / "record.json")) fs::rename(entry, stale, ec);
  fs::rename(partial, entry, ec);
  if (ec) fs::remove_all(partial, ec);  // another worker stored it first: same key, same result
  fs::remove_all(stale, ec);
  r["log"] = "logs/" + mesh.name + ".log";
  if (!materialize(fs::exists(entry / "record.json") ? entry : partial, mesh, s, error))
    r["status"] = "failed", r["error"] = error;
  return r;
}

void removeStalePartials(const std::string& cache) {
  const std::string host = hostName();
  std::error_code ec;
  for (fs::directory_iterator it(cache, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string n = it->path().filename().string();
    if (n.rfind(".partial-", 0) != 0) continue;
    // .partial-KEY16-HOST-PID-SERIAL: host names may hold '-', so read PID from the end
    const auto last = n.rfind('-');
    const auto before = last == std::string::npos ? last : n.rfind('-', last - 1);
    if (before == std::string::npos) continue;
    const std::string hostPart = n.substr(9 + 16 + 1, before - (9 + 16 + 1));
    const pid_t pid = static_cast<pid_t>(std::atol(n.substr(before + 1, last - before - 1).c_str()));
    if (hostPart == host && pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code e2;
      fs::remove_all(it->path(), e2);
    }
  }
}

}  // namespace acdcli
