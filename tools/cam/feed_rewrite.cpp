#include "tools/cam/feed_rewrite.h"

#include "core/gcode/block.h"
#include "core/gcode/lex.h"
#include "tools/cam/feed_word.h"

namespace dexmill {
namespace cli {

FeedEdit FeedRewriter::line(const FeedLine& l) {
  FeedEdit e;
  e.feed_nm_per_min = l.programmed_nm_per_min;
  if (l.feeds && l.inverse_time) return inverse_time(l);
  if (!l.feeds) {
    if (l.sets_feed) {
      out_nm_per_min_ = l.feed_after_nm_per_min;
      out_unsure_ = false;
    }
    return e;
  }
  const int64_t programmed = l.programmed_nm_per_min;
  e.lowered = l.limit_nm_per_min < programmed;
  e.raised = l.retarget && l.limit_nm_per_min > programmed;
  const int decimals = l.retarget ? (l.inch ? 2 : 0) : (l.inch ? 4 : 3);
  FeedNumber n = feed_number(e.lowered || e.raised ? l.limit_nm_per_min : programmed, l.inch,
                             e.lowered || e.raised ? decimals : 6);
  if (e.raised && n.nm_per_min <= programmed) {  // no whole unit above it: as programmed
    e.raised = false;
    n = feed_number(programmed, l.inch, 6);
  }
  const int64_t want = e.lowered || e.raised ? l.limit_nm_per_min : programmed;
  if (l.has_f) {
    if (e.lowered || e.raised) {
      e.kind = FeedEdit::Kind::kChange;
      e.number = n.text;
      e.feed_nm_per_min = n.nm_per_min;
    }
  } else if (!(out_unsure_ && e.lowered) && out_nm_per_min_ <= want && out_nm_per_min_ >= n.nm_per_min) {
    // The feed carried over is the one wanted, as closely as an F word of
    // ours could say it: nothing to write.
    e.feed_nm_per_min = out_nm_per_min_;
  } else {
    e.kind = FeedEdit::Kind::kInsert;
    e.number = n.text;
    e.feed_nm_per_min = n.nm_per_min;
  }
  out_nm_per_min_ = e.feed_nm_per_min;
  out_unsure_ = l.block_delete && e.kind != FeedEdit::Kind::kNone;
  return e;
}

FeedEdit FeedRewriter::inverse_time(const FeedLine& l) const {
  FeedEdit e;
  e.feed_nm_per_min = l.programmed_nm_per_min;
  if (l.limit_nm_per_min == l.programmed_nm_per_min) return e;
  if (l.limit_nm_per_min > l.programmed_nm_per_min && !l.retarget) return e;
  // F' = F x limit / rate at 6 decimals, rounded down (F <= 1e6 and rates
  // <= 2.54e13 nm/min: the products fit 128 bits).
  constexpr int kFrac = 6;
  const Decimal f = l.inverse_f;
  const __int128 scaled = static_cast<__int128>(f.mant) * pow10_i64(kFrac - (f.frac < kFrac ? f.frac : kFrac)) *
                          l.limit_nm_per_min / l.programmed_nm_per_min / pow10_i64(f.frac > kFrac ? f.frac - kFrac : 0);
  if (scaled <= 0) return e;  // below 1e-6 per minute: left as it is (the caller warns)
  Decimal g{static_cast<int64_t>(scaled), kFrac};
  e.kind = FeedEdit::Kind::kChange;
  e.lowered = l.limit_nm_per_min < l.programmed_nm_per_min;
  e.raised = !e.lowered;
  e.number = decimal_text(g);
  // The rate it gives, for the time estimate: rate x F' / F.
  e.feed_nm_per_min = static_cast<int64_t>(static_cast<__int128>(l.programmed_nm_per_min) * g.mant * pow10_i64(f.frac) /
                                           (static_cast<__int128>(pow10_i64(kFrac)) * f.mant));
  return e;
}

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_lower(char c) { return c >= 'a' && c <= 'z'; }

}  // namespace

FeedSplice feed_splice(const char* text, std::size_t len, const FeedEdit& e) {
  FeedSplice s;
  GcodeBlock b;
  GcodeLineKind kind;
  GcodeDiag d{};
  if (gcode_read_block(text, len, 1, &b, &kind, &d) != GcodeError::kOk || kind != GcodeLineKind::kBlock) return s;
  std::size_t start = 0;  // the words begin after a block delete's '/'
  while (start < len && is_blank(text[start])) ++start;
  if (start < len && text[start] == '/') ++start;
  GcodeScanner sc(text, len);
  GcodeWord w;
  if (e.kind == FeedEdit::Kind::kChange) {
    // The number after the letter, white space inside it included (`F 1 200`).
    const std::size_t letter = static_cast<std::size_t>(b.col_of('F') - 1);
    sc.set_pos(letter);
    if (sc.next(&w, &d) != GcodeError::kOk || w.letter != 'F') return s;
    s.at = letter + 1;
    s.erase = sc.pos() - s.at;
    s.text = e.number;
    return s;
  }
  sc.set_pos(start);
  std::size_t words = 0, end = start, last_letter = start;
  bool spaced = false;
  while (sc.next(&w, &d) == GcodeError::kOk && w.letter) {
    const std::size_t at = static_cast<std::size_t>(w.col - 1);
    if (words++ > 0 && at > 0 && is_blank(text[at - 1])) spaced = true;
    last_letter = at;
    end = sc.pos();
  }
  s.at = end;
  s.text = std::string(spaced || words < 2 ? " " : "") + (is_lower(text[last_letter]) ? "f" : "F") + e.number;
  return s;
}

}  // namespace cli
}  // namespace dexmill
