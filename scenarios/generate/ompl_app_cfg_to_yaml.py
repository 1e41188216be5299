#!/usr/bin/python3
"""Converts an OMPL.app problem file (.cfg, section [problem]) into a planner scenario (YAML),
printed on stdout. Usage: ompl_app_cfg_to_yaml.py PROBLEM.cfg > scenario.yaml

Mesh paths are kept as written (relative to the .cfg; put the YAML beside it). OMPL.app's
[benchmark] time_limit and run_count become a comment with the matching `planner --race`
options. SE(2) problems (start.theta without an axis) are not converted."""
import configparser
import sys


def number(section, key):
    value = section.get(key)
    if value is None:
        sys.exit("%s: missing [problem] %s" % (sys.argv[1], key))
    return float(value)


def pose(section, which):
    position = [number(section, "%s.%s" % (which, c)) for c in "xyz"]
    if "%s.axis.x" % which not in section:
        sys.exit("%s: %s has no axis (an SE(2) problem); not converted" % (sys.argv[1], which))
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
    out.append("world: %s" % p.get("world", ""))
    out.append("robot: %s            # a mesh robot centred on its vertices' mean, as OMPL.app does" % p.get("robot", ""))
    out.append("start: " + pose(p, "start"))
    out.append("goal: " + pose(p, "goal"))
    if "volume.min.x" in p:
        lo = ", ".join("%.10g" % number(p, "volume.min." + c) for c in "xyz")
        hi = ", ".join("%.10g" % number(p, "volume.max." + c) for c in "xyz")
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
