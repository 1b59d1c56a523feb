// The shipped scripts that read a sweep's folder (scripts/sweep_table.py, sweep_compare.py,
// keeping_rule.py, plot_sweep.py, false_lines.py and seed 001's sonar_map_*.py analyses) given bad
// input (s66 fifty-sixth pass): one line naming the file and the field (or the flag), exit 2, never
// a traceback, never a table over fewer runs than the sweep has. The folders are written by hand,
// as `plywood sweep` writes them.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::PythonImports;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

// Runs `python3 [python_flags] scripts/SCRIPT args` in `dir`, stdout and stderr into files there.
CliResult RunScript(const fs::path& dir, const std::string& script, const std::string& args,
                    const std::string& python_flags = "") {
  return testing::RunScript(dir, script, args, "/usr/bin/python3 " + python_flags);
}

void ExpectRefusal(const CliResult& r, const std::string& text) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_EQ(r.out.find("|---|"), std::string::npos) << r.out;  // no table, not even half of one
}

constexpr const char* kResultsHeader =
    "id,experiment,world,family,profile,seed,duration_s,occupancy.error,"
    "sensors.bumpers.contact_samples\n";

// A sweep of four runs (two durations x two seeds) in `folder`, finished: its manifest, sweep.json,
// summary.csv and results.csv with these rows (all four unless the caller passes fewer).
std::string FourRuns() {
  return "a,e.yaml,w.xml,,,1,3,0.01,0\n"
         "b,e.yaml,w.xml,,,2,3,0.02,0\n"
         "c,e.yaml,w.xml,,,1,4,0.03,0\n"
         "d,e.yaml,w.xml,,,2,4,0.05,1\n";
}

fs::path WriteSweep(const fs::path& folder, const std::string& rows = FourRuns(),
                    const std::string& summary_rows = "") {
  fs::create_directories(folder);
  WriteFile(folder / "cells.csv",
            "index,id,experiment,world,family,profile,seed,duration_s\n"
            "0,a,e.yaml,w.xml,,,1,3\n1,b,e.yaml,w.xml,,,2,3\n"
            "2,c,e.yaml,w.xml,,,1,4\n3,d,e.yaml,w.xml,,,2,4\n");
  WriteFile(folder / "sweep.json",
            "{\"name\": \"t\", \"axes\": [\"duration_s\"], \"metrics\": [\"occupancy.error\"], "
            "\"group_by\": [], \"cells\": 4}\n");
  WriteFile(folder / "results.csv", kResultsHeader + rows);
  WriteFile(
      folder / "summary.csv",
      "duration_s,metric,n,mean,std,ci95_low,ci95_high,min,max,p90\n" +
          (summary_rows.empty() ? "3,occupancy.error,2,0.015,0.007,0.001,0.03,0.01,0.02,0.02\n"
                                  "4,occupancy.error,2,0.04,0.014,0.01,0.07,0.03,0.05,0.05\n"
                                  "3,sensors.bumpers.contact_samples,2,0,0,0,0,0,0,0\n"
                                  "4,sensors.bumpers.contact_samples,2,0.5,0.7,-5,6,0,1,1\n"
                                : summary_rows));
  return folder;
}

// A run row with one field replaced: `column` 7 is occupancy.error, 8 the contacts.
std::string RowsWith(int row, int column, const std::string& text) {
  std::string rows = FourRuns();
  std::size_t start = 0;
  for (int i = 0; i < row; ++i) start = rows.find('\n', start) + 1;
  std::size_t field = start;
  for (int i = 0; i < column; ++i) field = rows.find(',', field) + 1;
  const std::size_t end = rows.find_first_of(",\n", field);
  return rows.replace(field, end - field, text);
}

std::string WithoutRow(int row) {
  std::string rows = FourRuns();
  std::size_t start = 0;
  for (int i = 0; i < row; ++i) start = rows.find('\n', start) + 1;
  return rows.erase(start, rows.find('\n', start) + 1 - start);
}

class SweepScriptsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!PythonImports()) GTEST_SKIP() << "python3 is not installed";
  }
};

// sweep_table.py printed a table of a sweep missing runs (summary.csv is over the finished ones),
// a column of '-' for a misspelt metric or an unknown flag, 'nan' as a mean, a row's n that was
// its first metric's beside a mean over fewer runs; a missing folder was a traceback.
TEST_F(SweepScriptsTest, SweepTableRefusesWhatIsNotAWholeSweepAndSaysEachCellsRuns) {
  const fs::path dir = MakeTempDir("SweepTableBadInput");
  WriteSweep(dir / "whole");
  CliResult r = RunScript(dir, "sweep_table.py", "whole");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| 3 | 2 | 0.015 (0.001-0.03) | 0 (0-0) |"), std::string::npos) << r.out;
  // A bound of -0 printed "(-0-0.5)".
  WriteSweep(dir / "minus_zero", FourRuns(),
             "3,occupancy.error,2,0.015,0.007,-0,0.5,0.01,0.02,0.02\n");
  const CliResult minus_zero = RunScript(dir, "sweep_table.py", "minus_zero");
  ASSERT_EQ(minus_zero.exit_code, 0) << minus_zero.err;
  EXPECT_NE(minus_zero.out.find("| 3 | 2 | 0.015 (0-0.5) |"), std::string::npos) << minus_zero.out;
  // A negative bound was printed "(-5-6)": a range from -5 to -6 at a glance.
  EXPECT_NE(r.out.find("| 4 | 2 | 0.04 (0.01-0.07) | 0.5 (-5 to 6) |"), std::string::npos) << r.out;

  ExpectRefusal(RunScript(dir, "sweep_table.py", "nowhere"),
                "sweep_table: nowhere: no such folder");
  ExpectRefusal(RunScript(dir, "sweep_table.py", "whole/results.csv"),
                "whole/results.csv: not a folder");
  ExpectRefusal(RunScript(dir, "sweep_table.py", "whole occupancy.eror"),
                "whole/summary.csv: metric 'occupancy.eror' has no row");
  ExpectRefusal(RunScript(dir, "sweep_table.py", "whole --metric"), "--metric: unknown flag");

  WriteSweep(dir / "killed", WithoutRow(3));
  ExpectRefusal(RunScript(dir, "sweep_table.py", "killed"),
                "killed/results.csv: holds 3 of the sweep's 4 runs (0 failed, in failures.csv; 1 "
                "unfinished)");
  WriteSweep(dir / "nan", FourRuns(), "3,occupancy.error,2,nan,,,,,,\n");
  ExpectRefusal(RunScript(dir, "sweep_table.py", "nan"),
                "nan/summary.csv: line 2: mean: expected a number, got 'nan'");
  WriteSweep(dir / "empty");
  WriteFile(dir / "empty" / "summary.csv", "");
  ExpectRefusal(RunScript(dir, "sweep_table.py", "empty"),
                "empty/summary.csv: empty file (no header line)");

  // The contacts null in one run of duration 4: its mean is over one run, the error's over two.
  WriteSweep(dir / "null", RowsWith(3, 8, ""),
             "4,occupancy.error,2,0.04,0.014,0.01,0.07,0.03,0.05,0.05\n"
             "4,sensors.bumpers.contact_samples,1,0,,,,0,0,0\n");
  r = RunScript(dir, "sweep_table.py", "null");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| 4 | 2 | 0.04 (0.01-0.07) | 0 (one run) [n 1] |"), std::string::npos)
      << r.out;
}

// sweep_compare.py took inf as a value, a null contact count as no contact, --threshold nan (no
// run above it), and compared sweeps missing runs; an empty results.csv or one without a column
// was a traceback, an unknown flag two lines of usage.
TEST_F(SweepScriptsTest, SweepCompareRefusesValuesAndSweepsItCannotCompare) {
  const fs::path dir = MakeTempDir("SweepCompareBadInput");
  WriteSweep(dir / "base");
  CliResult r = RunScript(dir, "sweep_compare.py", "base base");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| duration_s=4 | 2 | 0.0400 / 0.0500 / 0.0500 / 0 / 1 |"),
            std::string::npos)
      << r.out;

  WriteSweep(dir / "inf", RowsWith(1, 7, "inf"));
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base inf"),
                "inf/results.csv: line 3 (run b): occupancy.error: expected a number, got 'inf'");
  WriteSweep(dir / "nocontact", RowsWith(3, 8, ""));
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base nocontact"),
                "nocontact/results.csv: line 5 (run d): sensors.bumpers.contact_samples: expected "
                "a number, got ''");
  WriteSweep(dir / "killed", WithoutRow(2));
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "killed base"),
                "killed/results.csv: holds 3 of the sweep's 4 runs");
  WriteSweep(dir / "empty");
  WriteFile(dir / "empty" / "results.csv", "");
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base empty"),
                "empty/results.csv: empty file (no header line)");
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base base --metric occupancy.grid_error"),
                "base/results.csv: no column 'occupancy.grid_error'");
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base base --threshold nan"),
                "sweep_compare: --threshold: expected a finite number, got 'nan'");
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base base --treshold 0.1"),
                "sweep_compare: unrecognized arguments: --treshold");
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "base nowhere"), "nowhere: no such folder");
  // Experiment files of one name in two folders: runs a and c alike but for the folder.
  std::string twins = RowsWith(2, 6, "3");
  twins.replace(twins.find("e.yaml", twins.find("\nc,")), 6, "x/e.yaml");
  WriteSweep(dir / "twins", twins);
  ExpectRefusal(RunScript(dir, "sweep_compare.py", "twins base"),
                "sweep_compare: twins: runs c and another are alike in experiment file name, "
                "world, profile, seed and axes");
}

// keeping_rule.py read the bar and the rule on the runs that happened to finish ("kept", exit 0,
// of two sweeps each missing a run) or to pair, and its refusals exited 1, the code of "not kept",
// after the table's header.
TEST_F(SweepScriptsTest, KeepingRuleJudgesOnlyWholeSweepsOfTheSameRunsAndRefusesWithExit2) {
  const fs::path dir = MakeTempDir("KeepingRuleBadInput");
  WriteSweep(dir / "base");
  CliResult r = RunScript(dir, "keeping_rule.py", "base base");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("verdict: kept"), std::string::npos) << r.out;

  WriteSweep(dir / "killed_base", WithoutRow(3));
  WriteSweep(dir / "killed_new", WithoutRow(3));
  ExpectRefusal(RunScript(dir, "keeping_rule.py", "killed_base killed_new"),
                "killed_base/results.csv: holds 3 of the sweep's 4 runs");
  // Another sweep's runs: two of its four are not the base's.
  WriteSweep(dir / "other", RowsWith(2, 5, "7"));
  r = RunScript(dir, "keeping_rule.py", "base other");
  ExpectRefusal(r, "have no partner in the other sweep");
  // A pair given twice: its runs counted twice in every pooled figure.
  WriteSweep(dir / "new");
  ExpectRefusal(RunScript(dir, "keeping_rule.py", "base new base ./new"),
                "keeping_rule: base: given twice as a BASE sweep; give each pair once");
  // The same sweep given once as its folder, once as the results.csv in it (s66 review).
  ExpectRefusal(RunScript(dir, "keeping_rule.py", "base/results.csv new base new/results.csv"),
                "keeping_rule: base/results.csv: given twice as a BASE sweep; give each pair once");
  ExpectRefusal(RunScript(dir, "keeping_rule.py", "base nowhere"),
                "keeping_rule: nowhere: no such folder");
  ExpectRefusal(RunScript(dir, "keeping_rule.py", "base base --metrc x"),
                "keeping_rule: unrecognized arguments: --metrc");
}

// plot_sweep.py, run by hand: a missing folder, a value that is no number or a plots/ that is a
// file was a traceback, a NaN left out of the plot without a word, and without matplotlib a
// ModuleNotFoundError.
TEST_F(SweepScriptsTest, PlotSweepNamesTheFileAndFieldItCannotPlot) {
  if (!PythonImports("matplotlib")) GTEST_SKIP() << "python3-matplotlib is not installed";
  const fs::path dir = MakeTempDir("PlotSweepBadInput");
  ExpectRefusal(RunScript(dir, "plot_sweep.py", "nowhere"), "plot_sweep: nowhere: no such folder");
  WriteSweep(dir / "nan", RowsWith(1, 7, "nan"));
  ExpectRefusal(RunScript(dir, "plot_sweep.py", "nan"),
                "nan/results.csv: line 3 (run b): occupancy.error: expected a number, got 'nan'");
  WriteSweep(dir / "text", RowsWith(0, 7, "low"));
  ExpectRefusal(RunScript(dir, "plot_sweep.py", "text"),
                "text/results.csv: line 2 (run a): occupancy.error: expected a number, got 'low'");
  EXPECT_FALSE(fs::exists(dir / "text" / "plots" / "occupancy.error.png"));
  // No matplotlib on the path (python3 -S leaves out the packages Debian installs).
  WriteSweep(dir / "whole");
  ExpectRefusal(RunScript(dir, "plot_sweep.py", "whole", "-S"),
                "plot_sweep: no plots: python3-matplotlib is not installed");
  EXPECT_FALSE(fs::exists(dir / "whole" / "plots"));
  WriteSweep(dir / "file");
  WriteFile(dir / "file" / "plots", "a file\n");
  const CliResult r = RunScript(dir, "plot_sweep.py", "file");
  EXPECT_EQ(r.exit_code, 3) << r.err;  // CANNOT_WRITE: plywood sweep then exits 1
  EXPECT_EQ(r.err, "plywood sweep: file/plots: cannot write: a file, not a folder\n");
}

// A sweep grouped by world: results.csv holds the worlds' paths, summary.csv their stems, and
// plot_sweep.py matched the two by text, so no group got its mean and CI marker (s67).
TEST_F(SweepScriptsTest, PlotSweepGroupedByWorldDrawsEachGroupsMean) {
  if (!PythonImports("matplotlib")) GTEST_SKIP() << "python3-matplotlib is not installed";
  const fs::path dir = MakeTempDir("PlotSweepByWorld");
  const fs::path folder =
      WriteSweep(dir / "worlds",
                 "a,e.yaml,/w/room_a.xml,,,1,3,0.01,0\n"
                 "b,e.yaml,/w/room_a.xml,,,2,3,0.02,0\n"
                 "c,e.yaml,/w/room_b.xml,,,1,3,0.03,0\n"
                 "d,e.yaml,/w/room_b.xml,,,2,3,0.05,1\n",
                 "room_a,occupancy.error,2,0.015,0.007,0.001,0.03,0.01,0.02,0.02\n"
                 "room_b,occupancy.error,2,0.04,0.014,0.01,0.07,0.03,0.05,0.05\n");
  // WriteSweep's summary is grouped by duration_s; this one by world.
  std::string summary = Slurp(folder / "summary.csv");
  summary.replace(0, summary.find(','), "world");
  WriteFile(folder / "summary.csv", summary);
  const CliResult r = RunScript(dir, "plot_sweep.py", "worlds");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The mean's diamond is drawn in matplotlib's tab:red (#d62728); nothing else in the plot is.
  const std::string count_red =
      "/usr/bin/python3 -c \"import sys, matplotlib.image as m; a = m.imread(sys.argv[1]); "
      "print(int(((abs(a[..., 0] - 0.839) < 0.01) & (abs(a[..., 1] - 0.153) < 0.01) & "
      "(abs(a[..., 2] - 0.157) < 0.01)).sum()))\" '" +
      (folder / "plots" / "occupancy.error.png").string() + "' > '" + (dir / "red").string() + "'";
  ASSERT_EQ(std::system(count_red.c_str()), 0);
  EXPECT_GT(std::stoi(Slurp(dir / "red")), 40) << "no mean marker drawn";
}

// false_lines.py gave "0 lines, 0 false (pooled precision 1.000)" of an extractor no run has (a
// misspelt name, a misspelt --list), counted the runs of a sweep missing some, and a folder that is
// no sweep's was a traceback.
TEST_F(SweepScriptsTest, FalseLinesRefusesAnExtractorNoRunHasAndSweepsMissingRuns) {
  const fs::path dir = MakeTempDir("FalseLinesBadInput");
  const fs::path world = WriteFile(dir / "w.xml", "<mujoco><worldbody/></mujoco>\n");
  WriteSweep(dir / "lines");
  for (const char* run : {"a", "b", "c", "d"}) {
    WriteFile(dir / "lines" / "runs" / run / "config.yaml",
              "world: " + world.string() +
                  "\nrobot:\n  spawn:\n    x_m: 0\n    y_m: 0\n"
                  "    theta_deg: 0\n");
    WriteFile(dir / "lines" / "runs" / run / "lines.csv",
              "extractor,scan,points,x1_m,y1_m,x2_m,y2_m,truth_segment\n"
              "split_and_merge,0,10,1,0,1,1,3\nsplit_and_merge,0,10,2,0,2,1,\n");
  }
  CliResult r = RunScript(dir, "false_lines.py", "lines");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("split_and_merge: 8 lines, 4 false (pooled precision 0.500)"),
            std::string::npos)
      << r.out;
  ExpectRefusal(RunScript(dir, "false_lines.py", "lines ransac"),
                "lines: extractor 'ransac': no line of it in any run's lines.csv (extractors "
                "there: split_and_merge)");
  ExpectRefusal(RunScript(dir, "false_lines.py", "lines --lst"), "--lst: unknown flag");
  ExpectRefusal(RunScript(dir, "false_lines.py", "nowhere"),
                "false_lines: nowhere: no such folder");
  WriteFile(dir / "lines" / "results.csv", kResultsHeader + WithoutRow(0));
  ExpectRefusal(RunScript(dir, "false_lines.py", "lines"),
                "lines/results.csv: holds 3 of the sweep's 4 runs");
}

// A table piped into a reader that stops early (`sweep_table.py DIR | head -3`) ended in a
// BrokenPipeError traceback; each script now ends as `cat` would, without a word. Its stdout here
// is a pipe whose reader is already gone, so the first write fails every time.
TEST_F(SweepScriptsTest, TablesEndWithoutATracebackWhenTheirReaderHasGone) {
  const fs::path dir = MakeTempDir("SweepScriptsClosedPipe");
  WriteSweep(dir / "whole");
  for (const std::string args :
       {"sweep_table.py whole", "sweep_compare.py whole whole", "keeping_rule.py whole whole"}) {
    SCOPED_TRACE(args);
    const std::string command =
        "cd '" + dir.string() +
        "' && /usr/bin/python3 -c 'import os, subprocess, sys; r, w = os.pipe(); os.close(r); "
        "subprocess.call(sys.argv[1:], stdout=w)' /usr/bin/python3 '" +
        (SourceRoot() / "scripts").string() + "'/" + args + " 2>stderr";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(Slurp(dir / "stderr"), "");
  }
}

// Seed 001's analysis scripts (docs/sonar_map/history.md) over sweep folders: a missing folder was
// a traceback or, for the two that take LO HI, no run and exit 0; a sweep missing runs was read on
// the runs that finished; LO and HI that are no numbers a traceback, NaN bounds no run, exit 0.
TEST_F(SweepScriptsTest, SonarMapContactsRefusesSweepsMissingRunsAndMissingFolders) {
  const fs::path dir = MakeTempDir("SonarMapContactsBadInput");
  WriteSweep(dir / "killed", WithoutRow(1));
  ExpectRefusal(RunScript(dir, "sonar_map_contacts.py", "killed"),
                "sonar_map_contacts: killed/results.csv: holds 3 of the sweep's 4 runs");
  ExpectRefusal(RunScript(dir, "sonar_map_contacts.py", "nowhere"),
                "sonar_map_contacts: nowhere: no such folder");
  // A run folder without its metrics.json was skipped: "runs with a contact: 0" of runs unread.
  WriteSweep(dir / "unread");
  fs::create_directories(dir / "unread" / "runs" / "a");
  ExpectRefusal(RunScript(dir, "sonar_map_contacts.py", "unread"),
                "sonar_map_contacts: unread/runs/a/metrics.json: no such file (results.csv lists "
                "run a as finished)");
}

TEST_F(SweepScriptsTest, SonarMapErrorCausesRefusesSweepsMissingRunsAndATopThatIsNoNumber) {
  if (!PythonImports("numpy")) GTEST_SKIP() << "python3-numpy is not installed";
  const fs::path dir = MakeTempDir("SonarMapCausesBadInput");
  WriteSweep(dir / "killed", WithoutRow(1));
  ExpectRefusal(RunScript(dir, "sonar_map_error_causes.py", "killed"),
                "sonar_map_error_causes: killed/results.csv: holds 3 of the sweep's 4 runs");
  ExpectRefusal(RunScript(dir, "sonar_map_error_causes.py", "killed 3x"),
                "sonar_map_error_causes: TOP: expected a whole number >= 0, got '3x'");
}

TEST_F(SweepScriptsTest, SonarMapErrorMechanismsRefusesBoundsThatAreNoNumbersAndMissingFolders) {
  if (!PythonImports("numpy")) GTEST_SKIP() << "python3-numpy is not installed";
  const fs::path dir = MakeTempDir("SonarMapMechanismsBadInput");
  ExpectRefusal(RunScript(dir, "sonar_map_error_mechanisms.py", "0 1 nowhere"),
                "sonar_map_error_mechanisms: nowhere: no such folder");
  ExpectRefusal(RunScript(dir, "sonar_map_error_mechanisms.py", "nan 0.1 nowhere"),
                "sonar_map_error_mechanisms: LO: expected a finite number, got 'nan'");
}

TEST_F(SweepScriptsTest, SonarMapUnvisitedSpaceRefusesEmptyRangesAndSweepsMissingRuns) {
  if (!PythonImports("numpy, scipy"))
    GTEST_SKIP() << "python3-numpy or python3-scipy is not installed";
  const fs::path dir = MakeTempDir("SonarMapUnvisitedBadInput");
  WriteSweep(dir / "killed", WithoutRow(1));
  ExpectRefusal(RunScript(dir, "sonar_map_unvisited_space.py", "0 1 killed"),
                "sonar_map_unvisited_space: killed/results.csv: holds 3 of the sweep's 4 runs");
  ExpectRefusal(RunScript(dir, "sonar_map_unvisited_space.py", "0.1 0 killed"),
                "sonar_map_unvisited_space: LO 0.1 is not below HI 0");
}

TEST_F(SweepScriptsTest, SonarMapNarrowGapsRefusesMissingFilesAndSweepsMissingRuns) {
  if (!PythonImports("numpy, scipy"))
    GTEST_SKIP() << "python3-numpy or python3-scipy is not installed";
  const fs::path dir = MakeTempDir("SonarMapNarrowGapsBadInput");
  WriteSweep(dir / "killed", WithoutRow(1));
  ExpectRefusal(RunScript(dir, "sonar_map_narrow_gaps.py", "nowhere/results.csv"),
                "sonar_map_narrow_gaps.py: nowhere/results.csv: no such file");
  ExpectRefusal(RunScript(dir, "sonar_map_narrow_gaps.py", "killed/results.csv"),
                "killed/results.csv: holds 3 of the sweep's 4 runs");
  // A world results.csv names that is not there, and runs in their experiment's own world (no
  // world in results.csv: the shipped sonar_map_layouts.yaml) were tracebacks (s66 review).
  WriteSweep(dir / "whole");
  ExpectRefusal(RunScript(dir, "sonar_map_narrow_gaps.py", "whole/results.csv"),
                "whole/w.xml: no such file (a world the sweep's results.csv names)");
  std::string own = FourRuns();
  for (std::size_t at = own.find("w.xml"); at != std::string::npos; at = own.find("w.xml"))
    own.erase(at, 5);
  WriteSweep(dir / "own", own);
  ExpectRefusal(RunScript(dir, "sonar_map_narrow_gaps.py", "own/results.csv"),
                "own/results.csv: line 2: world: empty (the run's world is its experiment's own)");
}

}  // namespace
}  // namespace plywood
