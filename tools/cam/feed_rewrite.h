// `dexmill optimize`'s decision, line by line: which F word each line of
// the output needs so that its feed moves run at the lower of the
// programmed feed and the line's limit (the lowest max feed of the
// materials they removed), and where that F word goes in the line's text.
//
// The rule (RS274/NGC: F is modal, and a block's F applies to the block's
// own moves):
// - a line whose feed moves must run slower gets F at the lowered value
//   (its own F word changed, or one added);
// - a line that must run at the programmed feed while the output's modal
//   feed is another (a lowered line came before) gets the programmed F
//   back;
// - every other line, and every other byte, stays as written.
// With a target (FeedLine::retarget) the wanted feed may be above the
// programmed one too: the same rule with "runs faster" beside "slower".
// Inverse-time moves (G93: F is 1/minutes, every move's own, its rate the
// move's length times F) over their limit (or off their target) get F scaled by limit / rate,
// rounded down at 6 decimals: the rate read back is at most the limit
// (round(F' x length) <= limit x (F x length) / rate < limit + 1/2).
//
// Block delete: a `/` line runs, as in the simulation (the switch off, as
// LinuxCNC starts), and the F words after it are written for that case.
// One precaution for an operator who skips it: a lowered feed is never
// carried from an F word this rewrite put on a `/` line; the next line
// that must run lowered writes its own F.
#ifndef DEXMILL_TOOLS_CAM_FEED_REWRITE_H
#define DEXMILL_TOOLS_CAM_FEED_REWRITE_H

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/math/decimal.h"

namespace dexmill {
namespace cli {

// What one line of the program does with the feed, as read and cut.
struct FeedLine {
  bool feeds = false;                // the line makes feed moves (G1, arcs, a cycle's feeds)
  bool inverse_time = false;         // ... in G93 (one move)
  Decimal inverse_f{0, 0};           // G93: the line's F as written
  int64_t programmed_nm_per_min = 0; // their feed as programmed (G94: one per line; G93: the move's rate)
  int64_t limit_nm_per_min = 0;      // the lowest max feed of what they removed (kNoFeedLimit: none)
  // `--target`: limit_nm_per_min is the feed wanted, above or below the
  // programmed one (core/engage/engage_target.h), written with whole
  // mm/min (hundredths of inch/min), rounded down.
  bool retarget = false;
  bool sets_feed = false;            // an F word, G93 or G94: the modal feed after it is the program's
  int64_t feed_after_nm_per_min = 0; // the modal feed after the line, as programmed
  bool has_f = false;                // the line has an F word
  bool block_delete = false;         // the line begins with '/'
  bool inch = false;                 // F on this line is in inch/min (G20 in force)
};

struct FeedEdit {
  enum class Kind : uint8_t { kNone, kChange, kInsert } kind = Kind::kNone;
  std::string number;                // the F word's number text (kChange, kInsert)
  int64_t feed_nm_per_min = 0;       // the line's feed moves in the output (feeds)
  bool lowered = false;              // below the programmed feed
  bool raised = false;               // above it (--target)
};

class FeedRewriter {
 public:
  // The next line's edit (lines in program order).
  FeedEdit line(const FeedLine& l);
  // Lines put before the next one (a split move's pieces) left the
  // output's modal feed at nm_per_min.
  void modal_changed(int64_t nm_per_min) {
    out_nm_per_min_ = nm_per_min;
    out_unsure_ = false;
  }

 private:
  FeedEdit inverse_time(const FeedLine& l) const;

  int64_t out_nm_per_min_ = 0;  // the output's modal feed after the lines so far
  bool out_unsure_ = false;     // ... set by an F word this rewrite put on a `/` line
};

// Where an edit goes in a line's text (without its line end): erase
// `erase` bytes at `at`, insert `text`.
struct FeedSplice {
  std::size_t at = 0, erase = 0;
  std::string text;
};

// The splice of edit e (kChange or kInsert) into the line text[0, len),
// which must read (gcode_read_block). kChange replaces the F word's number
// (the letter's case kept); kInsert puts ` F...` after the line's last word,
// before any comment, with no space when the line's words are written
// together (G1X10Y5), the letter in the case of the word before it.
FeedSplice feed_splice(const char* text, std::size_t len, const FeedEdit& e);

}  // namespace cli
}  // namespace dexmill

#endif
