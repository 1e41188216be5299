#!/usr/bin/python3
"""Converts an OMPL.app problem file (.cfg, section [problem]) into a planner scenario (YAML),
printed on stdout. Usage: ompl_app_cfg_to_yaml.py PROBLEM.cfg > scenario.yaml

The planner reads .cfg files directly (`planner PROBLEM.cfg`); the YAML is for editing a
problem into a scenario of one's own. Mesh paths are kept as written (relative to the .cfg; put
the YAML beside it); the meshes are read in OMPL.app's frame (`frame: ompl_app`) and poses are
valid as OMPL.app judges them (`validity: triangles`). OMPL.app's [benchmark] time_limit and
run_count become a comment with the matching `planner --race` options. Without a volume the
YAML bounds the reference point by the environment's box alone; OMPL.app (and `planner
PROBLEM.cfg`) grow that box to hold the start and the goal."""
import configparser
import sys


def number(section, key):
    value = section.get(key)
    if value is None:
        sys.exit("%s: missing [problem] %s" % (sys.argv[1], key))
    return float(value)


def is_se2(section):
    """OMPL.app's rule: x, y and theta for both poses, and no z and no axis."""
    for w in ("start", "goal"):
        if any("%s.%s" % (w, k) not in section for k in ("x", "y", "theta")):
            return False
        if any("%s.%s" % (w, k) in section for k in ("z", "axis.x", "axis.y", "axis.z")):
            return False
    return True


def pose(section, which, se2):
    if se2:  # in the xy-plane at z = 0, turned about z
        position = [number(section, "%s.x" % which), number(section, "%s.y" % which), 0.0]
        axis = [0.0, 0.0, 1.0]
    else:
        position = [number(section, "%s.%s" % (which, c)) for c in "xyz"]
        axis = [number(section, "%s.axis.%s" % (which, c)) for c in "xyz"]
    theta = number(section, "%s.theta" % which)
    return "{position: [%s], axis: [%s], theta: %s}" % (
        ", ".join("%.10g" % v for v in position), ", ".join("%.10g" % v for v in axis), "%.10g" % theta)


def planner_entries(path):
    """The [planner] keys in file order, repeats kept (configparser keeps only the last)."""
    entries, inside = [], False
    for line in open(path):
        line = line.strip()
        if line.startswith("["):
            inside = line.lower() == "[planner]"
        elif inside and line and line[0] not in "#;":
            entries.append(line.split("=", 1)[0].strip())
    return entries


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: ompl_app_cfg_to_yaml.py PROBLEM.cfg > scenario.yaml")
    # OMPL.app's problem files repeat keys in [planner] (one line per planner instance) and its
    # own reader takes them: so does this one (strict=False; the entries are listed below).
    cfg = configparser.ConfigParser(strict=False, interpolation=None)
    try:
        if not cfg.read(sys.argv[1]):
            sys.exit("%s: cannot read" % sys.argv[1])
    except configparser.Error as e:
        sys.exit("%s: not an OMPL.app problem file: %s" % (sys.argv[1], str(e).splitlines()[0]))
    if "problem" not in cfg:
        sys.exit("%s: no [problem] section" % sys.argv[1])
    p = cfg["problem"]
    out = []
    if "name" in p:
        out.append("name: %s" % p["name"])
    se2 = is_se2(p)
    out.append("frame: ompl_app       # meshes as OMPL.app reads them (COLLADA's up axis and unit applied)")
    out.append("validity: triangles   # OMPL.app's rule: the robot touches none of the environment's triangles")
    out.append("world: %s" % p.get("world", ""))
    if se2:
        out.append("robot: {type: mesh, mesh: %s, center: true, planar: true}   # SE(2)" % p.get("robot", ""))
    else:
        out.append("robot: %s            # a mesh robot centred on its vertices' mean, as OMPL.app does" % p.get("robot", ""))
    out.append("start: " + pose(p, "start", se2))
    out.append("goal: " + pose(p, "goal", se2))
    if "volume.min.x" in p:
        # SE(2): z is not bounded (the robot stays at z = 0); any range holding 0 will do.
        lo = ", ".join("%.10g" % (number(p, "volume.min." + c) if c != "z" or not se2 else -1) for c in "xyz")
        hi = ", ".join("%.10g" % (number(p, "volume.max." + c) if c != "z" or not se2 else 1) for c in "xyz")
        out.append("volume: {min: [%s], max: [%s]}" % (lo, hi))
    else:
        out.append("# no volume: the reference point's bounds are the world's bounding box, as in OMPL.app")
    if "benchmark" in cfg:
        b = cfg["benchmark"]
        out.append("# OMPL.app benchmark: planner SCENARIO --race --time-limit %s --runs %s"
                   % (b.get("time_limit", "30"), b.get("run_count", "20")))
    planners = planner_entries(sys.argv[1])
    if planners:
        out.append("# OMPL.app [planner] entries: " + ", ".join(planners))
    print("\n".join(out))


if __name__ == "__main__":
    main()
