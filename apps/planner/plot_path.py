#!/usr/bin/python3
"""The free space's ACD components (one colour each), the best path's reference points and the
robot (a box) at a few states along it, as in the paper's Figure 3.
Usage: plot_path.py FREE_SPACE_ACD_OBJ BEST_PATH_TXT OUT_PNG SX SY SZ [TITLE]
(the OBJ and the path are what `planner` writes; SX SY SZ is the robot box's size)."""
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_objects(path):
    vertices, objects = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "o":
            objects.append([])
        elif parts[0] == "v":
            vertices.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            if not objects:
                objects.append([])
            objects[-1].append([int(p.split("/")[0]) - 1 for p in parts[1:4]])
    return np.array(vertices), objects


def rotation(q):  # x y z w
    x, y, z, w = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def box_faces(centre, R, half):
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    corners = centre + (signs * half) @ R.T
    quads = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]]
    return [[corners[i] for i in q] for q in quads]


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    vertices, objects = read_objects(sys.argv[1])
    path = np.loadtxt(sys.argv[2], ndmin=2)
    half = 0.5 * np.array([float(v) for v in sys.argv[4:7]])
    fig = plt.figure(figsize=(8, 5.5), dpi=120)
    ax = fig.add_subplot(projection="3d")
    colours = plt.cm.tab10.colors
    for i, faces in enumerate(objects):
        tris = [[vertices[j] for j in f] for f in faces]
        ax.add_collection3d(Poly3DCollection(tris, facecolor=colours[i % 10], edgecolor="none", alpha=0.10))
    ax.plot(path[:, 0], path[:, 1], path[:, 2], color="black", linewidth=1.5, label="best path (reference point)")
    if path.shape[1] >= 7:
        for k in np.linspace(0, len(path) - 1, 12).astype(int):
            ax.add_collection3d(Poly3DCollection(box_faces(path[k, :3], rotation(path[k, 3:7]), half),
                                                 facecolor="tab:red", edgecolor="darkred", alpha=0.35, linewidth=0.3))
    ax.scatter(*path[0, :3], color="green", s=30, label="start")
    ax.scatter(*path[-1, :3], color="blue", s=30, label="goal")
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    ax.set_xlim(lo[0], hi[0]), ax.set_ylim(lo[1], hi[1]), ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)
    ax.view_init(elev=25, azim=-60)
    ax.set_title(sys.argv[7] if len(sys.argv) > 7 else "ACD components of the free space and the best path", fontsize=9)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[3])


if __name__ == "__main__":
    main()
