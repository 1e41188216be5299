"""Shared fixtures of the Python suite. Run by ctest (python_tests) with PYTHONPATH=build/python,
ACD_CLI=build/bin/acd and ACD_SOURCE_DIR set; the fallbacks below let pytest run from the repository root."""
import copy
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("ACD_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("ACD_CLI", SOURCE / "build" / "bin" / "acd"))
MESHES = SOURCE / "data" / "meshes"
# Corpus models: the README's (genus 1, about 40 components at tau = 0.05) and a smaller one.
CORPUS_MODEL = MESHES / "elephant.off"
SMALL_MODEL = MESHES / "handle.off"


@pytest.fixture(scope="session")
def cli():
    if not CLI.exists():
        pytest.fail(f"the acd command is not built: {CLI}")
    return CLI


def corpus(path):
    if not path.exists():
        pytest.fail(f"the corpus is missing ({path}): run scripts/fetch_corpus.sh")
    return path


@pytest.fixture(scope="session")
def corpus_model():
    return corpus(CORPUS_MODEL)


@pytest.fixture(scope="session")
def small_model():
    return corpus(SMALL_MODEL)


def run_cli(cli, *args):
    """Runs the acd command; (exit code, stdout, stderr)."""
    p = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def cli_decompose(cli, model, out, *args):
    code, _, err = run_cli(cli, "decompose", model, "-q", "-o", out, *args)
    assert code in (0, 4), err
    return json.loads((pathlib.Path(out) / "report.json").read_text())


# The section of the files `acd decompose --format` wrote (acd.write_simulator_files returns their names).
CLI_ONLY_SECTIONS = ("outputs",)


def without_timing(report):
    """The parts of a report that do not depend on the clock or on where the input came from."""
    r = copy.deepcopy(report)
    for key in ("timing", "model") + CLI_ONLY_SECTIONS:
        r.pop(key, None)
    r.get("hull_budget", {}).pop("seconds", None)
    return r


def l_shape():
    """Three unit cells in an L in the xy-plane, extruded to depth 1: 12 vertices, 20 triangles,
    volume 3, outward faces. Built here, not by the library, to be an independent input."""
    outline = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]  # counter-clockwise seen from +z
    n = len(outline)
    vertices = [(x, y, 0.0) for x, y in outline] + [(x, y, 1.0) for x, y in outline]
    faces = []
    for k in range(1, n - 1):  # fan from (0, 0), which sees every corner
        faces.append((0, k + 1, k))              # bottom, facing -z
        faces.append((n, n + k, n + k + 1))      # top, facing +z
    for a in range(n):
        b = (a + 1) % n
        faces += [(a, b, n + b), (a, n + b, n + a)]  # side, facing out of the outline
    return np.array(vertices, dtype=np.float64), np.array(faces, dtype=np.int64)


def signed_volume(vertices, faces):
    """Divergence theorem, computed here in numpy (an oracle independent of the library)."""
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)
