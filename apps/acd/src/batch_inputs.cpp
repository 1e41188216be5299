#include "batch_inputs.hpp"

#include <acd/scene_io.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>

namespace fs = std::filesystem;

namespace acdcli {

namespace {

// Names of what acd batch and acd report write next to the meshes' folders.
const std::set<std::string> kReserved{"logs", "cache", "report", "index.html", "batch.jsonl"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string safeName(const std::string& raw) {
  std::string s;
  for (unsigned char c : raw) s += (std::isalnum(c) || c == '.' || c == '_' || c == '-' || c == '+') ? char(c) : '_';
  while (!s.empty() && s.front() == '.') s.erase(s.begin());  // no hidden folders
  return s.empty() ? "mesh" : s;
}

struct Found {
  std::string path, base, problem;
};

void addFolder(const fs::path& folder, std::vector<Found>& out) {
  std::error_code ec;
  std::vector<fs::path> files;
  for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    std::error_code ignored;
    if (it->is_directory(ignored)) continue;
    if (isMeshFile(it->path().string())) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    fs::path rel = f.lexically_relative(folder);
    rel.replace_extension();
    std::string base;
    for (const auto& part : rel) base += (base.empty() ? "" : "__") + part.string();
    Found m{f.string(), base, ""};
    std::error_code e2;
    if (!fs::exists(f, e2)) m.problem = "no such file (dangling link)";
    out.push_back(m);
  }
}

void addEntry(const fs::path& p, std::vector<Found>& out, int depth);

void addManifest(const fs::path& manifest, std::vector<Found>& out, int depth) {
  std::ifstream in(manifest);
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    std::size_t first = 0;
    while (first < line.size() && std::isspace(static_cast<unsigned char>(line[first]))) ++first;
    line.erase(0, first);
    if (line.empty() || line[0] == '#') continue;
    fs::path p(line);
    if (p.is_relative()) p = manifest.parent_path() / p;
    addEntry(p, out, depth + 1);
  }
}

void addEntry(const fs::path& p, std::vector<Found>& out, int depth) {
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);
  if (fs::is_directory(st)) return addFolder(p, out);
  const bool exists = fs::exists(st);
  if (exists && !isMeshFile(p.string()) && depth < 4) return addManifest(p, out, depth);
  Found m{p.string(), p.stem().string(), ""};
  if (!exists) m.problem = "no such file";
  else if (!isMeshFile(p.string())) m.problem = "manifests nested too deep";
  out.push_back(m);
}

}  // namespace

bool isMeshFile(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl" || acd::isSceneFormat(path);
}

bool resolveBatchInputs(const std::vector<std::string>& inputs, std::vector<BatchInput>& meshes, std::string& error) {
  std::vector<Found> found;
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (!fs::exists(input, ec)) {
      error = "no such file or folder: " + input;
      return false;
    }
    addEntry(input, found, 0);
  }
  // A mesh reached twice (a folder and a manifest naming the same file) is decomposed once.
  std::set<std::string> seen;
  std::vector<Found> unique;
  for (Found& f : found) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(f.path, ec);
    if (seen.insert(ec ? f.path : canonical.string()).second) unique.push_back(std::move(f));
  }
  std::stable_sort(unique.begin(), unique.end(), [](const Found& a, const Found& b) { return a.path < b.path; });
  std::set<std::string> taken(kReserved);
  meshes.clear();
  for (const Found& f : unique) {
    const std::string base = safeName(f.base);
    std::string name = base;
    for (int k = 2; taken.count(lower(name)); ++k) name = base + "-" + std::to_string(k);
    taken.insert(lower(name));  // case-insensitive: the outputs may land on such a filesystem
    meshes.push_back({name, f.path, f.problem});
  }
  return true;
}

}  // namespace acdcli
