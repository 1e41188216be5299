// acd batch: one mesh, start to end. Looks the mesh up in the cache (content hash of the file,
// the decomposition options and the acd executable), otherwise runs `acd decompose` on it in a
// child process under the caps, stores the outcome in the cache and copies the files to
// OUT/NAME/. The local batch and the Dask tasks (python/acd/batch.py, via `acd batch --worker`)
// both go through here, so they share the cache, the caps and the record format.
#pragma once

#include "batch_inputs.hpp"
#include <sandbox/child_process.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace acdcli {

struct BatchSettings {
  std::string out;                          // OUT: OUT/NAME/ per mesh, OUT/logs/NAME.log
  std::string cache;                        // the cache folder (default OUT/cache)
  std::vector<std::string> decomposeArgs;   // options passed on to `acd decompose`, as given
  std::vector<std::string> keyItems;        // the same as sorted "--name=value" items, for the key
  int threads = 1;                          // --threads of each decomposition
  acdsandbox::ChildLimits limits;              // per mesh
  bool retryFailed = false;                 // re-run meshes whose cached outcome is a failure
  std::string executable;                   // the acd binary the workers run
  std::string executableHash;               // part of the cache key: a rebuilt acd recomputes
};

/// Statuses of a record; failures are every status but ok and unresolved.
bool isFailure(const std::string& status);

/// The cache key of a mesh file under these settings; false (with `error`) if unreadable.
bool batchKey(const std::string& meshPath, const BatchSettings& s, std::string& key, std::string& error);

/// Runs (or finds in the cache) one mesh and returns its record: name, input, key, status
/// (ok, unresolved, refused, unreadable, crashed, time_cap, memory_cap, failed, bad_options),
/// exit_code, signal, parts, unresolved, max_concavity, seconds, peak_memory_mib, error, cached,
/// time_limit, memory_limit_mib, log. Never throws on a bad mesh.
nlohmann::json runBatchJob(const BatchInput& mesh, const BatchSettings& s);

/// Removes cache entries left half-written by workers of this host that no longer run.
void removeStalePartials(const std::string& cache);

}  // namespace acdcli
