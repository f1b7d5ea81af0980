// SPDX-License-Identifier: MIT
#include "events/calendar_queue.hpp"

#include "events/calendar_queue_impl.hpp"

namespace sparsedyn {

template class BasicCalendarQueue<NoPayload>;

}  // namespace sparsedyn
