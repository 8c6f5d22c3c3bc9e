// The input guard for the subcommands; see guard_inputs.h.
#include "tools/run/guard_inputs.h"

#include "core/material/material_preset.h"
#include "tools/cli/cli.h"

namespace dexmill {
namespace cli {

int guard_status(const FileGuard& guard, FileGuard::Verdict v) {
  if (v == FileGuard::Verdict::kOk) return kExitOk;
  return fail(v == FileGuard::Verdict::kClash ? kExitUsage : kExitIo, "%s", guard.message().c_str());
}

int guard_read_inputs(const std::string& program, const ReadOptions& read, FileGuard* guard) {
  if (const int code = guard_status(*guard, guard->register_input(program, FileGuard::kProgram))) return code;
  return guard_status(*guard, guard->register_input(read.tools_file, "--tools"));
}

int guard_job_inputs(const JobOptions& job, const std::string& program, FileGuard* guard) {
  if (const int code = guard_read_inputs(program, job.read, guard)) return code;
  // A preset's name is no file (tools/run/run_material.cpp tries it first), nor
  // a built-in part's (tools/run/run_assess.cpp).
  if (material_preset_index(job.material.c_str()) < 0)
    if (const int code = guard_status(*guard, guard->register_input(job.material, "--material"))) return code;
  if (!job.builtin && !job.demo_design)
    if (const int code = guard_status(*guard, guard->register_input(job.design, "--design"))) return code;
  if (const int code = guard_status(*guard, guard->register_input(job.machine_file, "--machine"))) return code;
  if (const int code = guard_status(*guard, guard->register_input(job.stock_file, "--stock"))) return code;
  return guard_status(*guard, guard->register_input(job.stock_stl, "--stock"));
}

}  // namespace cli
}  // namespace dexmill
