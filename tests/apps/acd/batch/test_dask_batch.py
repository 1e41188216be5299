"""acd batch on Dask: a LocalCluster of 2 worker processes decomposes a folder of corpus models
with the same results as the local batch (records and files), then finds everything in the cache.

Run by ctest (batch_dask) with the acd binary as first argument; PYTHONPATH names the package."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ACD = None
CORPUS = None
MODELS = ["eight", "handle"]


def records(out):
    with open(os.path.join(out, "batch.jsonl")) as f:
        return {r["name"]: r for r in (json.loads(line) for line in f if line.strip())}


def same_files(test, a, b):
    test.assertEqual(sorted(os.listdir(a)), sorted(os.listdir(b)), a)
    for name in os.listdir(a):
        with open(os.path.join(a, name), "rb") as x, open(os.path.join(b, name), "rb") as y:
            if name == "report.json":
                jx, jy = json.load(x), json.load(y)
                jx.pop("timing"), jy.pop("timing")
                test.assertEqual(jx, jy, os.path.join(a, name))
            else:
                test.assertTrue(x.read() == y.read(), "%s differs" % os.path.join(b, name))


class DaskBatch(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="acd_dask_")
        self.inputs = os.path.join(self.dir, "in")
        os.makedirs(self.inputs)
        for m in MODELS:
            shutil.copy(os.path.join(CORPUS, m + ".off"), self.inputs)
        with open(os.path.join(self.inputs, "garbage.off"), "w") as f:
            f.write("OFF\nnot a mesh\n")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def run_cmd(self, cmd):
        done = subprocess.run(cmd, cwd=self.dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
        return done.returncode, done.stdout + done.stderr

    def test_local_cluster_matches_local_batch(self):
        code, text = self.run_cmd([ACD, "batch", "in", "-o", "local", "-t", "0.2", "--jobs", "2", "-q"])
        self.assertEqual(code, 7, text)  # garbage.off is refused
        code, text = self.run_cmd([sys.executable, "-m", "acd.batch", "in", "-o", "dask", "-t", "0.2",
                                   "--scheduler", "local:2", "--acd", ACD])
        self.assertEqual(code, 7, text)
        self.assertIn("meshes/min", text)
        local, dask = records(os.path.join(self.dir, "local")), records(os.path.join(self.dir, "dask"))
        self.assertEqual(sorted(local), sorted(MODELS + ["garbage"]))
        self.assertEqual(sorted(dask), sorted(local))
        for name in local:
            for field in ("status", "exit_code", "parts", "unresolved", "max_concavity", "key", "input", "error"):
                self.assertEqual(local[name][field], dask[name][field], "%s: %s" % (name, field))
            self.assertFalse(dask[name]["cached"], name)
        self.assertEqual(dask["garbage"]["status"], "refused")
        for name in MODELS:
            self.assertEqual(local[name]["status"], "ok", name)
            same_files(self, os.path.join(self.dir, "local", name), os.path.join(self.dir, "dask", name))

        # The same batch through `acd batch --dask`: every mesh from the (shared) cache.
        code, text = self.run_cmd([ACD, "batch", "in", "-o", "dask", "-t", "0.2", "--dask", "local:2"])
        self.assertEqual(code, 7, text)
        again = records(os.path.join(self.dir, "dask"))
        self.assertTrue(all(r["cached"] for r in again.values()), again)
        for name in MODELS:
            same_files(self, os.path.join(self.dir, "local", name), os.path.join(self.dir, "dask", name))

    def test_refused_options_stop_the_batch(self):
        code, text = self.run_cmd([sys.executable, "-m", "acd.batch", "in", "-o", "dask", "-t", "5",
                                   "--scheduler", "local:2", "--acd", ACD, "-q"])
        self.assertEqual(code, 3, text)
        self.assertIn("options were refused", text)


if __name__ == "__main__":
    ACD, CORPUS = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    try:
        import distributed  # noqa: F401
    except ImportError:
        print("SKIPPED: Dask distributed is not installed (scripts/setup.sh installs python3-distributed)")
        sys.exit(77)
    for m in MODELS:
        if not os.path.exists(os.path.join(CORPUS, m + ".off")):
            print("SKIPPED: corpus missing (scripts/fetch_corpus.sh)")
            sys.exit(77)
    unittest.main(argv=sys.argv[:1], verbosity=2)
