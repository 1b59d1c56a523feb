#include "eval/sweep/slurm_job.h"

#include <cstdio>
#include <stdexcept>

#include "sim/runner/file_writer.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// Single quotes for the shell, so paths with spaces survive.
std::string Quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  return quoted + "'";
}

// An #SBATCH line's value as sbatch reads it back: unquoted, a space ends it and '#' starts a
// comment, and in a file name '%' starts a pattern (%a, %j). `--out 'runs/cluster #1'` sent every
// task's log to the file runs/cluster, outside the sweep folder. In double quotes a backslash
// escapes the next character; "%%" is a '%'. `pattern` is appended as it is (task-%a.log).
std::string SbatchFileName(const std::string& folder, const std::string& pattern) {
  std::string quoted = "\"";
  for (char c : folder) {
    if (c == '"') quoted += '\\';
    quoted += c;
    if (c == '%') quoted += '%';
  }
  return quoted + "/" + pattern + "\"";
}

}  // namespace

void RequireSlurmSafeFolder(const fs::path& out_dir) {
  if (fs::absolute(out_dir).string().find_first_of("\n\r") != std::string::npos) {
    throw std::invalid_argument(
        "--out: a Slurm job cannot write to a folder whose path holds a line break");
  }
  // sbatch takes a backslash in a file name for "expand no %a", and the task logs would share
  // one file.
  if (fs::absolute(out_dir).string().find('\\') != std::string::npos) {
    throw std::invalid_argument(
        "--out: a Slurm job cannot write to a folder whose path holds a backslash (sbatch reads it "
        "as 'expand no %a' in the task logs' name)");
  }
}

SlurmJob WriteSlurmJob(const fs::path& plywood, const fs::path& sweep_file, const fs::path& out_dir,
                       int cells, const SlurmJobOptions& options) {
  SlurmJob job;
  job.tasks = options.tasks > 0 ? options.tasks : std::min(cells, 1000);
  job.tasks = std::max(1, std::min(job.tasks, cells));
  RequireSlurmSafeFolder(out_dir);
  const fs::path dir = fs::absolute(out_dir) / "slurm";
  fs::create_directories(dir);
  job.script = dir / "sweep.sbatch";
  std::string array = "0-" + std::to_string(job.tasks - 1);
  if (options.max_parallel > 0) array += "%" + std::to_string(options.max_parallel);
  std::string text = "#!/bin/bash\n";
  text += "#SBATCH --job-name=plywood-sweep\n";
  text += "#SBATCH --array=" + array + "\n";
  text += "#SBATCH --cpus-per-task=1\n";
  text += "#SBATCH --output=" + SbatchFileName(dir.string(), "task-%a.log") + "\n";
  if (!options.partition.empty()) text += "#SBATCH --partition=" + options.partition + "\n";
  text += "# Task I of " + std::to_string(job.tasks) +
          " runs the cells whose index % N == I; re-submitting after scancel resumes.\n";
  text += "set -euo pipefail\n";
  text += "exec " + Quote(fs::absolute(plywood).string()) + " sweep " +
          Quote(fs::absolute(sweep_file).string()) + " --out " +
          Quote(fs::absolute(out_dir).string()) + " --shard \"${SLURM_ARRAY_TASK_ID}/" +
          std::to_string(job.tasks) + "\" --jobs 1 --no-collect --quiet\n";
  sim::FileWriter out(job.script);
  out.out() << text;
  out.Close();  // checked after closing: a full disk may show only when the buffer is written
  fs::permissions(job.script, fs::perms::owner_exec, fs::perm_options::add);
  return job;
}

std::string SubmitSlurmJob(const SlurmJob& job) {
  const std::string command = "sbatch --parsable " + Quote(job.script.string()) + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run sbatch");
  std::string output;
  char buffer[256];
  while (fgets(buffer, sizeof(buffer), pipe)) output += buffer;
  const int status = pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  if (status != 0) throw std::runtime_error("sbatch failed: " + output);
  // --parsable prints "JOBID" or "JOBID;CLUSTER".
  return output.substr(0, output.find(';'));
}

}  // namespace plywood::eval
