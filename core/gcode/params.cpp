// Parameters; see params.h.
#include "core/gcode/params.h"

#include <string.h>

namespace dexmill {
namespace {

// The stored entry of a folded name visible at the current level (a global,
// or a local of this level), or -1.
int32_t find(const ParamStore& p, const char* folded) {
  const bool global = folded[0] == '_';
  for (int32_t k = 0; k < p.nnamed; ++k)
    if (!strcmp(p.named[k].name, folded) && (global || p.named[k].level == p.level)) return k;
  return -1;
}

}  // namespace

void params_clear(ParamStore* p) {
  for (int32_t k = 0; k <= kParamsNumbered; ++k) p->numbered_e9[k] = 0;
  p->nnamed = 0;
  p->level = 0;
}

void params_drop_level(ParamStore* p, uint8_t level) {
  int32_t kept = 0;
  for (int32_t k = 0; k < p->nnamed; ++k) {
    const bool local = p->named[k].name[0] != '_' && p->named[k].level == level;
    if (!local) p->named[kept++] = p->named[k];
  }
  p->nnamed = kept;
}

bool param_fold_name(const char* name, size_t len, char* out) {
  size_t k = 0;
  for (size_t i = 0; i < len; ++i) {
    char c = name[i];
    if (c == ' ' || c == '\t') continue;
    if (k >= static_cast<size_t>(kParamNameMax)) return false;
    out[k++] = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  out[k] = 0;
  return k > 0;
}

GcodeError param_get(const ParamStore& p, int64_t n, GValue* out) {
  if (n < 1 || n > kParamsNumbered) return GcodeError::kParamNumberRange;
  if (p.system.read && p.system.read(p.system.ctx, static_cast<int32_t>(n), nullptr, out)) return GcodeError::kOk;
  out->e9 = p.numbered_e9[n];
  return GcodeError::kOk;
}

GcodeError param_set(ParamStore* p, int64_t n, GValue v) {
  if (n < 1 || n > kParamsNumbered) return GcodeError::kParamNumberRange;
  GValue sys;
  if (p->system.read && p->system.read(p->system.ctx, static_cast<int32_t>(n), nullptr, &sys)) return GcodeError::kParamReadOnly;
  p->numbered_e9[n] = v.e9;
  return GcodeError::kOk;
}

GcodeError param_get_named(const ParamStore& p, const char* name, size_t len, GValue* out, bool* exists) {
  char folded[kParamNameMax + 1];
  if (!param_fold_name(name, len, folded)) return GcodeError::kParamNameTooLong;
  if (folded[0] == '_' && p.system.read && p.system.read(p.system.ctx, 0, folded, out)) {
    if (exists) *exists = true;
    return GcodeError::kOk;
  }
  const int32_t k = find(p, folded);
  if (exists) *exists = k >= 0;
  if (k < 0) {
    out->e9 = 0;
    return exists ? GcodeError::kOk : GcodeError::kParamUnknownName;
  }
  out->e9 = p.named[k].e9;
  return GcodeError::kOk;
}

GcodeError param_set_named(ParamStore* p, const char* name, size_t len, GValue v) {
  char folded[kParamNameMax + 1];
  if (!param_fold_name(name, len, folded)) return GcodeError::kParamNameTooLong;
  GValue sys;
  if (folded[0] == '_' && p->system.read && p->system.read(p->system.ctx, 0, folded, &sys)) return GcodeError::kParamReadOnly;
  int32_t k = find(*p, folded);
  if (k < 0) {
    if (p->nnamed >= kParamsNamedMax) return GcodeError::kTooManyNamedParams;
    k = p->nnamed++;
    ParamStore::Named& e = p->named[k];
    for (size_t i = 0; i <= sizeof e.name - 1; ++i) {
      e.name[i] = folded[i];
      if (!folded[i]) break;
    }
    e.level = folded[0] == '_' ? 0 : p->level;
  }
  p->named[k].e9 = v.e9;
  return GcodeError::kOk;
}

}  // namespace dexmill
