#include "search_report.hpp"

#include <cstdio>
#include <fstream>

namespace planner {

void printN90Table(std::ostream& out, const std::vector<N90Search>& searches, int maxN) {
  char line[256];
  std::snprintf(line, sizeof line, "%-15s %9s %8s %14s %16s %12s\n", "sampler", "N at 90%", "success", "roadmap 90% [s]",
                "preprocessing [s]", "total [s]");
  out << "milestones to 90 % success (doubling, then bisecting to 10 %):\n" << line;
  for (const N90Search& s : searches) {
    if (s.n90 < 0) {
      std::snprintf(line, sizeof line, "%-15s %9s %8s %14s %16s %12s\n", s.sampler.c_str(),
                    ("> " + std::to_string(maxN)).c_str(), "-", "-", "-", "-");
    } else {
      std::snprintf(line, sizeof line, "%-15s %9d %6.1f %% %14.2f %16.2f %12.2f\n", s.sampler.c_str(), s.n90, 100 * s.rate,
                    s.trialSeconds90, s.preprocessingSeconds, s.seconds90());
    }
    out << line;
  }
}

bool writeN90Csv(const std::string& path, const std::vector<N90Search>& searches, int trials) {
  std::ofstream out(path);
  out << "sampler,n90,rate,trials,trial_seconds_90,preprocessing_seconds,seconds_90\n";
  for (const N90Search& s : searches) {
    out << s.sampler << ',';
    if (s.n90 >= 0)
      out << s.n90 << ',' << s.rate << ',' << trials << ',' << s.trialSeconds90 << ',' << s.preprocessingSeconds << ','
          << s.seconds90() << '\n';
    else
      out << ",," << trials << ",,,\n";
  }
  return static_cast<bool>(out);
}

void printRaceTable(std::ostream& out, const std::vector<PlannerTimes>& race, double timeLimit) {
  char line[256];
  std::snprintf(line, sizeof line, "%-20s %5s %7s %11s %13s\n", "planner", "runs", "solved", "median [s]", "90% by [s]");
  out << "planners, first solution within " << timeLimit << " s per run (PRM_acd: ACD preprocessing included):\n"
      << line;
  for (const PlannerTimes& t : race) {
    const double t90 = t.seconds90();
    char by[32];
    if (t90 >= 0)
      std::snprintf(by, sizeof by, "%13.2f", t90);
    else
      std::snprintf(by, sizeof by, "%13s", ("> " + std::to_string(static_cast<int>(timeLimit))).c_str());
    std::snprintf(line, sizeof line, "%-20s %5d %6.0f%% %11.2f %s\n", t.planner.c_str(), t.runs,
                  t.runs ? 100.0 * t.solved / t.runs : 0.0, t.medianSeconds(), by);
    out << line;
  }
}

bool writeRaceCsv(const std::string& path, const std::vector<PlannerTimes>& race) {
  std::ofstream out(path);
  out << "planner,runs,solved,median_seconds,seconds_90,added_seconds\n";
  for (const PlannerTimes& t : race) {
    out << t.planner << ',' << t.runs << ',' << t.solved << ',' << t.medianSeconds() << ',';
    if (t.seconds90() >= 0) out << t.seconds90();
    out << ',' << t.addedSeconds << '\n';
  }
  return static_cast<bool>(out);
}

bool writeRaceRunsCsv(const std::string& path, const std::vector<PlannerTimes>& race) {
  std::ofstream out(path);
  out << "planner,run,solved,seconds\n";
  for (const PlannerTimes& t : race)
    for (std::size_t i = 0; i < t.seconds.size(); ++i)
      out << t.planner << ',' << i << ',' << (t.solvedRuns[i] ? 1 : 0) << ',' << t.seconds[i] << '\n';
  return static_cast<bool>(out);
}

}  // namespace planner
