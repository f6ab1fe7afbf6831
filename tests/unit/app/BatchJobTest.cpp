// What a batch job needs from apps/contessa (docs/user-guide.md, "Batch runs"): the job's end time as
// Slurm prints it, the command-line options --restart auto and --job-end-margin, and the summary of a
// continued run with both scopes (this job, the whole run).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "ProcessEnvironment.hpp"
#include "RunReport.hpp"
#include "common/Error.hpp"

namespace {

using namespace contessa::app;

CommandLine parse(std::vector<std::string> words) {
  words.insert(words.begin(), "contessa");
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  return parseCommandLine(static_cast<int>(argv.size()), argv.data());
}

TEST(BatchJob, EndTimeIsSecondsSinceTheEpoch) {
  const auto t = parseEpochSeconds("1795738263");
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(std::chrono::duration_cast<std::chrono::seconds>(t->time_since_epoch()).count(), 1795738263LL);
  // What squeue prints for a job without an end time, or nothing at all: no limit known.
  for (const char* text : {"", "Unknown", "NONE", "N/A", "2026-11-27T01:00:00", "-5", "12 34", "1e9"})
    EXPECT_FALSE(parseEpochSeconds(text).has_value()) << text;
}

TEST(BatchJob, RestartAutoAndJobEndMargin) {
  const CommandLine cl = parse({"deck.xml", "--restart", "auto", "--job-end-margin", "40"});
  EXPECT_EQ(cl.restart, "auto");
  EXPECT_DOUBLE_EQ(cl.jobEndMargin, 40);
  EXPECT_DOUBLE_EQ(parse({"deck.xml", "--job-end-margin=2.5"}).jobEndMargin, 2.5);
  EXPECT_DOUBLE_EQ(parse({"deck.xml"}).jobEndMargin, 10);
  for (const char* bad : {"-1", "ten", "inf", "nan", "5s", ""}) {
    try {
      parse({"deck.xml", "--job-end-margin", bad});
      ADD_FAILURE() << "accepted --job-end-margin " << bad;
    } catch (const contessa::InputError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("--job-end-margin: expected seconds >= 0, got '") + bad + "'");
    }
  }
  EXPECT_THROW(parse({"deck.xml", "--job-end-margin"}), contessa::InputError);
}

// A restart file's history rows: steps 0..3 and the run's wall time.
TEST(BatchJob, EarlierJobsFromTheRestartHistory) {
  const std::vector<std::string> columns{"step", "lambda", "newton_iterations", "wall_s"};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<double>> rows{{0, 0, 2, 0.5}, {1, 0.1, 4, 1.5}, {2, 0.2, 5, 2.5}, {3, 0.3, nan, 3.25}};
  const EarlierJobs e = earlierJobs(columns, rows);
  EXPECT_EQ(e.step, 3);
  EXPECT_DOUBLE_EQ(e.wallSeconds, 3.25);
}

TEST(BatchJob, ContinuedRunSummaryStatesBothScopes) {
  RunReport r;
  r.summary.finished = true;
  r.summary.increments = 10;  // the driver counts the whole run's increments
  r.summary.failedAttempts = 2;
  r.summary.newtonIterations = 30;     // this job's
  r.summary.runNewtonIterations = 30;  // a new run: the same
  r.wallSeconds = 20;
  r.peakBytesPerRank = {1 << 20};
  const std::string fresh = summaryLine(r);
  EXPECT_EQ(fresh.rfind("contessa: summary: 10 increments, 2 failed attempts, 30 Newton iterations, 0 linear "
                        "iterations, wall 20 s,", 0), 0u) << fresh;
  r.earlier = EarlierJobs{4, 12.5};
  r.summary.runNewtonIterations = 46;  // the earlier jobs' 16 (failed attempts included) and this job's 30
  const std::string line = summaryLine(r);
  EXPECT_NE(line.find("this job 6 increments (steps 5 to 10), 30 Newton iterations, wall 20 s; whole run 10 "
                      "increments, 2 failed attempts, 46 Newton iterations, wall 32.5 s;"), std::string::npos) << line;
  const std::string json = summaryJson(r);
  EXPECT_NE(json.find("\"this_job\": {\"first_step\": 5, \"increments\": 6, \"newton_iterations\": 30, \"wall_seconds\": 20}"),
            std::string::npos) << json;
  EXPECT_NE(json.find("\"whole_run\": {\"continued\": true, \"increments\": 10, \"newton_iterations\": 46, "
                      "\"wall_seconds\": 32.5}"), std::string::npos) << json;
}

}  // namespace
