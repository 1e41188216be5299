// acd batch: broken meshes do not stop a batch and are named in batch.jsonl; per-mesh results are
// byte-identical to a plain `acd decompose`; a second run does no work (cache); a killed batch
// resumes with only the rest and leaves no process behind; names, manifests, modes, exit codes.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const std::string kCorpus = std::string(ACD_DATA_DIR) + "/meshes/";

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct ToolRun {
  int code = -1;
  std::string out, err;
  double seconds = 0;
};

class Batch : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("acd_batch_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in");
    if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built: " << ACD_CLI;
    for (const char* m : {"eight", "handle"})
      if (!fs::exists(kCorpus + m + ".off")) GTEST_SKIP() << "corpus missing (scripts/fetch_corpus.sh): " << m;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  /// Copies a corpus model into in/ as NAME, with `extra` appended (distinct bytes: another cache key).
  std::string addModel(const std::string& model, const std::string& name, const std::string& extra = "") {
    const fs::path p = dir_ / "in" / name;
    std::ofstream(p, std::ios::binary) << slurp(kCorpus + model + ".off") << extra;
    return p.string();
  }

  ToolRun acd(const std::string& args, const std::string& env = "") const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = env + (env.empty() ? "" : " ") + quote(ACD_CLI) + " " + args + " >" + quote(out.string()) +
                            " 2>" + quote(err.string()) + " </dev/null";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(cmd.c_str());
    ToolRun r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  std::map<std::string, json> records(const std::string& out = "out") const {
    std::map<std::string, json> r;
    std::istringstream in(slurp(dir_ / out / "batch.jsonl"));
    std::string line;
    while (std::getline(in, line))
      if (!line.empty()) {
        const json j = json::parse(line);
        EXPECT_EQ(r.count(j["name"]), 0u) << "one line per mesh";
        r[j["name"]] = j;
      }
    return r;
  }

  std::string p(const std::string& rel) const { return (dir_ / rel).string(); }

  /// Every file of a plain `acd decompose` of the mesh equals the batch's; report.json up to timing.
  void expectSameAsDecompose(const std::string& name, const std::string& input, const std::string& options,
                             int threads = 1) {
    const std::string plain = p("plain/" + name);
    const ToolRun d = acd("decompose " + quote(input) + " " + options + " --threads " + std::to_string(threads) +
                          " -q -o " + quote(plain));
    ASSERT_TRUE(d.code == 0 || d.code == 4) << d.err;
    std::set<std::string> a, b;
    for (const auto& e : fs::recursive_directory_iterator(plain))
      if (e.is_regular_file()) a.insert(e.path().lexically_relative(plain).string());
    for (const auto& e : fs::recursive_directory_iterator(p("out/" + name)))
      if (e.is_regular_file()) b.insert(e.path().lexically_relative(p("out/" + name)).string());
    EXPECT_EQ(a, b) << name;
    for (const std::string& f : a) {
      if (f == "report.json") {
        json x = json::parse(slurp(plain + "/" + f)), y = json::parse(slurp(p("out/" + name + "/" + f)));
        x.erase("timing"), y.erase("timing");
        EXPECT_EQ(x, y) << name << "/report.json";
      } else {
        EXPECT_TRUE(slurp(plain + "/" + f) == slurp(p("out/" + name + "/" + f))) << name << "/" << f << " differs";
      }
    }
  }

  fs::path dir_;
};

}  // namespace

TEST_F(Batch, BrokenMeshesAreRecordedAndTheRestDecomposed) {
  addModel("eight", "eight.off");
  addModel("handle", "handle.off");
  addModel("eight", "crash.off", "\n# aborts (test switch)\n");
  addModel("handle", "slow.off", "\n# hangs (test switch)\n");
  std::ofstream(dir_ / "in" / "garbage.off") << "OFF\nthis is not a mesh\n";
  fs::create_symlink(dir_ / "nowhere.off", dir_ / "in" / "gone.off");
  const std::string fault = "ACD_BATCH_TEST_FAULT=abort:crash.off,hang:slow.off";
  // The cap must let the real meshes finish on a loaded machine, yet stop the hang soon.
  const std::string cmd = "batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --jobs 2 --time-limit ";

  ToolRun r = acd(cmd + "15", fault);
  EXPECT_EQ(r.code, 7) << r.err;
  auto recs = records();
  ASSERT_EQ(recs.size(), 6u) << r.out;
  EXPECT_EQ(recs["eight"]["status"], "ok");
  EXPECT_EQ(recs["handle"]["status"], "ok");
  EXPECT_EQ(recs["crash"]["status"], "crashed");
  EXPECT_EQ(recs["crash"]["signal"], SIGABRT);
  EXPECT_EQ(recs["slow"]["status"], "time_cap");
  EXPECT_NE(recs["slow"]["error"].get<std::string>().find("time cap of 15 s"), std::string::npos);
  EXPECT_EQ(recs["garbage"]["status"], "refused");
  EXPECT_EQ(recs["garbage"]["exit_code"], 2);
  EXPECT_NE(recs["garbage"]["error"].get<std::string>().find("garbage.off"), std::string::npos);
  EXPECT_EQ(recs["gone"]["status"], "unreadable");
  for (const char* ok : {"eight", "handle"}) {
    // (At tau 0.2 the handle fits one hull within tau of the model.)
    EXPECT_GE(recs[ok]["parts"].get<int>(), std::string(ok) == "handle" ? 1 : 2);
    EXPECT_GT(recs[ok]["peak_memory_mib"].get<double>(), 1.0);
    EXPECT_EQ(recs[ok]["cached"], false);
    expectSameAsDecompose(ok, p("in/" + std::string(ok) + ".off"), "-t 0.2");
  }
  for (const char* failed : {"crash", "slow", "garbage", "gone"}) EXPECT_FALSE(fs::exists(p("out/") + failed)) << failed;
  EXPECT_NE(r.out.find("6 meshes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("time_cap"), std::string::npos) << r.out;

  // Second run: everything comes from the cache, including the failures (the hang is not
  // waited for again under the same cap).
  fs::remove_all(p("out/eight"));
  r = acd(cmd + "15", fault);
  EXPECT_EQ(r.code, 7) << r.err;
  recs = records();
  ASSERT_EQ(recs.size(), 6u);
  for (const auto& [name, rec] : recs)
    if (name != "gone") EXPECT_EQ(rec["cached"], true) << name;
  EXPECT_LT(r.seconds, 10.0) << "the second run did work";
  expectSameAsDecompose("eight", p("in/eight.off"), "-t 0.2");

  // With --retry-failed and no fault, the two meshes that were made to fail are decomposed.
  r = acd(cmd + "300 --retry-failed");
  EXPECT_EQ(r.code, 7) << r.err;
  recs = records();
  EXPECT_EQ(recs["crash"]["status"], "ok");
  EXPECT_EQ(recs["slow"]["status"], "ok");
  EXPECT_EQ(recs["garbage"]["status"], "refused");
  EXPECT_EQ(recs["eight"]["cached"], true);
  expectSameAsDecompose("slow", p("in/slow.off"), "-t 0.2");
}

TEST_F(Batch, KilledBatchResumesWithTheRestAndLeavesNoProcess) {
  addModel("eight", "a.off");
  addModel("handle", "b.off");
  addModel("eight", "c.off", "\n# differs\n");
  addModel("handle", "d.off", "\n# hangs until killed (test switch)\n");
  const std::string out = p("out");
  std::vector<std::string> argv{ACD_CLI, "batch", p("in"), "-o", out, "-t", "0.2", "--jobs", "1", "-q"};
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  std::vector<std::string> env{"ACD_BATCH_TEST_FAULT=hang:d.off"};
  for (char** e = environ; *e; ++e) env.emplace_back(*e);
  std::vector<char*> cenv;
  for (auto& e : env) cenv.push_back(e.data());
  cenv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(::posix_spawn(&pid, ACD_CLI, nullptr, nullptr, cargv.data(), cenv.data()), 0);
  // Meshes run in path order with one job: once three lines are written, the fourth hangs.
  int lines = 0;
  for (int i = 0; i < 600 && lines < 3; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::istringstream in(slurp(fs::path(out) / "batch.jsonl"));
    std::string line;
    lines = 0;
    while (std::getline(in, line)) lines += !line.empty();
  }
  ASSERT_EQ(lines, 3);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  // No process of that batch (its workers share its command line) may survive it.
  bool survivor = true;
  for (int i = 0; i < 50 && survivor; ++i) {
    survivor = false;
    for (const auto& e : fs::directory_iterator("/proc")) {
      const std::string cmdline = slurp(e.path() / "cmdline");
      const std::string state = slurp(e.path() / "stat");
      if (cmdline.find(out) != std::string::npos && state.find(") Z") == std::string::npos) survivor = true;
    }
    if (survivor) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_FALSE(survivor) << "a worker outlived the killed batch";

  const ToolRun r = acd("batch " + quote(p("in")) + " -o " + quote(out) + " -t 0.2 --jobs 1");
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  auto recs = records();
  ASSERT_EQ(recs.size(), 4u);
  for (const char* done : {"a", "b", "c"}) EXPECT_EQ(recs[done]["cached"], true) << done;
  EXPECT_EQ(recs["d"]["cached"], false);
  EXPECT_EQ(recs["d"]["status"], "ok");
  EXPECT_NE(r.out.find("3 from the cache"), std::string::npos) << r.out;
  for (const auto& e : fs::directory_iterator(fs::path(out) / "cache"))
    EXPECT_NE(e.path().filename().string().rfind(".partial-", 0), 0u) << "left behind: " << e.path();
}

TEST_F(Batch, NamesManifestsAndPlan) {
  fs::create_directories(dir_ / "in" / "a");
  fs::create_directories(dir_ / "in" / "b");
  addModel("eight", "a/x.off");
  addModel("eight", "b/x.OBJ");  // extensions in any case; content does not matter for the plan
  addModel("eight", "x.off");
  addModel("eight", "logs.off");  // a name the batch uses itself
  std::ofstream(dir_ / "in" / "notes.txt") << "not a mesh, not in any manifest\n";
  std::ofstream(dir_ / "list.txt") << "# meshes\n\nin/x.off\n  in/a/x.off  \nmissing.off\n";
  const ToolRun r = acd("batch --plan " + quote(p("in")) + " " + quote(p("list.txt")) + " " + quote(p("in/x.off")) +
                    " -o " + quote(p("out")));
  ASSERT_EQ(r.code, 0) << r.err;
  std::map<std::string, json> plan;
  std::istringstream in(r.out);
  std::string line;
  while (std::getline(in, line)) {
    const json j = json::parse(line);
    plan[j["input"].get<std::string>()] = j;
  }
  // in/x.off and in/a/x.off are named three times (folder, manifest, argument): kept once each.
  ASSERT_EQ(plan.size(), 5u) << r.out;
  EXPECT_EQ(plan[p("in/a/x.off")]["name"], "a__x");
  EXPECT_EQ(plan[p("in/b/x.OBJ")]["name"], "b__x");
  EXPECT_EQ(plan[p("in/x.off")]["name"], "x");
  EXPECT_EQ(plan[p("in/logs.off")]["name"], "logs-2");
  EXPECT_EQ(plan[p("missing.off")]["problem"], "no such file");

  const ToolRun missing = acd("batch " + quote(p("nothing-here")) + " -o " + quote(p("out")));
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nothing-here"), std::string::npos) << missing.err;
  fs::create_directories(dir_ / "empty");
  const ToolRun empty = acd("batch " + quote(p("empty")) + " -o " + quote(p("out")));
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(empty.err.find("no meshes"), std::string::npos) << empty.err;
}

TEST_F(Batch, RefusedOptionsStopTheBatch) {
  addModel("eight", "eight.off");
  addModel("handle", "handle.off");
  const ToolRun r = acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 5 --jobs 1");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("options were refused"), std::string::npos) << r.err;
  EXPECT_TRUE(records().empty());
  EXPECT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " --time-limit -1").code, 3);
  EXPECT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " --no-such-option").code, 1);
}

TEST_F(Batch, MemoryCap) {
  addModel("eight", "eight.off");
  // 12 MiB of address space: enough to start acd, not to decompose (its peak is about 9 MiB
  // resident, but thread stacks and allocator arenas count against the address space too).
  const ToolRun r = acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --memory-limit 0.0117");
  EXPECT_EQ(r.code, 7) << r.err;
  auto recs = records();
  EXPECT_EQ(recs["eight"]["status"], "memory_cap") << recs["eight"].dump();
  EXPECT_NE(recs["eight"]["error"].get<std::string>().find("memory cap of 11 MiB"), std::string::npos)
      << recs["eight"].dump();
  EXPECT_FALSE(fs::exists(p("out/eight")));
  // A larger cap runs it again (the cached memory_cap stood only for caps up to 11 MiB).
  const ToolRun again = acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --memory-limit 4");
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(records()["eight"]["status"], "ok");
}

TEST_F(Batch, WorkerAndSummaryModes) {
  const std::string mesh = addModel("handle", "handle.off");
  const ToolRun w = acd("batch --worker " + quote(mesh) + " --name H -o " + quote(p("out")) + " -t 0.2");
  ASSERT_EQ(w.code, 0) << w.err;
  const json rec = json::parse(w.out);
  EXPECT_EQ(rec["name"], "H");
  EXPECT_EQ(rec["status"], "ok");
  EXPECT_TRUE(fs::exists(p("out/H/hulls.obj")));
  EXPECT_FALSE(fs::exists(p("out/batch.jsonl"))) << "--worker leaves batch.jsonl to its caller";
  std::ofstream(p("out/batch.jsonl")) << w.out;
  const ToolRun s = acd("batch --summary -o " + quote(p("out")));
  EXPECT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("1 meshes: 1 ok"), std::string::npos) << s.out;
  // The same mesh under another name: from the cache, with its own path in report.json.
  const std::string copy = addModel("handle", "copy.off");
  const ToolRun again = acd("batch --worker " + quote(copy) + " -o " + quote(p("out")) + " -t 0.2 --threads 2");
  const json rec2 = json::parse(again.out);
  EXPECT_EQ(rec2["cached"], true);
  // Made with one thread, found in the cache for a run with two: report.json says two, as a
  // plain decompose with two threads would (the output does not depend on the thread count).
  expectSameAsDecompose("copy", copy, "-t 0.2", 2);
}

TEST_F(Batch, ProgressBarOnATerminalOnly) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script (util-linux) not installed";
  addModel("eight", "a.off");
  addModel("handle", "b.off");
  // `script` gives acd a terminal; the bar (with an ETA once a mesh has run) goes to it.
  const std::string inner = quote(ACD_CLI) + " batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --jobs 1";
  const std::string cmd = "script -qec " + quote(inner) + " /dev/null > " + quote(p("tty.txt"));
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = slurp(p("tty.txt"));
  EXPECT_NE(text.find("1/2 meshes"), std::string::npos) << text;
  EXPECT_NE(text.find("ETA"), std::string::npos) << text;
  EXPECT_NE(text.find("2/2 meshes"), std::string::npos) << text;
  // Without a terminal: no bar, the summary only.
  fs::remove_all(p("out"));
  const ToolRun plain = acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --jobs 1");
  EXPECT_EQ(plain.code, 0);
  EXPECT_EQ(plain.err.find("meshes,"), std::string::npos) << plain.err;
  EXPECT_NE(plain.out.find("2 meshes: 2 ok"), std::string::npos) << plain.out;
}

TEST_F(Batch, ReportCarriesEvaluationAndEveryMesh) {
  const std::string eight = addModel("eight", "eight.off");
  std::ofstream(dir_ / "in" / "bad.off") << "OFF\nnot a mesh\n";
  ASSERT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 -q").code, 7);
  const ToolRun r = acd("report " + quote(p("out")) + " --evaluate --no-pictures");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string html = slurp(p("out/index.html"));
  const auto start = html.find("<script type=\"application/json\" id=\"acd-data\">");
  ASSERT_NE(start, std::string::npos);
  const auto open = html.find('>', start) + 1;
  const json data = json::parse(html.substr(open, html.find("</script>", open) - open));
  ASSERT_EQ(data["meshes"].size(), 2u);
  const json& e8 = data["meshes"][1]["name"] == "eight" ? data["meshes"][1] : data["meshes"][0];
  const json& bad = data["meshes"][1]["name"] == "eight" ? data["meshes"][0] : data["meshes"][1];
  EXPECT_EQ(bad["status"], "refused");
  EXPECT_TRUE(bad["hulls"].is_null());
  EXPECT_EQ(e8["tau"], 0.2);
  EXPECT_EQ(e8["picture_note"], "no picture (--no-pictures)");
  ASSERT_TRUE(e8["hulls"].is_string());
  EXPECT_TRUE(fs::exists(p("out/" + e8["hulls"].get<std::string>())));
  // The IoU shown is acd evaluate's, run on its own with the same samples (same seed).
  const ToolRun ev = acd("evaluate " + quote(eight) + " " + quote(p("out/eight/hulls.obj")) +
                         " --json --samples 200000 --surface-samples 20000 --threads 1");
  ASSERT_EQ(ev.code, 0) << ev.err;
  const json direct = json::parse(ev.out);
  EXPECT_DOUBLE_EQ(e8["iou"].get<double>(), direct["iou"].get<double>());
  EXPECT_DOUBLE_EQ(e8["excess"].get<double>(), direct["union_to_model"].get<double>() - 1.0);
  EXPECT_GT(e8["iou"].get<double>(), 0.5);
  EXPECT_EQ(acd("report " + quote(p("nowhere"))).code, 2);
}

TEST_F(Batch, EveryDecomposeOptionIsPassedOnWithAllItsValues) {
  const std::string mesh = addModel("handle", "handle.off");
  if (acd("decompose --help").out.find("--format") == std::string::npos) GTEST_SKIP() << "no --format in this build";
  ASSERT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out")) + " -t 0.2 --format urdf glb -q").code, 0);
  expectSameAsDecompose("handle", mesh, "-t 0.2 --format urdf glb");
  ASSERT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out2")) + " -t 0.2 --format urdf,glb -q").code, 0);
  EXPECT_EQ(records("out")["handle"]["key"], records("out2")["handle"]["key"]) << "same options, same key";
  ASSERT_EQ(acd("batch " + quote(p("in")) + " -o " + quote(p("out3")) + " -t 0.2 -q").code, 0);
  EXPECT_NE(records("out")["handle"]["key"], records("out3")["handle"]["key"]) << "other options, other key";
}
