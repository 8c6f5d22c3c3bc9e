// The embedding API: program text in, steps with a budget (dexmill.h).
#include <string.h>

#include "display/api/handles.h"

using namespace dexmill;
using namespace dexmill::api;

static_assert(DM_READY == static_cast<int>(SimState::kReady) && DM_NEED_INPUT == static_cast<int>(SimState::kNeedInput) &&
                  DM_DONE == static_cast<int>(SimState::kDone) && DM_STOPPED == static_cast<int>(SimState::kStopped) &&
                  DM_IO_ERROR == static_cast<int>(SimState::kIoError),
              "the DM_ states are the engine's numbers");
static_assert(DM_LINE_MAX == kGcodeMaxLine, "a line dm_feed_line takes is one the reader takes");

namespace {

// The caller's yield, asked as the engine asks (SimBudget::yield).
bool ask_caller(void* ctx) {
  const dm_budget* b = static_cast<const dm_budget*>(ctx);
  return b->yield(b->yield_ctx) != 0;
}

}  // namespace

extern "C" {

dm_status dm_feed(dm_sim* sim, const char* text, size_t n) {
  if (!live(sim) || (!text && n)) return DM_E_ARGUMENT;
  if (sim->ended) return DM_E_STATE;
  if (!sim->sim->input_taken()) return DM_E_BUSY;
  sim->sim->feed(text, n);
  return DM_OK;
}

int32_t dm_input_taken(const dm_sim* sim) { return live(sim) && sim->sim->input_taken() ? 1 : 0; }

dm_status dm_feed_line(dm_sim* sim, const char* line, size_t n) {
  if (!live(sim) || (!line && n)) return DM_E_ARGUMENT;
  if (n > DM_LINE_MAX) return DM_E_LINE;
  if (sim->ended) return DM_E_STATE;
  if (!sim->sim->input_taken()) return DM_E_BUSY;
  if (n) memcpy(sim->line, line, n);
  sim->line[n] = '\n';
  sim->sim->feed(sim->line, n + 1);
  return DM_OK;
}

dm_status dm_end_input(dm_sim* sim) {
  if (!live(sim)) return DM_E_ARGUMENT;
  sim->ended = true;
  sim->sim->close_input();
  return DM_OK;
}

dm_status dm_step(dm_sim* sim, const dm_budget* budget, int32_t* state) {
  if (!live(sim) || !state) return DM_E_ARGUMENT;
  SimBudget b;
  dm_budget caller{};
  if (budget) {
    caller = *budget;
    if (caller.moves) b.moves = caller.moves;
    if (caller.dexel_updates) b.dexel_updates = caller.dexel_updates;
    if (caller.lines) b.lines = caller.lines;
    if (caller.yield) {
      b.yield = ask_caller;
      b.yield_ctx = &caller;
    }
  }
  *state = static_cast<int32_t>(sim->sim->step(b));
  return DM_OK;
}

dm_status dm_stop(dm_sim* sim) {
  if (!live(sim)) return DM_E_ARGUMENT;
  sim->sim->stop();
  return DM_OK;
}

}  // extern "C"
