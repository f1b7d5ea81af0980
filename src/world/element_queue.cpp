// SPDX-License-Identifier: MIT
// The element queue: a calendar queue whose slots carry the elements' predictions.
#include "events/calendar_queue_impl.hpp"
#include "world/meeting_scan.hpp"

namespace sparsedyn {

template class BasicCalendarQueue<Prediction>;

}  // namespace sparsedyn
