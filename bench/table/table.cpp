// acd-table: every cell is one run of the acd program (`acd decompose ... -q`), so the table
// measures exactly what a user gets, and methods that are not built in (surface ACD) show "n/a"
// until they are. Components and times come from each run's report.json; sizes are those of
// the pieces written as one OBJ file (one object per piece), the same writer for every method.
#include <sandbox/child_process.hpp>
#include "exit_codes.hpp"
#include "table.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace acdcli {

namespace {

struct TableArgs {
  std::vector<std::string> models{"elephant", "knot", "eight", "handle", "mushroom", "pipe", "u", "joint"};
  std::string data = "data/meshes";
  std::vector<double> taus{0.2, 0.02};
  double exactTimeLimit = 600.0;
  double exactMemoryGiB = 8.0;
  std::vector<std::string> sweepModels;
  std::vector<double> sweepTaus;
  std::string markdown;  // empty: standard output
  std::string jsonPath;
  std::string work;
  bool keep = false;
  int threads = 0;
  std::string commandLine;
  std::string acd;  // the acd program; empty: beside this one
};
TableArgs args;

/// One decomposition run and what it produced.
struct Cell {
  std::string status;  // ok, unresolved, unfinished, refused, n/a, failed
  long components = -1;
  long unresolved = 0;
  std::uintmax_t bytes = 0;
  double seconds = 0.0;
  std::string note;
};

json toJson(const Cell& c) {
  return {{"status", c.status}, {"components", c.components}, {"unresolved", c.unresolved},
          {"bytes", c.bytes},   {"seconds", c.seconds},       {"note", c.note}};
}

bool progressShown() { return isatty(fileno(stderr)) != 0; }

void progress(const std::string& text) {
  if (!progressShown()) return;
  std::fprintf(stderr, "\r  table: %-70.70s", text.c_str());
  std::fflush(stderr);
}

/// The acd program the runs use: --acd, else the one beside this program.
std::string acdPath() {
  if (!args.acd.empty()) return args.acd;
  return (fs::path(acdsandbox::selfExecutable("acd-table")).parent_path() / "acd").string();
}

std::string format(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

/// Runs `argv` with stdout and stderr into `log`; returns the exit code (128 + signal if killed).
int runCommand(const std::vector<std::string>& argv, const std::string& log) {
  acdsandbox::ChildOptions options;
  options.logPath = log;
  const acdsandbox::ChildOutcome o = acdsandbox::runProgram(argv, options);
  if (o.end == acdsandbox::ChildEnd::StartFailed) return -1;
  return o.signal != 0 ? 128 + o.signal : o.exitCode;
}

std::string lastLine(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  if (last.rfind("acd: ", 0) == 0) last = last.substr(5);
  return last;
}

/// The pieces a run wrote, whatever its mode: one OBJ with objects, or one file per piece.
std::vector<acd::TriMesh> piecesOf(const fs::path& dir) {
  for (const char* name : {"pieces.obj", "patches.obj", "components.obj"}) {
    if (!fs::exists(dir / name)) continue;
    acd::ObjObjects o = acd::readObjObjects((dir / name).string());
    if (o.status.ok()) return o.objects;
  }
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if ((n.rfind("component_", 0) == 0 || n.rfind("patch_", 0) == 0) && e.path().extension() == ".off")
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<acd::TriMesh> out;
  for (const auto& f : files) {
    acd::ReadResult r = acd::readMesh(f.string());
    if (r.status.ok()) out.push_back(std::move(r.mesh));
  }
  return out;
}

std::uintmax_t objBytes(const std::vector<acd::TriMesh>& meshes, const fs::path& file) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < meshes.size(); ++i) names.push_back("piece_" + std::to_string(i));
  if (!acd::writeObjObjects(file.string(), meshes, names).ok()) return 0;
  std::error_code ec;
  const auto n = fs::file_size(file, ec);
  fs::remove(file, ec);
  return ec ? 0 : n;
}

/// One `acd decompose MODEL EXTRA -q -o DIR` and its results.
Cell runDecompose(const std::string& model, const std::vector<std::string>& extra, const std::string& tag) {
  const fs::path dir = fs::path(args.work) / tag;
  std::error_code ec;
  fs::remove_all(dir, ec);
  std::vector<std::string> argv{acdPath(), "decompose", model};
  argv.insert(argv.end(), extra.begin(), extra.end());
  argv.insert(argv.end(), {"-q", "-o", dir.string(), "--threads", std::to_string(args.threads)});
  const std::string log = (fs::path(args.work) / (tag + ".log")).string();
  const auto start = std::chrono::steady_clock::now();
  const int code = runCommand(argv, log);
  Cell c;
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (code == 0 || code == 4) {
    std::ifstream in(dir / "report.json");
    json report;
    try {
      in >> report;
    } catch (const std::exception&) {
      c.status = "failed";
      c.note = "no readable report.json";
      return c;
    }
    const json& totals = report.value("totals", json::object());
    c.components = totals.value("components", -1L);
    c.unresolved = totals.value("unresolved", 0L);
    if (report.contains("timing") && report["timing"].contains("total_seconds"))
      c.seconds = report["timing"]["total_seconds"].get<double>();
    const bool finished = totals.value("finished", true);
    c.status = !finished ? "unfinished" : (code == 4 ? "unresolved" : "ok");
    c.note = totals.value("note", std::string());
    if (c.status == "unresolved" && c.note.empty()) c.note = lastLine(log);
    if (finished) c.bytes = objBytes(piecesOf(dir), fs::path(args.work) / (tag + "-size.obj"));
  } else if (code == 1) {
    c.status = "n/a";
    c.note = lastLine(log);
  } else if (code == 2) {
    c.status = "refused";
    c.note = lastLine(log);
  } else {
    c.status = "failed";
    c.note = "exit code " + std::to_string(code) + ": " + lastLine(log);
  }
  if (!args.keep) fs::remove_all(dir, ec), fs::remove(log, ec);
  return c;
}

/// Surface ACD is another mode of `acd decompose`; probe it on a box.
bool surfaceAcdAvailable() {
  const fs::path box = fs::path(args.work) / "probe-box.off";
  if (!acd::writeMesh(box.string(), acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(1, 1, 1))).ok()) return false;
  const Cell c = runDecompose(box.string(), {"--surface"}, "probe");
  std::error_code ec;
  fs::remove(box, ec);
  return c.status == "ok" || c.status == "unresolved";
}

std::string modelPath(const std::string& name) {
  if (name.find('/') != std::string::npos || fs::path(name).has_extension()) return name;
  return (fs::path(args.data) / (name + ".off")).string();
}

std::string modelName(const std::string& name) { return fs::path(name).stem().string(); }

std::string humanBytes(std::uintmax_t b) {
  char s[32];
  if (b >= 10u * 1024 * 1024)
    std::snprintf(s, sizeof s, "%.0f MB", b / 1048576.0);
  else if (b >= 1024 * 1024)
    std::snprintf(s, sizeof s, "%.1f MB", b / 1048576.0);
  else
    std::snprintf(s, sizeof s, "%.0f KB", std::max<double>(1, b / 1024.0));
  return s;
}

std::string cellText(const Cell& c) {
  char s[128];
  if (c.status == "ok" || c.status == "unresolved") {
    std::snprintf(s, sizeof s, "%ld%s / %s / %.2f s", c.components,
                  c.unresolved > 0 ? (" (" + std::to_string(c.unresolved) + " unres.)").c_str() : "",
                  humanBytes(c.bytes).c_str(), c.seconds);
    return s;
  }
  if (c.status == "unfinished") return "not finished in " + format(args.exactTimeLimit) + " s";
  if (c.status == "refused") {
    std::string why = c.note;
    const auto colon = why.find(": ");
    if (colon != std::string::npos && why.substr(0, colon).find('/') != std::string::npos) why = why.substr(colon + 2);
    if (why.size() > 40) why = why.substr(0, 40) + "...";
    return "refused: " + why;
  }
  return c.status;
}

struct Method {
  std::string key, title;
  std::vector<std::string> extra;
  bool surface = false;
};

std::vector<Method> methods() {
  std::vector<Method> m;
  for (double t : args.taus) m.push_back({"solid_acd_" + format(t), "solid ACD<sub>" + format(t) + "</sub>", {"-t", format(t)}});
  m.push_back({"solid_ecd", "solid ECD",
               {"--exact", "--exact-time-limit", format(args.exactTimeLimit), "--exact-memory", format(args.exactMemoryGiB)}});
  for (double t : args.taus)
    m.push_back({"surface_acd_" + format(t), "surface ACD<sub>" + format(t) + "</sub>", {"--surface", "-t", format(t)}, true});
  m.push_back({"surface_ecd", "surface ECD", {"--exact", "--surface"}});
  return m;
}

/// Mean over models of a/b (the paper averages per-model percentages).
struct RatioStats {
  double sum = 0;
  int n = 0;
  void add(double r) { sum += r, ++n; }
  std::string percent() const {
    if (n == 0) return "n/a";
    char s[32];
    const double v = 100.0 * sum / n;
    std::snprintf(s, sizeof s, v < 0.01 ? "%.2g %%" : "%.3g %%", v);
    return s + std::string(" (") + std::to_string(n) + ")";
  }
  std::string factor() const {
    if (n == 0) return "n/a";
    char s[32];
    std::snprintf(s, sizeof s, "%.3g (%d)", sum / n, n);
    return s;
  }
};

bool usable(const Cell& c) { return (c.status == "ok" || c.status == "unresolved") && c.components > 0; }

int writeOutputs(const json& j, const std::string& md) {
  if (args.markdown.empty()) {
    std::cout << md;
  } else {
    std::ofstream out(args.markdown);
    out << md;
    if (!out) return std::fprintf(stderr, "acd: output: cannot write %s\n", args.markdown.c_str()), kOutputFailed;
  }
  if (!args.jsonPath.empty()) {
    std::ofstream out(args.jsonPath);
    out << j.dump(2) << "\n";
    if (!out) return std::fprintf(stderr, "acd: output: cannot write %s\n", args.jsonPath.c_str()), kOutputFailed;
  }
  return kOk;
}

}  // namespace

void addTableOptions(CLI::App& app) {
  CLI::App* t = &app;
  t->add_option("--models", args.models, "Models: names in --data (NAME.off) or paths")->delimiter(',')->capture_default_str();
  t->add_option("--data", args.data, "Folder of the corpus models")->capture_default_str();
  t->add_option("--taus", args.taus, "Tolerances of the ACD columns")->delimiter(',')->capture_default_str();
  t->add_option("--exact-time-limit", args.exactTimeLimit, "Cap of each solid ECD run in seconds (0 = none)")
      ->capture_default_str();
  t->add_option("--exact-memory", args.exactMemoryGiB, "Memory cap of each solid ECD run in GiB")->capture_default_str();
  t->add_option("--sweep-taus", args.sweepTaus,
                "Also run solid and surface ACD at these tolerances, with and without feature grouping")
      ->delimiter(',');
  t->add_option("--sweep-models", args.sweepModels, "Models of the sweep (default: --models)")->delimiter(',');
  t->add_option("--markdown", args.markdown, "Write the Markdown tables here (default: standard output)");
  t->add_option("--json", args.jsonPath, "Write every measurement as JSON here (input of scripts/plot_table.py)");
  t->add_option("--work", args.work, "Scratch folder for the runs' outputs (default: a fresh temporary folder)");
  t->add_flag("--keep", args.keep, "Keep every run's output folder and log in --work");
  t->add_option("--threads", args.threads, "Worker threads of each ACD run, 0 = all cores")->capture_default_str();
  t->add_option("--acd", args.acd, "The acd program to run (default: the one beside acd-table)");
}

int runTable() {
  for (double t : args.taus)
    if (!(t > 0) || !std::isfinite(t)) return std::fprintf(stderr, "acd: invalid parameter: tau %g must be > 0\n", t), kBadParameter;
  for (double t : args.sweepTaus)
    if (!(t > 0) || !std::isfinite(t)) return std::fprintf(stderr, "acd: invalid parameter: tau %g must be > 0\n", t), kBadParameter;
  if (!(args.exactTimeLimit >= 0) || !(args.exactMemoryGiB >= 0))
    return std::fprintf(stderr, "acd: invalid parameter: exact caps must be >= 0\n"), kBadParameter;
  if (args.sweepModels.empty()) args.sweepModels = args.models;
  {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string part;
    while (std::getline(in, part, '\0')) args.commandLine += (args.commandLine.empty() ? "acd-table" : " " + part);
  }

  // Read every model first: a typo fails now, not after an hour of runs.
  struct Model {
    std::string name, path;
    acd::TriMesh mesh;
  };
  std::vector<Model> models;
  auto load = [&](const std::string& name) -> int {
    for (const auto& m : models)
      if (m.path == modelPath(name)) return kOk;
    acd::ReadResult r = acd::readMesh(modelPath(name));
    if (!r.status.ok()) {
      std::fprintf(stderr, "acd: %s\n", r.status.message.c_str());
      return kBadInput;
    }
    models.push_back({modelName(name), modelPath(name), std::move(r.mesh)});
    return kOk;
  };
  for (const auto& n : args.models)
    if (const int e = load(n)) return e;
  for (const auto& n : args.sweepModels)
    if (const int e = load(n)) return e;

  const bool ownWork = args.work.empty();
  if (ownWork) args.work = (fs::temp_directory_path() / ("acd-table-" + std::to_string(::getpid()))).string();
  std::error_code ec;
  fs::create_directories(args.work, ec);
  if (ec) return std::fprintf(stderr, "acd: output: cannot create %s\n", args.work.c_str()), kOutputFailed;

  const bool surfaceAcd = surfaceAcdAvailable();
  const std::vector<Method> ms = methods();
  json j;
  j["command"] = args.commandLine;
  j["surface_acd_available"] = surfaceAcd;
  j["exact_time_limit_seconds"] = args.exactTimeLimit;
  j["taus"] = args.taus;
  j["models"] = json::array();

  std::ostringstream md;
  md << "| model | \\|e\\| | notch % | model size |";
  for (const auto& m : ms) md << " " << m.title << " |";
  md << "\n|---|---:|---:|---:|";
  for (std::size_t i = 0; i < ms.size(); ++i) md << "---:|";
  md << "\n";

  std::vector<std::vector<Cell>> cells;
  for (const std::string& name : args.models) {
    const Model& model = *std::find_if(models.begin(), models.end(), [&](const Model& m) { return m.path == modelPath(name); });
    const acd::MeshDiagnosis d = acd::diagnose(model.mesh);
    const int reflex = acd::countNotches(model.mesh);
    const std::uintmax_t modelBytes = objBytes({model.mesh}, fs::path(args.work) / "model-size.obj");
    json row = {{"model", model.name}, {"path", model.path}, {"edges", d.edges}, {"reflex_edges", reflex},
                {"notch_percent", d.edges > 0 ? 100.0 * reflex / d.edges : 0.0}, {"model_bytes", modelBytes},
                {"closed", d.closed}, {"runs", json::object()}};
    char head[160];
    std::snprintf(head, sizeof head, "| %s | %d | %.1f | %s |", model.name.c_str(), d.edges,
                  d.edges > 0 ? 100.0 * reflex / d.edges : 0.0, humanBytes(modelBytes).c_str());
    md << head;
    std::vector<Cell> rowCells;
    for (const auto& m : ms) {
      progress(model.name + ": " + m.key);
      Cell c;
      if (m.surface && !surfaceAcd) {
        c.status = "n/a";
        c.note = "surface ACD is not available in this build";
      } else {
        c = runDecompose(model.path, m.extra, model.name + "-" + m.key);
      }
      row["runs"][m.key] = toJson(c);
      md << " " << cellText(c) << " |";
      rowCells.push_back(c);
    }
    md << "\n";
    cells.push_back(rowCells);
    j["models"].push_back(row);
  }
  md << "\nEach cell: components / size of the pieces as one OBJ / time. \"not finished\": the solid ECD hit its cap.\n";

  // The paper's Result 1-2 summary: per-model ratios, averaged over the models where both ran.
  auto indexOf = [&](const std::string& key) {
    for (std::size_t i = 0; i < ms.size(); ++i)
      if (ms[i].key == key) return static_cast<int>(i);
    return -1;
  };
  md << "\n| | % solid ECD #components | % solid ECD size | solid ECD time / ACD time | % surface ECD #components | "
        "% surface ECD size |\n|---|---:|---:|---:|---:|---:|\n";
  json summary = json::object();
  for (double t : args.taus) {
    const int solid = indexOf("solid_acd_" + format(t)), surface = indexOf("surface_acd_" + format(t));
    const int secd = indexOf("solid_ecd"), fecd = indexOf("surface_ecd");
    RatioStats sc, ss, st, fc, fs_;
    for (const auto& row : cells) {
      if (usable(row[solid]) && usable(row[secd])) {
        sc.add(double(row[solid].components) / row[secd].components);
        if (row[secd].bytes > 0) ss.add(double(row[solid].bytes) / row[secd].bytes);
        if (row[solid].seconds > 0) st.add(row[secd].seconds / row[solid].seconds);
      }
      if (usable(row[surface]) && usable(row[fecd])) {
        fc.add(double(row[surface].components) / row[fecd].components);
        if (row[fecd].bytes > 0) fs_.add(double(row[surface].bytes) / row[fecd].bytes);
      }
    }
    md << "| ACD<sub>" << format(t) << "</sub> | " << sc.percent() << " | " << ss.percent() << " | " << st.factor()
       << " | " << fc.percent() << " | " << fs_.percent() << " |\n";
    summary[format(t)] = {{"solid_components_ratio", sc.n ? sc.sum / sc.n : -1.0}, {"solid_size_ratio", ss.n ? ss.sum / ss.n : -1.0},
                          {"solid_ecd_time_over_acd", st.n ? st.sum / st.n : -1.0}, {"models_compared", sc.n},
                          {"surface_components_ratio", fc.n ? fc.sum / fc.n : -1.0},
                          {"surface_size_ratio", fs_.n ? fs_.sum / fs_.n : -1.0}, {"surface_models_compared", fc.n}};
  }
  md << "\nMeans of per-model ratios over the models where both decompositions finished (their count in brackets).\n";
  j["summary"] = summary;

  // Figures 18-19: components and time against tau, with and without feature grouping.
  if (!args.sweepTaus.empty()) {
    j["sweep"] = json::array();
    md << "\n| model | decomposition | τ | feature grouping | components | time (s) |\n|---|---|---:|:---:|---:|---:|\n";
    for (const std::string& name : args.sweepModels) {
      const std::string path = modelPath(name);
      for (const bool surface : {false, true}) {
        if (surface && !surfaceAcd) continue;
        for (const bool grouping : {true, false})
          for (double t : args.sweepTaus) {
            std::vector<std::string> extra{"-t", format(t)};
            if (surface) extra.push_back("--surface");
            if (!grouping) extra.push_back("--no-grouping");
            const std::string kind = surface ? "surface" : "solid";
            progress(modelName(name) + ": " + kind + " tau " + format(t) + (grouping ? "" : " no grouping"));
            const Cell c = runDecompose(path, extra, modelName(name) + "-sweep");
            json e = toJson(c);
            e["model"] = modelName(name), e["kind"] = kind, e["grouping"] = grouping, e["tau"] = t;
            j["sweep"].push_back(e);
            char line[200];
            std::snprintf(line, sizeof line, "| %s | %s | %g | %s | %s | %s |\n", modelName(name).c_str(), kind.c_str(), t,
                          grouping ? "on" : "off",
                          usable(c) ? (std::to_string(c.components) + (c.unresolved ? " (" + std::to_string(c.unresolved) + " unres.)" : "")).c_str()
                                    : c.status.c_str(),
                          usable(c) ? format(std::round(c.seconds * 1000) / 1000).c_str() : "");
            md << line;
          }
      }
    }
  }
  if (progressShown()) std::fprintf(stderr, "\r%80s\r", "");
  if (ownWork && !args.keep) fs::remove_all(args.work, ec);
  return writeOutputs(j, md.str());
}

}  // namespace acdcli
