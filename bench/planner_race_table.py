#!/usr/bin/python3
"""The race's Markdown table from OUT/<problem>/race.csv (bench/planner_race.sh): per problem,
each planner's solved runs, median time (unsolved runs at the limit) and the time by which 90 %
were solved, and whether PRM with the acd sampler met the bar (as many solved as the best of
the others, in at most half its median time). Usage: planner_race_table.py OUT PROBLEM..."""
import csv
import os
import sys


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    out, problems = sys.argv[1], sys.argv[2:]
    print("| problem | planner | solved | median [s] | 90 % by [s] |")
    print("|---|---|---:|---:|---:|")
    verdicts = []
    for p in problems:
        rs = rows(os.path.join(out, p, "race.csv"))
        for r in rs:
            s90 = "%.2f" % float(r["seconds_90"]) if r["seconds_90"] else "—"
            print("| %s | %s | %s/%s | %.2f | %s |" % (p, r["planner"], r["solved"], r["runs"], float(r["median_seconds"]), s90))
        acd = [r for r in rs if r["planner"] == "PRM_acd"]
        others = [r for r in rs if r["planner"] != "PRM_acd"]
        if acd and others:
            a = acd[0]
            best = max(others, key=lambda r: (int(r["solved"]), -float(r["median_seconds"])))
            ok = int(a["solved"]) >= int(best["solved"]) and float(a["median_seconds"]) <= 0.5 * float(best["median_seconds"])
            verdicts.append("%s: PRM_acd %s/%s in %.2f s median, best other %s %s/%s in %.2f s: %s" % (
                p, a["solved"], a["runs"], float(a["median_seconds"]), best["planner"], best["solved"], best["runs"],
                float(best["median_seconds"]), "met" if ok else "NOT met"))
    print()
    for v in verdicts:
        print("- " + v)


if __name__ == "__main__":
    main()
