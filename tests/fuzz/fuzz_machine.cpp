// libFuzzer target: the machine description reader (platform/format/machine_file.h):
// a LinuxCNC INI file or a grbl settings dump, told apart by content, and
// the parameter-file reader on the same bytes. A text that reads gives a
// machine of the kind it says, every limited axis with its minimum at most
// its maximum and within the readers' ranges, and reads again to the same;
// one that does not gives one error line naming the file and leaves the
// output as it was.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/math/fixed.h"
#include "platform/format/machine_file.h"
#include "tests/fuzz/fuzz_entry.h"

namespace fuzz_machine {

using namespace dexmill;

bool same(const MachineSpec& a, const MachineSpec& b) {
  bool eq = a.kind == b.kind && a.inch == b.inch && a.have_offsets == b.have_offsets && a.tlo_nm == b.tlo_nm &&
            a.coord_system == b.coord_system && a.max_feed_override_ppm == b.max_feed_override_ppm && a.g92 == b.g92;
  for (int k = 0; k < 3; ++k)
    eq = eq && a.axis[k].limited == b.axis[k].limited && a.axis[k].min_nm == b.axis[k].min_nm &&
         a.axis[k].max_nm == b.axis[k].max_nm && a.axis[k].max_velocity_nm_per_min == b.axis[k].max_velocity_nm_per_min &&
         a.axis[k].max_accel_nm_per_s2 == b.axis[k].max_accel_nm_per_s2;
  for (int k = 0; k < kMachineCoordSystems; ++k) eq = eq && a.work_offset[k] == b.work_offset[k];
  return eq;
}

int fuzz_machine(const uint8_t* data, size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  MachineFile f, again;
  f.tool_table = "sentinel";
  std::string err;
  if (!machine_file_parse("fuzz.ini", text, size, "/cfg", &f, &err)) {
    FUZZ_REQUIRE(err.compare(0, 9, "fuzz.ini:") == 0);
    FUZZ_REQUIRE(err.find('\n') == std::string::npos);
    FUZZ_REQUIRE(f.tool_table == "sentinel" && f.spec.kind == MachineKind::kNone);
  } else {
    FUZZ_REQUIRE(err.empty());
    FUZZ_REQUIRE(f.spec.kind == MachineKind::kLinuxcnc || f.spec.kind == MachineKind::kGrbl);
    for (const MachineAxis& a : f.spec.axis) {
      if (a.limited) FUZZ_REQUIRE(a.min_nm <= a.max_nm);
      FUZZ_REQUIRE(a.min_nm >= -10000 * kNmPerMm && a.max_nm <= 10000 * kNmPerMm);
      FUZZ_REQUIRE(a.max_velocity_nm_per_min >= 0 && a.max_accel_nm_per_s2 >= 0);
    }
    std::string err2;
    FUZZ_REQUIRE(machine_file_parse("fuzz.ini", text, size, "/cfg", &again, &err2));
    FUZZ_REQUIRE(same(f.spec, again.spec) && f.tool_table == again.tool_table &&
                 f.subroutine_path == again.subroutine_path && f.parameter_file == again.parameter_file);
  }
  // The same bytes as a parameter file.
  MachineSpec spec, before;
  spec.tlo_nm = before.tlo_nm = 12345;
  std::string verr;
  if (!machine_var_parse("fuzz.var", text, size, size % 2 == 1, &spec, &verr)) {
    FUZZ_REQUIRE(verr.compare(0, 9, "fuzz.var:") == 0);
    FUZZ_REQUIRE(same(spec, before));
  } else {
    FUZZ_REQUIRE(spec.have_offsets && spec.coord_system < kMachineCoordSystems);
  }
  return 0;
}

}  // namespace fuzz_machine

DEXMILL_FUZZ_ENTRY(fuzz_machine::fuzz_machine)
