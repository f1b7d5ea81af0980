// SPDX-License-Identifier: MIT
#include "world/look_ahead.hpp"

#include "base/prefetch.hpp"

namespace sparsedyn {

void LookAhead::FetchElement(std::uint32_t e) const {
  Prefetch(&paths_.Records()[e]);  // one line: the path start and the grid links
  sparse_.queue().Prefetch(e);     // the queue entry with its prediction, both its lines
}

std::uint32_t LookAhead::CellAhead(std::uint32_t e) const {
  // The cell e's next event will scan around: the one it crosses into, or its own.
  const Prediction& event = sparse_.PredictionOf(e);
  const Grid& grid = *sparse_.grid();
  const std::uint32_t cell = grid.CellOf(e);
  if (event.kind != EventKind::kCellCrossing) return cell;
  return grid.CellAcross(cell, event.CrossingAxis(), event.CrossingDirection());
}

void LookAhead::Fetch() const {
  // A pipeline over the coming events, so that each step's cache misses have events' time to
  // arrive before the step that needs them: the fourth-next element's own entries; the
  // third-next's cell heads and its meeting partner's entries (its event, fetched one event
  // earlier, names the partner); the second-next crossing's new neighbours (their heads are
  // the ones fetched one event earlier), or the second-next meeting's partner's cell heads
  // (a collision then fetches its neighbours while the actor predicts). The queue only
  // guesses the order; a wrong guess costs the fetches. One event further ahead measured the
  // same, one event less 4% slower at N = 10^6; the partner's entries one stage earlier (a
  // wait for the event), slower. The last stage for every event's 27 cells was 13% slower at
  // 10^5 (27 head loads, which wait when the heads have not arrived); for the 9 new cells of
  // crossings only, +2.5% at 10^5 and +7.3% at 10^6; a meeting's actor's 27 as well, even
  // (docs/lab/measurements.md#twenty-first-measurement).
  const Grid& grid = *sparse_.grid();
  std::uint32_t next[4];
  const int count = sparse_.queue().Upcoming(next, 4);
  if (count >= 3) {
    grid.FetchAround(CellAhead(next[2]));
    const Prediction& event = sparse_.PredictionOf(next[2]);
    if (event.kind == EventKind::kSphereMeet) FetchElement(event.target);
  }
  if (count >= 4) FetchElement(next[3]);
  if (count >= 2) {
    const Prediction& event = sparse_.PredictionOf(next[1]);
    if (event.kind == EventKind::kCellCrossing) {
      grid.FetchNewFirsts(CellAhead(next[1]), event.CrossingAxis(), event.CrossingDirection());
    } else if (event.kind == EventKind::kSphereMeet) {
      grid.FetchAround(grid.CellOf(event.target));
    }
  }
}

}  // namespace sparsedyn
