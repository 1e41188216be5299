// Output of the two searches beside the fixed-N table: milestones to 90 % success per sampler
// (n90.csv, and every point in n90_points.csv) and OMPL's planners against the clock (race.csv,
// plus OMPL's own benchmark log).
#pragma once

#include "n90_search.hpp"
#include "ompl_planners.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace planner {

void printN90Table(std::ostream& out, const std::vector<N90Search>& searches, int maxN);

/// sampler,n90,rate,trials,trial_seconds_90,preprocessing_seconds,seconds_90 (n90 empty when not reached).
bool writeN90Csv(const std::string& path, const std::vector<N90Search>& searches, int trials);

void printRaceTable(std::ostream& out, const std::vector<PlannerTimes>& race, double timeLimit);

/// planner,runs,solved,median_seconds,seconds_90,added_seconds (seconds_90 empty when fewer than 90 % solved).
bool writeRaceCsv(const std::string& path, const std::vector<PlannerTimes>& race);

/// Every run of the race (planner, run, solved, seconds): the data of apps/planner/plot_race.py.
bool writeRaceRunsCsv(const std::string& path, const std::vector<PlannerTimes>& race);

}  // namespace planner
